// The fast threshold QEM as Simplification_pipeline runs it (docs/fast.md): its own flat-array
// engine, not edge_collapse, converting the mesh and its corner attributes to arrays and back.
#ifndef CGAL_POLICIES_INTERNAL_RUN_FAST_POLICY_H
#define CGAL_POLICIES_INTERNAL_RUN_FAST_POLICY_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Fast_threshold_simplifier.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Pipeline_visitor.h>
#include <cgal_policies/internal/Policy_outcome.h>

#include <cstddef>
#include <functional>

namespace cgal_policies {
namespace internal {

template <class Point>
Policy_outcome run_fast(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                        const Simplification_options& options) {
  Fast_threshold_options fast = options.fast;
  fast.max_normal_angle_deg = options.max_normal_angle_deg;
  const std::size_t start = mesh.number_of_faces();
  std::function<void(std::size_t)> on_progress;
  if (options.progress)
    on_progress = [&options, start, target_faces](std::size_t faces) {
      options.progress(Simplification_pass::simplification,
                       simplification_done(start, target_faces, faces), faces);
    };
  const Fast_threshold_report report =
      Fast_threshold_simplifier(fast)(mesh, target_faces, on_progress);
  Policy_outcome outcome;
  // The simplifier carries whatever corner values the mesh has (it re-adds their maps).
  outcome.attributes_carried = Corner_attributes<Point>(mesh).any_corner_values();
  outcome.stop_reason =
      report.target_reached ? Stop_reason::target_reached : Stop_reason::no_collapse_left;
  return outcome;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_FAST_POLICY_H
