#include "Policy_options_table.h"
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Attribute_quadric_policies.h>
#include <cgal_policies/Bounded_normal_angle_filter.h>

namespace apps {
namespace {

using Options = cgal_policies::Attribute_quadric_options;

const Policy_options_table<Options>& attribute_options() {
  static const Policy_options_table<Options> table =
      Policy_options_table<Options>()
          .number("uv-weight", &Options::uv_weight, 0, Policy_options_table<Options>::unbounded,
                  "texture-space error against geometric error (1: 1% of the texture's extent "
                  "costs as much as 1% of the diagonal)")
          .number("normal-weight", &Options::normal_weight, 0,
                  Policy_options_table<Options>::unbounded,
                  "normal error against geometric error (1: a normal 0.01 off costs as much as 1% "
                  "of the diagonal)")
          .number("color-weight", &Options::color_weight, 0,
                  Policy_options_table<Options>::unbounded,
                  "colour error against geometric error (1: a colour 0.01 off in each channel "
                  "costs as much as 1% of the diagonal)")
          .number("seam-weight", &Options::seam_weight, 0, Policy_options_table<Options>::unbounded,
                  "weight of the planes that keep each seam on its course")
          .border_weight();
  return table;
}

Simplify_outcome run_attributes(Mesh& mesh, const Simplify_settings& settings) {
  cgal_policies::Attribute_quadric_policies<Mesh, Kernel> policies(
      mesh, attribute_options().read(settings.options));
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg),
      Error_bound_keeper::runner,
      [&policies](Attribute_carrier& carrier) { policies.carry_with(carrier); });
}

}  // namespace

std::vector<Policy_entry> attribute_policies() {
  return {{"attributes",
           "cgal_policies Attribute_quadric_policies (quadrics over position, texture "
           "coordinates, normals and colours per wedge; seams kept)",
           attribute_options().options(), run_attributes}};
}

}  // namespace apps
