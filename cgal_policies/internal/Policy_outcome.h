// What one policy's run hands back to Simplification_pipeline.
#ifndef CGAL_POLICIES_INTERNAL_POLICY_OUTCOME_H
#define CGAL_POLICIES_INTERNAL_POLICY_OUTCOME_H

#include <cgal_policies/Stop_reason.h>

namespace cgal_policies {
namespace internal {

struct Policy_outcome {
  Stop_reason stop_reason = Stop_reason::no_collapse_left;
  bool attributes_carried = false;  // the corner attributes followed the collapses
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_POLICY_OUTCOME_H
