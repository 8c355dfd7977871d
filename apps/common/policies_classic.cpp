#include "Policy_options_table.h"
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>

namespace apps {
namespace {

using Options = cgal_policies::Quadric_options;

const Policy_options_table<Options>& classic_options() {
  static const Policy_options_table<Options> table =
      Policy_options_table<Options>().border_weight().area_weights();
  return table;
}

Simplify_outcome run_classic(Mesh& mesh, const Simplify_settings& settings) {
  const cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(
      mesh, classic_options().read(settings.options));
  return run_edge_collapse(
      mesh, settings, policies.get_cost(), policies.get_placement(),
      cgal_policies::Bounded_normal_angle_filter<>(settings.max_normal_angle_deg));
}

}  // namespace

std::vector<Policy_entry> classic_policies() {
  return {{"classic",
           "cgal_policies Classic_quadric_policies (the QEM tutorial: placement chain, border "
           "planes, flip check)",
           classic_options().options(), run_classic}};
}

}  // namespace apps
