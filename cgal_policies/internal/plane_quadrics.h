// Plane quadrics of faces and border edges, and their sums per vertex (docs/quadric_core.md).
#ifndef CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H
#define CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

namespace cgal_policies {
namespace internal {

// The plane of a face of this area normal (twice its area long) through `on_plane`.
inline Quadric triangle_plane_quadric(const Eigen::Vector3d& area_normal,
                                      const Eigen::Vector3d& on_plane, Face_weighting weighting) {
  const double twice_area = area_normal.norm();
  if (twice_area == 0) return Quadric();
  const Eigen::Vector3d n = area_normal / twice_area;
  const double weight = weighting == Face_weighting::area ? 0.5 * twice_area : 1.0;
  return Quadric::from_plane(n, -n.dot(on_plane), weight);
}

template <typename TriangleMesh, typename VertexPointMap>
Quadric face_plane_quadric(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                           const TriangleMesh& tm, const VertexPointMap& vpm,
                           Face_weighting weighting) {
  return triangle_plane_quadric(face_area_normal(f, tm, vpm),
                                to_eigen(get(vpm, target(halfedge(f, tm), tm))), weighting);
}

// Perpendicular to the face of this area normal through its border edge from a to b: moving a
// border vertex off its border line costs border_weight per squared unit (times |e|^2 with area
// weights).
inline Quadric border_side_quadric(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& face_area_normal, double border_weight,
                                   Face_weighting weighting) {
  const Eigen::Vector3d n = unit_or_zero((b - a).cross(face_area_normal));
  if (n.isZero()) return Quadric();
  const double weight =
      weighting == Face_weighting::area ? border_weight * (b - a).squaredNorm() : border_weight;
  return Quadric::from_plane(n, -n.dot(a), weight);
}

// The same through h's edge, perpendicular to h's face.
template <typename TriangleMesh, typename VertexPointMap>
Quadric border_plane_quadric(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                             const TriangleMesh& tm, const VertexPointMap& vpm,
                             double border_weight, Face_weighting weighting) {
  return border_side_quadric(to_eigen(get(vpm, source(h, tm))), to_eigen(get(vpm, target(h, tm))),
                             face_area_normal(face(h, tm), tm, vpm), border_weight, weighting);
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
      if (!CGAL::is_border(opposite(h, tm), tm)) continue;
      const Quadric border_quadric = border_plane_quadric(h, tm, vpm, border_weight, weighting);
      put(border_map, source(h, tm), get(border_map, source(h, tm)) + border_quadric);
      put(border_map, target(h, tm), get(border_map, target(h, tm)) + border_quadric);
    }
  }
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PLANE_QUADRICS_H
