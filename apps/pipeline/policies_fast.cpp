// The flat-array engines (docs/fast.md, docs/flat_lt.md): fast and flat-lt, not edge_collapse.
#include "Pipeline.h"
#include "Policy_options_table.h"
#include "policy_entries.h"

CGAL_POLICIES_APPS_POLICY_RUN(run_fast);
CGAL_POLICIES_APPS_POLICY_RUN(run_flat_lt);

namespace apps {

std::vector<Policy_entry> fast_policies() {
  using Fast = cgal_policies::Fast_threshold_options;
  using Fast_table = Policy_options_table<Fast>;
  const Fast_table fast =
      Fast_table(&cgal_policies::Simplification_options::fast)
          .number("aggressiveness", &Fast::aggressiveness, 0, Fast_table::unbounded,
                  "a in the threshold 1e-9 (k+3)^a D^2 of pass k", true)
          .flag("lossless", &Fast::lossless, true, "only collapses of zero error")
          .border_weight()
          .flag("unit-weights", &Fast::face_weighting, cgal_policies::Face_weighting::unit,
                "give the face planes equal weights, not their areas");
  using Lt = cgal_policies::Flat_lindstrom_turk_options;
  using Lt_table = Policy_options_table<Lt>;
  const Lt_table flat_lt = Lt_table(&cgal_policies::Simplification_options::flat_lt)
                               .number("volume-weight", &Lt::volume_weight, 0, Lt_table::unbounded,
                                       "weight of the volume cost")
                               .number("boundary-weight", &Lt::boundary_weight, 0,
                                       Lt_table::unbounded, "weight of the border cost")
                               .number("shape-weight", &Lt::shape_weight, 0, Lt_table::unbounded,
                                       "weight of the shape cost");
  return {{cgal_policies::Simplification_policy::fast, "fast",
           "cgal_policies Fast_threshold_simplifier (the 2014 report's threshold passes, with the "
           "link condition)",
           fast.options()},
          {cgal_policies::Simplification_policy::flat_lt, "flat-lt",
           "cgal_policies Flat_lindstrom_turk_simplifier (lt's memoryless cost and placement on "
           "flat arrays)",
           flat_lt.options()}};
}

}  // namespace apps
