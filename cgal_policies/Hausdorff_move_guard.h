// Hausdorff_move_guard: a predicate for Laplacian_smoother that refuses any vertex move that would
// break a two-sided Hausdorff bound between a mesh and the original it approximates (policies.md
// §3, bounded smoothing).
//
// The original's triangles go into an AABB tree, and each one is attached, split if need be, to a
// face of the current mesh that covers it within the tolerance. A move is made only when the
// vertex's new star is certified within the tolerance of the original (refined sample grids plus
// their covering radius) and every piece attached to the star is still covered by one of its
// faces. Where the given mesh already breaks the bound, the faces concerned are frozen.
//
// Parameters:
//   tolerance  the bound, a fraction of the original's bounding-box diagonal D
//
// Usage:
//   cgal_policies::Hausdorff_move_guard<Mesh> guard(original, simplified, 0.005);
//   cgal_policies::Laplacian_smoother<Mesh>().smooth(simplified, 10, guard);
#ifndef CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H
#define CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_tracker.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <memory>

namespace cgal_policies {

template <typename TriangleMesh>
class Hausdorff_move_guard {
  using Tracker = internal::Hausdorff_tracker<TriangleMesh>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

 public:
  // `current` must stay alive, and change only through moves this guard allowed.
  Hausdorff_move_guard(const TriangleMesh& original, TriangleMesh& current, double tolerance)
      : m_tracker(
            std::make_shared<Tracker>(original, current, tolerance, Hausdorff_bounded_options())),
        m_current(&current) {
    m_tracker->attach_to_approximation(current, get(CGAL::vertex_point, current));
  }

  template <typename Point>
  bool operator()(vertex_descriptor v, const Point& p) const {
    return m_tracker->try_move(*m_current, get(CGAL::vertex_point, *m_current), v,
                               internal::to_eigen(p));
  }

 private:
  std::shared_ptr<Tracker> m_tracker;
  TriangleMesh* m_current;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H
