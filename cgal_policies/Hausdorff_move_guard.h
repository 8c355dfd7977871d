// Hausdorff_move_guard: an allow_move(v, point) predicate for Laplacian_smoother::smooth() that
// refuses any move breaking a two-sided Hausdorff bound between a mesh and the original it
// approximates ([Liu17] §2.4, bounded; docs/hausdorff.md): the vertex's star must stay certified
// and the original's pieces attached to it covered; faces already breaking the bound are frozen.
// Parameters:
//   original      the reference surface
//   current       the mesh to smooth; it must outlive the guard and change only by allowed moves
//   tolerance     the bound as a fraction of the original's bounding-box diagonal D, > 0
//   original_vpm  original's vertex point map (default: get(CGAL::vertex_point, original))
//   current_vpm   current's vertex point map (default: get(CGAL::vertex_point, current))
// Usage:
//   cgal_policies::Hausdorff_move_guard<Mesh> guard(original, simplified, 0.005);
//   cgal_policies::Laplacian_smoother<Mesh>().smooth(simplified, 10, guard);
#ifndef CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H
#define CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>

#include <memory>

namespace cgal_policies {

template <typename TriangleMesh,
          typename VertexPointMap =
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>
class Hausdorff_move_guard {
  using Shared_state = internal::Hausdorff_bounded_state<TriangleMesh>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

 public:
  Hausdorff_move_guard(const TriangleMesh& original, TriangleMesh& current, double tolerance)
      : Hausdorff_move_guard(original, current, tolerance, get(CGAL::vertex_point, original),
                             get(CGAL::vertex_point, current)) {}

  template <typename OriginalPointMap>
  Hausdorff_move_guard(const TriangleMesh& original, TriangleMesh& current, double tolerance,
                       const OriginalPointMap& original_vpm, const VertexPointMap& current_vpm)
      : m_state(std::make_shared<Shared_state>(original, original_vpm, current, tolerance,
                                               Hausdorff_bounded_options())),
        m_current(&current),
        m_vpm(current_vpm) {
    CGAL_precondition(tolerance > 0);
    m_state->attach_to_approximation(current, m_vpm);
  }

  template <typename Point>
  bool operator()(vertex_descriptor v, const Point& p) const {
    return m_state->try_move(*m_current, m_vpm, v, internal::to_eigen(p));
  }

 private:
  std::shared_ptr<Shared_state> m_state;
  TriangleMesh* m_current;
  VertexPointMap m_vpm;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_MOVE_GUARD_H
