#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_attributes);

namespace apps {

std::vector<Policy_entry> attribute_policies() {
  using Options = cgal_policies::Attribute_quadric_options;
  using Table = Policy_options_table<Options>;
  const Table table =
      Table(&cgal_policies::Simplification_options::attributes)
          .number("uv-weight", &Options::uv_weight, 0, Table::unbounded,
                  "texture-space error against geometric error (1: 1% of the texture's extent "
                  "costs as much as 1% of the diagonal)")
          .number("normal-weight", &Options::normal_weight, 0, Table::unbounded,
                  "normal error against geometric error (1: a normal 0.01 off costs as much as 1% "
                  "of the diagonal)")
          .number("color-weight", &Options::color_weight, 0, Table::unbounded,
                  "colour error against geometric error (1: a colour 0.01 off in each channel "
                  "costs as much as 1% of the diagonal)")
          .number("seam-weight", &Options::seam_weight, 0, Table::unbounded,
                  "weight of the planes that keep each seam on its course")
          .border_weight();
  return {{cgal_policies::Simplification_policy::attributes, "attributes",
           "cgal_policies Attribute_quadric_policies (quadrics over position, texture "
           "coordinates, normals and colours per wedge; seams kept)",
           table.options()}};
}

}  // namespace apps
