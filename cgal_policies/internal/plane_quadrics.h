// Plane quadrics of faces and border edges, and their sums per vertex (docs/quadric_core.md).
#ifndef CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H
#define CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/iterator.h>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh, typename VertexPointMap>
Quadric face_plane_quadric(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                           const TriangleMesh& tm, const VertexPointMap& vpm,
                           Face_weighting weighting) {
  const Eigen::Vector3d area_normal = face_area_normal(f, tm, vpm);
  const double twice_area = area_normal.norm();
  if (twice_area == 0) return Quadric();
  const Eigen::Vector3d n = area_normal / twice_area;
  const Eigen::Vector3d p = to_eigen(get(vpm, target(halfedge(f, tm), tm)));
  const double weight = weighting == Face_weighting::area ? 0.5 * twice_area : 1.0;
  return Quadric::from_plane(n, -n.dot(p), weight);
}

// Perpendicular to h's face through h's edge: moving a border vertex off its border line costs
// border_weight per squared unit (times |e|^2 with area weights).
template <typename TriangleMesh, typename VertexPointMap>
Quadric border_plane_quadric(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                             const TriangleMesh& tm, const VertexPointMap& vpm,
                             double border_weight, Face_weighting weighting) {
  const Eigen::Vector3d a = to_eigen(get(vpm, source(h, tm)));
  const Eigen::Vector3d b = to_eigen(get(vpm, target(h, tm)));
  const Eigen::Vector3d n = unit_or_zero((b - a).cross(face_area_normal(face(h, tm), tm, vpm)));
  if (n.isZero()) return Quadric();
  const double weight =
      weighting == Face_weighting::area ? border_weight * (b - a).squaredNorm() : border_weight;
  return Quadric::from_plane(n, -n.dot(a), weight);
}

// Sums the face planes around each vertex into face_map and its border planes into border_map;
// the same map twice stores the plain sum.
template <typename TriangleMesh, typename VertexPointMap, typename FaceQuadricMap,
          typename BorderQuadricMap>
void accumulate_vertex_quadrics(const TriangleMesh& tm, const VertexPointMap& vpm,
                                Face_weighting weighting, double border_weight,
                                FaceQuadricMap face_map, BorderQuadricMap border_map) {
  for (auto v : vertices(tm)) {
    put(face_map, v, Quadric());
    put(border_map, v, Quadric());
  }
  for (auto f : faces(tm)) {
    const Quadric face_quadric = face_plane_quadric(f, tm, vpm, weighting);
    for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      put(face_map, target(h, tm), get(face_map, target(h, tm)) + face_quadric);
      if (!is_border(opposite(h, tm), tm)) continue;
      const Quadric border_quadric = border_plane_quadric(h, tm, vpm, border_weight, weighting);
      put(border_map, source(h, tm), get(border_map, source(h, tm)) + border_quadric);
      put(border_map, target(h, tm), get(border_map, target(h, tm)) + border_quadric);
    }
  }
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H
