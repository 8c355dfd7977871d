#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_fusion);

namespace apps {

std::vector<Policy_entry> fusion_policies() {
  using Options = cgal_policies::Feature_fusion_options;
  using Table = Policy_options_table<Options>;
  const Table table = Table(&cgal_policies::Simplification_options::fusion)
                          .number("mu", &Options::mu, 0, Table::unbounded,
                                  "weight of the normal variation in the quadric cost, per radian")
                          .number("visual-weight", &Options::visual_weight, 0, Table::unbounded,
                                  "weight w_v of the visual term (twist x side ratio x L0^2)")
                          .border_weight();
  return {{cgal_policies::Simplification_policy::fusion, "fusion",
           "cgal_policies Feature_fusion_policies (Wang et al. 2013: normal-weighted QEM plus "
           "side-ratio-weighted normal twist)",
           table.options()}};
}

}  // namespace apps
