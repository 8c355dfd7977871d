#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Feature_fusion_policies.h>

namespace apps {
namespace {

using Fusion_policies = cgal_policies::Feature_fusion_policies<Mesh, Kernel>;

Simplify_outcome run_fusion(Mesh& mesh, const Simplify_settings& settings) {
  const Fusion_policies policies(mesh, settings.options.at("mu"),
                                 settings.options.at("visual-weight"),
                                 settings.options.at("border-weight"));
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> fusion_policies() {
  return {{"fusion",
           "cgal_policies Feature_fusion_policies (Wang et al. 2013: normal-weighted QEM plus "
           "side-ratio-weighted normal twist)",
           {{"mu", Fusion_policies::default_mu,
             "weight of the normal variation in the quadric cost, per radian"},
            {"visual-weight", Fusion_policies::default_visual_weight,
             "weight w_v of the visual term (twist x side ratio x L0^2)"},
            {"border-weight", 1000, "weight of the border planes"}},
           run_fusion}};
}

}  // namespace apps
