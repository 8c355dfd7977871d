// The fast threshold QEM (docs/fast.md): its own flat-array engine, not edge_collapse.
#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_fast);

namespace apps {

std::vector<Policy_entry> fast_policies() {
  using Options = cgal_policies::Fast_threshold_options;
  using Table = Policy_options_table<Options>;
  const Table table =
      Table(&cgal_policies::Simplification_options::fast)
          .number("aggressiveness", &Options::aggressiveness, 0, Table::unbounded,
                  "a in the threshold 1e-9 (k+3)^a D^2 of pass k", true)
          .flag("lossless", &Options::lossless, true, "only collapses of zero error")
          .border_weight();
  return {{cgal_policies::Simplification_policy::fast, "fast",
           "cgal_policies Fast_threshold_simplifier (the 2014 report's threshold passes, with the "
           "link condition)",
           table.options()}};
}

}  // namespace apps
