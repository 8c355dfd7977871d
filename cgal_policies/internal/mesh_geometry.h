// Small geometric helpers shared by the policies, in double precision whatever the kernel.
#ifndef CGAL_POLICIES_INTERNAL_MESH_GEOMETRY_H
#define CGAL_POLICIES_INTERNAL_MESH_GEOMETRY_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cgal_policies {
namespace internal {

template <typename Point>
Eigen::Vector3d to_eigen(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <typename Point>
Point to_point(const Eigen::Vector3d& p) {
  return Point(p.x(), p.y(), p.z());
}

// Its length is twice the triangle's area.
inline Eigen::Vector3d triangle_area_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                            const Eigen::Vector3d& c) {
  return (b - a).cross(c - a);
}

inline Eigen::Vector3d unit_or_zero(const Eigen::Vector3d& v) {
  const double length = v.norm();
  return length > 0 ? Eigen::Vector3d(v / length) : Eigen::Vector3d::Zero();
}

template <typename TriangleMesh, typename VertexPointMap>
Eigen::Vector3d face_area_normal(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                                 const TriangleMesh& tm, const VertexPointMap& vpm) {
  const auto h = halfedge(f, tm);
  return triangle_area_normal(to_eigen(get(vpm, source(h, tm))), to_eigen(get(vpm, target(h, tm))),
                              to_eigen(get(vpm, target(next(h, tm), tm))));
}

enum class Normal_weighting { unit, area };

template <typename TriangleMesh, typename VertexPointMap>
Eigen::Vector3d vertex_normal(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                              const TriangleMesh& tm, const VertexPointMap& vpm,
                              Normal_weighting weighting) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (auto f : CGAL::faces_around_target(halfedge(v, tm), tm)) {
    if (f == boost::graph_traits<TriangleMesh>::null_face()) continue;
    const Eigen::Vector3d n = face_area_normal(f, tm, vpm);
    sum += weighting == Normal_weighting::area ? n : unit_or_zero(n);
  }
  return unit_or_zero(sum);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_MESH_GEOMETRY_H
