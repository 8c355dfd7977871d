// The fast threshold QEM (policies.md §5): it runs its own flat-array engine, not edge_collapse,
// and is timed and reported like the others (conversions to and from the arrays included).
#include "App_error.h"
#include "policy_entries.h"

#include <cgal_policies/Fast_threshold_simplifier.h>

#include <chrono>

namespace apps {
namespace {

Simplify_outcome run_fast(Mesh& mesh, const Simplify_settings& settings) {
  const double aggressiveness = settings.options.at("aggressiveness");
  if (!(aggressiveness > 0)) throw App_error(exit_usage, "--aggressiveness must be positive");
  // The bound certifies edge collapses one by one; the engine's passes have no such hook.
  if (settings.max_error > 0)
    throw App_error(exit_usage,
                    "--max-error needs an edge-collapse policy; fast runs its own engine (try "
                    "classic)");
  const cgal_policies::Fast_threshold_simplifier simplifier(
      aggressiveness, settings.options.at("lossless") != 0, settings.max_normal_angle_deg,
      settings.options.at("border-weight"));
  const auto start = std::chrono::steady_clock::now();
  const cgal_policies::Fast_threshold_report report =
      simplifier(mesh, settings.target_faces, settings.on_progress);
  Simplify_outcome outcome;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.stop_reason = report.target_reached ? "target_reached" : "no_collapse_left";
  return outcome;
}

}  // namespace

std::vector<Policy_entry> fast_policies() {
  return {{"fast",
           "cgal_policies Fast_threshold_simplifier (the 2014 report's threshold passes, with the "
           "link condition)",
           {{"aggressiveness", 7, "a in the threshold 1e-9 (k+3)^a D^2 of pass k"},
            {"lossless", 0, "only collapses of zero error", true},
            {"border-weight", 1000, "weight of the border planes"}},
           run_fast}};
}

}  // namespace apps
