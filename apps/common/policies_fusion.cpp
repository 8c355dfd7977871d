#include "Policy_options_table.h"
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Feature_fusion_policies.h>

namespace apps {
namespace {

using Options = cgal_policies::Feature_fusion_options;

const Policy_options_table<Options>& fusion_options() {
  using Table = Policy_options_table<Options>;
  static const Table table =
      Table()
          .number("mu", &Options::mu, 0, Table::unbounded,
                  "weight of the normal variation in the quadric cost, per radian")
          .number("visual-weight", &Options::visual_weight, 0, Table::unbounded,
                  "weight w_v of the visual term (twist x side ratio x L0^2)")
          .border_weight();
  return table;
}

Simplify_outcome run_fusion(Mesh& mesh, const Simplify_settings& settings) {
  const cgal_policies::Feature_fusion_policies<Mesh, Kernel> policies(
      mesh, fusion_options().read(settings.options));
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> fusion_policies() {
  return {{"fusion",
           "cgal_policies Feature_fusion_policies (Wang et al. 2013: normal-weighted QEM plus "
           "side-ratio-weighted normal twist)",
           fusion_options().options(), run_fusion}};
}

}  // namespace apps
