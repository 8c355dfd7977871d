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
#include <cgal_policies/internal/Flat_part.h>
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

// How a flat-array run ended.
inline Policy_outcome flat_array_outcome(bool target_reached, bool interrupted,
                                         bool attributes_carried) {
  Policy_outcome outcome;
  outcome.attributes_carried = attributes_carried;
  outcome.stop_reason = interrupted      ? Stop_reason::interrupted
                        : target_reached ? Stop_reason::target_reached
                                         : Stop_reason::no_collapse_left;
  return outcome;
}

// The engines carry whatever corner values the mesh has (they re-add their maps).
template <class Point>
Policy_outcome flat_array_outcome(const CGAL::Surface_mesh<Point>& mesh, bool target_reached,
                                  bool interrupted) {
  return flat_array_outcome(target_reached, interrupted,
                            Corner_attributes<Point>(mesh).any_corner_values());
}

inline Fast_threshold_options fast_options_of(const Simplification_options& options) {
  Fast_threshold_options fast = options.fast;
  fast.max_normal_angle_deg = options.max_normal_angle_deg;
  return fast;
}

inline Flat_lindstrom_turk_options flat_lt_options_of(const Simplification_options& options) {
  Flat_lindstrom_turk_options flat_lt = options.flat_lt;
  flat_lt.max_normal_angle_deg = options.max_normal_angle_deg;
  return flat_lt;
}

template <class Point>
Policy_outcome run_fast(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                        const Simplification_options& options, const CGAL::Surface_mesh<Point>*) {
  const Fast_threshold_report report = Fast_threshold_simplifier(fast_options_of(options))(
      mesh, target_faces, flat_array_progress(options, mesh.number_of_faces(), target_faces));
  return flat_array_outcome(mesh, report.target_reached, false);
}

template <class Point>
Policy_outcome run_flat_lt(CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
                           const Simplification_options& options,
                           const CGAL::Surface_mesh<Point>*) {
  const Flat_lindstrom_turk_report report =
      Flat_lindstrom_turk_simplifier(flat_lt_options_of(options))(
          mesh, target_faces, flat_array_progress(options, mesh.number_of_faces(), target_faces),
          options.interrupted);
  return flat_array_outcome(mesh, report.target_reached, report.interrupted);
}

// Whether a partitioned run keeps its parts as arrays (run_flat_partitioned): fast alone, or
// flat_lt after the fast prepass or without one, on a mesh without corner values.
template <class Point>
bool runs_on_flat_parts(const CGAL::Surface_mesh<Point>& mesh,
                        const Simplification_options& options) {
  const bool fast_alone =
      options.policy == Simplification_policy::fast && options.prepass_factor == 0;
  return (fast_alone || options.policy == Simplification_policy::flat_lt) &&
         !Corner_attributes<Point>(mesh).any();
}

// What run_policy does to a mesh that runs_on_flat_parts, on a part kept as arrays.
inline Policy_outcome run_on_flat_part(Flat_part& part, std::size_t target,
                                       const Simplification_options& options) {
  const std::size_t start = part.triangles.size();
  const std::function<void(std::size_t)> progress = flat_array_progress(options, start, target);
  const std::size_t coarse = options.prepass_faces(target);
  const bool prepass = coarse != 0 && start > coarse;
  if (options.policy == Simplification_policy::fast || prepass) {
    const Fast_threshold_options fast = fast_options_of(options);
    const Face_weighting weighting = plane_weighting(fast);
    Fast_threshold_engine<No_corner_values> engine(
        fast_threshold_vertices(part, weighting, fast.border_weight), part.triangles,
        part.diagonal(), weighting);
    const auto outcome = engine.simplify(prepass ? coarse : target, fast, progress);
    take_engine_result(engine.mesh(), part);
    if (!prepass) return flat_array_outcome(outcome.target_reached, false, false);
    if (options.interrupted && options.interrupted()) return flat_array_outcome(false, true, false);
  }
  Lindstrom_turk_engine<No_corner_values> engine(lindstrom_turk_vertices(part), part.triangles);
  const auto outcome =
      engine.simplify(target, flat_lt_options_of(options), progress, options.interrupted);
  take_engine_result(engine.mesh(), part);
  return flat_array_outcome(outcome.target_reached, outcome.interrupted, false);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_FLAT_ARRAY_POLICIES_H
