#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_classic);

namespace apps {

std::vector<Policy_entry> classic_policies() {
  using Table = Policy_options_table<cgal_policies::Quadric_options>;
  const Table table =
      Table(&cgal_policies::Simplification_options::classic).border_weight().area_weights();
  return {{cgal_policies::Simplification_policy::classic, "classic",
           "cgal_policies Classic_quadric_policies (the QEM tutorial: placement chain, border "
           "planes, flip check)",
           table.options()}};
}

}  // namespace apps
