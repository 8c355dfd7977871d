// The Hausdorff-bounded policy as Simplification_pipeline runs it (docs/hausdorff.md): in global
// mode it keeps max_error itself, with the tighter of the two bounds; in local mode its tolerance
// bounds each step against the patch before it, not the output against the input, so the runner's
// filter keeps max_error, as for the other policies.
#ifndef CGAL_POLICIES_INTERNAL_RUN_HAUSDORFF_POLICY_H
#define CGAL_POLICIES_INTERNAL_RUN_HAUSDORFF_POLICY_H

#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Policy_outcome.h>
#include <cgal_policies/internal/run_edge_collapse.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cstddef>

namespace cgal_policies {
namespace internal {

// `reference`: the input, when it is not the mesh as it is now (run_edge_collapse); the tolerance
// is a fraction of its diagonal in both modes.
template <class Point>
Policy_outcome run_hausdorff(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                             const Simplification_options& options,
                             const CGAL::Surface_mesh<Point>* reference) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  Hausdorff_bounded_options hausdorff = options.hausdorff;
  hausdorff.max_normal_angle_deg = options.max_normal_angle_deg;
  const bool local = hausdorff.reference == Hausdorff_reference::local;
  if (options.max_error > 0 && !local)
    hausdorff.beta = (std::min)(hausdorff.beta, options.max_error);
  const CGAL::Surface_mesh<Point>& input = reference ? *reference : mesh;
  Hausdorff_bounded_policies<CGAL::Surface_mesh<Point>, Kernel> policies(mesh, input,
                                                                         input.points(), hausdorff);
  return run_edge_collapse(
      mesh, target_faces, options, policies.get_cost(), policies.get_placement(),
      policies.get_filter(), local ? Error_bound_keeper::runner : Error_bound_keeper::policy,
      [&policies](Corner_attribute_carrier<Point>& carrier) { policies.keep_seams_with(carrier); },
      reference);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_HAUSDORFF_POLICY_H
