// CGAL's own policies, run as CGAL ships them (docs/evaluation.md): they take no options.
#include "Pipeline.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_gh);
CGAL_POLICIES_APPS_POLICY_RUN(run_gh_probabilistic);
CGAL_POLICIES_APPS_POLICY_RUN(run_lt);

namespace apps {

std::vector<Policy_entry> cgal_baseline_policies() {
  using cgal_policies::Simplification_policy;
  return {
      {Simplification_policy::gh, "gh", "CGAL GarlandHeckbert_plane_policies (classic QEM)", {}},
      {Simplification_policy::gh_probabilistic,
       "gh-prob",
       "CGAL GarlandHeckbert_probabilistic_plane_policies",
       {}},
      {Simplification_policy::lt, "lt", "CGAL LindstromTurk_cost and LindstromTurk_placement", {}},
  };
}

}  // namespace apps
