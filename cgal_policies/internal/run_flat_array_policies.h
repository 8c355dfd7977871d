// The flat-array engines as Simplification_pipeline runs them (docs/fast.md, docs/flat_lt.md):
// fast and flat_lt, not edge_collapse, converting the mesh and its corner attributes to arrays
// and back. They keep no max_error bound (the pipeline's precondition), so they have no use for
// the reference input the other runs take.
#ifndef CGAL_POLICIES_INTERNAL_RUN_FLAT_ARRAY_POLICIES_H
#define CGAL_POLICIES_INTERNAL_RUN_FLAT_ARRAY_POLICIES_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Fast_threshold_simplifier.h>
#include <cgal_policies/Flat_lindstrom_turk_simplifier.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Pipeline_visitor.h>
#include <cgal_policies/internal/Policy_outcome.h>

#include <cstddef>
#include <functional>

namespace cgal_policies {
namespace internal {

// The engines' face counts as the pipeline's progress; empty without a progress callback.
inline std::function<void(std::size_t)> flat_array_progress(const Simplification_options& options,
                                                            std::size_t start,
                                                            std::size_t target_faces) {
  if (!options.progress) return {};
  return [&options, start, target_faces](std::size_t faces) {
    options.progress(Simplification_pass::simplification,
                     simplification_done(start, target_faces, faces), faces);
  };
}

// The engines carry whatever corner values the mesh has (they re-add their maps).
template <class Point>
Policy_outcome flat_array_outcome(const CGAL::Surface_mesh<Point>& mesh, bool target_reached,
                                  bool interrupted) {
  Policy_outcome outcome;
  outcome.attributes_carried = Corner_attributes<Point>(mesh).any_corner_values();
  outcome.stop_reason = interrupted      ? Stop_reason::interrupted
                        : target_reached ? Stop_reason::target_reached
                                         : Stop_reason::no_collapse_left;
  return outcome;
}

template <class Point>
Policy_outcome run_fast(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                        const Simplification_options& options, const CGAL::Surface_mesh<Point>*) {
  Fast_threshold_options fast = options.fast;
  fast.max_normal_angle_deg = options.max_normal_angle_deg;
  const Fast_threshold_report report = Fast_threshold_simplifier(fast)(
      mesh, target_faces, flat_array_progress(options, mesh.number_of_faces(), target_faces));
  return flat_array_outcome(mesh, report.target_reached, false);
}

template <class Point>
Policy_outcome run_flat_lt(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                           const Simplification_options& options,
                           const CGAL::Surface_mesh<Point>*) {
  Flat_lindstrom_turk_options flat_lt = options.flat_lt;
  flat_lt.max_normal_angle_deg = options.max_normal_angle_deg;
  const Flat_lindstrom_turk_report report = Flat_lindstrom_turk_simplifier(flat_lt)(
      mesh, target_faces, flat_array_progress(options, mesh.number_of_faces(), target_faces),
      options.interrupted);
  return flat_array_outcome(mesh, report.target_reached, report.interrupted);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_FLAT_ARRAY_POLICIES_H
