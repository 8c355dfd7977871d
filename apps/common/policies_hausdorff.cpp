// The Hausdorff-bounded policy (docs/hausdorff.md): cgal_policies::Hausdorff_bounded_policies, its
// cost, placement and filter.
#include "Policy_options_table.h"
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Hausdorff_bounded_policies.h>

#include <algorithm>

namespace apps {
namespace {

using Options = cgal_policies::Hausdorff_bounded_options;

const Policy_options_table<Options>& hausdorff_options() {
  using Table = Policy_options_table<Options>;
  static const Table table =
      Table()
          .number("tolerance", &Options::beta, 0, Table::unbounded,
                  "two-sided Hausdorff bound alpha*beta, a fraction of D", true)
          .whole_number("steps", &Options::steps, 1, 1000,
                        "K: candidates at K+1 points along the edge, plus the quadric optimum")
          .flag("local", &Options::reference, cgal_policies::Hausdorff_reference::local,
                "the paper's literal rule: measure against the current patch")
          .flag("scan-order", &Options::order, cgal_policies::Collapse_order::storage,
                "the paper's single pass in storage order, not by cost")
          .flag("lock-border", &Options::border, cgal_policies::Border_rule::lock,
                "border vertices never move (default: slide along the border)");
  return table;
}

Simplify_outcome run_hausdorff(Mesh& mesh, const Simplify_settings& settings) {
  Options options = hausdorff_options().read(settings.options);
  options.max_normal_angle_deg = settings.max_normal_angle_deg;
  // In global mode the policy keeps --max-error itself, with the tighter of the two bounds. In
  // local mode its tolerance bounds each step against the patch before it, not the output against
  // the input, so the runner's filter keeps --max-error, as for the other policies.
  const bool local = options.reference == cgal_policies::Hausdorff_reference::local;
  if (settings.max_error > 0 && !local) options.beta = std::min(options.beta, settings.max_error);
  cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> hausdorff(mesh, options);
  return run_edge_collapse(
      mesh, settings, hausdorff.get_cost(), hausdorff.get_placement(), hausdorff.get_filter(),
      local ? Error_bound_keeper::runner : Error_bound_keeper::policy,
      [&hausdorff](Attribute_carrier& carrier) { hausdorff.keep_seams_with(carrier); });
}

}  // namespace

std::vector<Policy_entry> hausdorff_policies() {
  Policy_entry hausdorff{
      "hausdorff",
      "cgal_policies Hausdorff_bounded_policies (Liu et al. 2017: K+1 candidates per edge, "
      "refused above the tolerance; global mode bounds the two-sided distance to the input)",
      hausdorff_options().options(), run_hausdorff};
  hausdorff.own_bound = [](const Simplify_settings& settings) {
    const Options options = hausdorff_options().read(settings.options);
    return options.reference == cgal_policies::Hausdorff_reference::local ? 0.0 : options.beta;
  };
  return {hausdorff};
}

}  // namespace apps
