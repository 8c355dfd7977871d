// The fast threshold QEM (docs/fast.md): it runs its own flat-array engine, not edge_collapse, and
// is timed and reported like the others (conversions to and from the arrays included, with the
// corner attributes when the mesh has them).
#include "Policy_options_table.h"
#include "Stopwatch.h"
#include "policy_entries.h"

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Fast_threshold_simplifier.h>

namespace apps {
namespace {

using Options = cgal_policies::Fast_threshold_options;

const Policy_options_table<Options>& fast_options() {
  using Table = Policy_options_table<Options>;
  static const Table table =
      Table()
          .number("aggressiveness", &Options::aggressiveness, 0, Table::unbounded,
                  "a in the threshold 1e-9 (k+3)^a D^2 of pass k", true)
          .flag("lossless", &Options::lossless, true, "only collapses of zero error")
          .border_weight();
  return table;
}

Simplify_outcome run_fast(Mesh& mesh, const Simplify_settings& settings) {
  Options options = fast_options().read(settings.options);
  options.max_normal_angle_deg = settings.max_normal_angle_deg;
  const Stopwatch watch;
  const cgal_policies::Fast_threshold_report report = cgal_policies::Fast_threshold_simplifier(
      options)(mesh, settings.target_faces, settings.on_progress);
  Simplify_outcome outcome;
  outcome.seconds = watch.seconds();
  // The simplifier carries whatever corner values the mesh has (it re-adds their maps).
  outcome.attributes_carried = cgal_policies::Corner_attributes<Point>(mesh).any_corner_values();
  outcome.stop_reason =
      report.target_reached ? Stop_reason::target_reached : Stop_reason::no_collapse_left;
  return outcome;
}

}  // namespace

std::vector<Policy_entry> fast_policies() {
  Policy_entry fast{"fast",
                    "cgal_policies Fast_threshold_simplifier (the 2014 report's threshold passes, "
                    "with the link condition)",
                    fast_options().options(), run_fast};
  // The bound certifies edge collapses one by one; the engine's passes have no such hook.
  fast.takes_error_bound = false;
  fast.takes_time_limit = false;
  return {fast};
}

}  // namespace apps
