#include "Policy_options_table.h"
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>

namespace apps {
namespace {

using Options = cgal_policies::Curvature_weighted_options;

const Policy_options_table<Options>& curvature_options() {
  using Table = Policy_options_table<Options>;
  static const Table table =
      Table()
          .number("eps", &Options::eps, 0, Table::unbounded,
                  "floor of the curvature factor (dimensionless)")
          .flag("literal", &Options::literal, true,
                "eq. 12 as printed: eps = 0, border planes weighted too (overrides --eps)")
          .border_weight()
          .area_weights();
  return table;
}

Simplify_outcome run_curvature(Mesh& mesh, const Simplify_settings& settings) {
  const cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(
      mesh, curvature_options().read(settings.options));
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> curvature_policies() {
  return {{"curvature",
           "cgal_policies Curvature_weighted_quadric_policies (Zhang et al. 2009: QEM weighted by "
           "the approximate curvature, flat regions first)",
           curvature_options().options(), run_curvature}};
}

}  // namespace apps
