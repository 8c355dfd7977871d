#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_curvature);

namespace apps {

std::vector<Policy_entry> curvature_policies() {
  using Options = cgal_policies::Curvature_weighted_options;
  using Table = Policy_options_table<Options>;
  const Table table =
      Table(&cgal_policies::Simplification_options::curvature)
          .number("eps", &Options::eps, 0, Table::unbounded,
                  "floor of the curvature factor (dimensionless)")
          .flag("literal", &Options::literal, true,
                "eq. 12 as printed: eps = 0, border planes weighted too (overrides --eps)")
          .border_weight()
          .area_weights();
  return {{cgal_policies::Simplification_policy::curvature, "curvature",
           "cgal_policies Curvature_weighted_quadric_policies (Zhang et al. 2009: QEM weighted by "
           "the approximate curvature, flat regions first)",
           table.options()}};
}

}  // namespace apps
