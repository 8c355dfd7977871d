// CGAL's own policies as Simplification_pipeline runs them: as CGAL ships them (no extra filter),
// the baselines of docs/evaluation.md; gh and gh-prob only step around one Debug precondition
// (Zero_quadric_tolerant_policies.h). Every run_* of the pipeline takes `reference`, the input a
// max_error bound is certified against when it is not the mesh as it is now (run_edge_collapse).
#ifndef CGAL_POLICIES_INTERNAL_RUN_CGAL_POLICIES_H
#define CGAL_POLICIES_INTERNAL_RUN_CGAL_POLICIES_H

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Policy_outcome.h>
#include <cgal_policies/internal/Zero_quadric_tolerant_policies.h>
#include <cgal_policies/internal/run_edge_collapse.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>

#include <cstddef>

namespace cgal_policies {
namespace internal {

template <class Policies, class Point>
Policy_outcome run_garland_heckbert(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                                    const Simplification_options& options,
                                    const CGAL::Surface_mesh<Point>* reference) {
  const Zero_quadric_tolerant_policies<Policies> policies(mesh);
  return run_edge_collapse(mesh, target_faces, options, policies.get_cost(),
                           policies.get_placement(),
                           CGAL::Surface_mesh_simplification::internal::Dummy_filter(),
                           Error_bound_keeper::runner, {}, reference);
}

template <class Point>
Policy_outcome run_gh(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                      const Simplification_options& options,
                      const CGAL::Surface_mesh<Point>* reference) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  return run_garland_heckbert<CGAL::Surface_mesh_simplification::GarlandHeckbert_plane_policies<
      CGAL::Surface_mesh<Point>, Kernel>>(mesh, target_faces, options, reference);
}

template <class Point>
Policy_outcome run_gh_probabilistic(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                                    const Simplification_options& options,
                                    const CGAL::Surface_mesh<Point>* reference) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  return run_garland_heckbert<
      CGAL::Surface_mesh_simplification::GarlandHeckbert_probabilistic_plane_policies<
          CGAL::Surface_mesh<Point>, Kernel>>(mesh, target_faces, options, reference);
}

template <class Point>
Policy_outcome run_lt(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                      const Simplification_options& options,
                      const CGAL::Surface_mesh<Point>* reference) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  using Mesh = CGAL::Surface_mesh<Point>;
  return run_edge_collapse(mesh, target_faces, options, SMS::LindstromTurk_cost<Mesh>(),
                           SMS::LindstromTurk_placement<Mesh>(), SMS::internal::Dummy_filter(),
                           Error_bound_keeper::runner, {}, reference);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_CGAL_POLICIES_H
