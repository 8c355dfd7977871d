#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>

namespace apps {
namespace {

Simplify_outcome run_curvature(Mesh& mesh, const Simplify_settings& settings) {
  const cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(
      mesh, settings.options.at("eps"), settings.options.at("border-weight"),
      settings.options.at("area-weights") != 0 ? cgal_policies::Face_weighting::area
                                               : cgal_policies::Face_weighting::unit,
      settings.options.at("literal") != 0);
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> curvature_policies() {
  return {{"curvature",
           "cgal_policies Curvature_weighted_quadric_policies (Zhang et al. 2009: QEM weighted by "
           "the approximate curvature, flat regions first)",
           {{"eps", 1e-3, "floor of the curvature factor (dimensionless)"},
            {"literal", 0,
             "eq. 12 as printed: eps = 0, border planes weighted too (overrides --eps)", true},
            {"border-weight", 1000, "weight of the border planes"},
            {"area-weights", 0, "weight face planes by area", true}},
           run_curvature}};
}

}  // namespace apps
