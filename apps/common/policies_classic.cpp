#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>

namespace apps {
namespace {

Simplify_outcome run_classic(Mesh& mesh, const Simplify_settings& settings) {
  const cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(
      mesh, settings.options.at("border-weight"),
      settings.options.at("area-weights") != 0 ? cgal_policies::Face_weighting::area
                                               : cgal_policies::Face_weighting::unit);
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> classic_policies() {
  return {{"classic",
           "cgal_policies Classic_quadric_policies (the QEM tutorial: placement chain, border "
           "planes, flip check)",
           {{"border-weight", 1000, "weight of the border planes"},
            {"area-weights", 0, "weight face planes by area", true}},
           run_classic}};
}

}  // namespace apps
