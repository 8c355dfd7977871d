// The Hausdorff-bounded policy (docs/hausdorff.md): cgal_policies::Hausdorff_bounded_policies, its
// cost, placement and filter.
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Hausdorff_bounded_policies.h>

#include <algorithm>

namespace apps {
namespace {

Simplify_outcome run_hausdorff(Mesh& mesh, const Simplify_settings& settings) {
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = settings.options.at("tolerance");
  options.steps = int(settings.options.at("steps"));
  options.reference = settings.options.at("local") != 0
                          ? cgal_policies::Hausdorff_reference::local
                          : cgal_policies::Hausdorff_reference::global;
  options.order = settings.options.at("scan-order") != 0 ? cgal_policies::Collapse_order::storage
                                                         : cgal_policies::Collapse_order::by_cost;
  options.border = settings.options.at("lock-border") != 0 ? cgal_policies::Border_rule::lock
                                                           : cgal_policies::Border_rule::slide;
  options.max_normal_angle_deg = settings.max_normal_angle_deg;
  // The policy enforces --max-error itself, with the tighter of the two bounds.
  Simplify_settings own = settings;
  if (own.max_error > 0) options.beta = std::min(options.beta, own.max_error);
  own.max_error = 0;
  const cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> hausdorff(mesh, options);
  return run_edge_collapse(mesh, own, hausdorff.get_cost(), hausdorff.get_placement(),
                           hausdorff.get_filter());
}

}  // namespace

std::vector<Policy_entry> hausdorff_policies() {
  return {
      {"hausdorff",
       "cgal_policies Hausdorff_bounded_policies (Liu et al. 2017: K+1 candidates per edge, "
       "refused above the tolerance; global mode bounds the two-sided distance to the input)",
       {{"tolerance", 0.005, "two-sided Hausdorff bound alpha*beta, a fraction of D"},
        {"steps", 10, "K: candidates at K+1 points along the edge, plus the quadric optimum"},
        {"local", 0, "the paper's literal rule: measure against the current patch", true},
        {"scan-order", 0, "the paper's single pass in storage order, not by cost", true},
        {"lock-border", 0, "border vertices never move (default: slide along the border)", true}},
       run_hausdorff}};
}

}  // namespace apps
