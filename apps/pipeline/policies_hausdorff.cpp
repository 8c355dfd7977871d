// The Hausdorff-bounded policy (docs/hausdorff.md): cgal_policies::Hausdorff_bounded_policies.
#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_hausdorff);

namespace apps {

std::vector<Policy_entry> hausdorff_policies() {
  using Options = cgal_policies::Hausdorff_bounded_options;
  using Table = Policy_options_table<Options>;
  const Table table =
      Table(&cgal_policies::Simplification_options::hausdorff)
          .number("tolerance", &Options::beta, 0, Table::unbounded,
                  "two-sided Hausdorff bound alpha*beta, a fraction of D", true)
          .whole_number("steps", &Options::steps, 1, 1000,
                        "K: candidates at K+1 points along the edge, plus the quadric optimum")
          .flag("local", &Options::reference, cgal_policies::Hausdorff_reference::local,
                "the paper's literal rule: measure against the current patch")
          .flag("scan-order", &Options::order, cgal_policies::Collapse_order::storage,
                "the paper's single pass in storage order, not by cost")
          .flag("lock-border", &Options::border, cgal_policies::Border_rule::lock,
                "border vertices never move (default: slide along the border)");
  return {{cgal_policies::Simplification_policy::hausdorff, "hausdorff",
           "cgal_policies Hausdorff_bounded_policies (Liu et al. 2017: K+1 candidates per edge, "
           "refused above the tolerance; global mode bounds the two-sided distance to the input)",
           table.options()}};
}

}  // namespace apps
