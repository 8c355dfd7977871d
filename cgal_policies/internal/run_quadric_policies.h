// This library's quadric policies as Simplification_pipeline runs them (docs/quadric_core.md):
// classic, curvature, fusion and attributes, each with Bounded_normal_angle_filter at the
// options' max_normal_angle_deg.
#ifndef CGAL_POLICIES_INTERNAL_RUN_QUADRIC_POLICIES_H
#define CGAL_POLICIES_INTERNAL_RUN_QUADRIC_POLICIES_H

#include <cgal_policies/Attribute_quadric_policies.h>
#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>
#include <cgal_policies/Feature_fusion_policies.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Policy_outcome.h>
#include <cgal_policies/internal/run_edge_collapse.h>

#include <CGAL/Kernel_traits.h>

#include <cstddef>

namespace cgal_policies {
namespace internal {

// Policies built on the mesh with their options, their cost and placement going into
// edge_collapse as they are.
template <template <class, class> class Policies, class Point, class Options>
Policy_outcome run_quadric_policies(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                                    const Simplification_options& options,
                                    const CGAL::Surface_mesh<Point>* reference,
                                    const Options& policy_options) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const Policies<CGAL::Surface_mesh<Point>, Kernel> policies(mesh, policy_options);
  return run_edge_collapse(mesh, target_faces, options, policies.get_cost(),
                           policies.get_placement(),
                           Bounded_normal_angle_filter<>(options.max_normal_angle_deg),
                           Error_bound_keeper::runner, {}, reference);
}

template <class Point>
Policy_outcome run_classic(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                           const Simplification_options& options,
                           const CGAL::Surface_mesh<Point>* reference) {
  return run_quadric_policies<Classic_quadric_policies>(mesh, target_faces, options, reference,
                                                        options.classic);
}

template <class Point>
Policy_outcome run_curvature(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                             const Simplification_options& options,
                             const CGAL::Surface_mesh<Point>* reference) {
  return run_quadric_policies<Curvature_weighted_quadric_policies>(mesh, target_faces, options,
                                                                   reference, options.curvature);
}

template <class Point>
Policy_outcome run_fusion(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                          const Simplification_options& options,
                          const CGAL::Surface_mesh<Point>* reference) {
  return run_quadric_policies<Feature_fusion_policies>(mesh, target_faces, options, reference,
                                                       options.fusion);
}

// The attribute quadrics solve the kept vertex's values: the carrier hears from them.
template <class Point>
Policy_outcome run_attributes(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                              const Simplification_options& options,
                              const CGAL::Surface_mesh<Point>* reference) {
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  Attribute_quadric_policies<CGAL::Surface_mesh<Point>, Kernel> policies(mesh, options.attributes);
  return run_edge_collapse(
      mesh, target_faces, options, policies.get_cost(), policies.get_placement(),
      Bounded_normal_angle_filter<>(options.max_normal_angle_deg), Error_bound_keeper::runner,
      [&policies](Corner_attribute_carrier<Point>& carrier) { policies.carry_with(carrier); },
      reference);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_QUADRIC_POLICIES_H
