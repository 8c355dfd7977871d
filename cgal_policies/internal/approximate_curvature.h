// The approximate curvature K of [Zhang09] eq. 9-10 (docs/curvature.md): the mean cosine between a
// vertex normal and its neighbours' normals.
#ifndef CGAL_POLICIES_INTERNAL_APPROXIMATE_CURVATURE_H
#define CGAL_POLICIES_INTERNAL_APPROXIMATE_CURVATURE_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace cgal_policies {
namespace internal {

// Value-initialised to zero in a property map, where an Eigen vector would start uninitialised
// (and GCC rightly warns when the map copies that default).
using Stored_normal = std::array<double, 3>;

inline Stored_normal to_stored_normal(const Eigen::Vector3d& n) { return {n.x(), n.y(), n.z()}; }
inline Eigen::Vector3d to_vector(const Stored_normal& n) { return {n[0], n[1], n[2]}; }

// A zero normal (faces that cancel) counts as perpendicular to everything: cosine 0. An isolated
// vertex gets 1.
template <typename TriangleMesh, typename NormalMap>
double approximate_curvature(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                             const TriangleMesh& tm, const NormalMap& normals) {
  const auto h = halfedge(v, tm);
  if (h == boost::graph_traits<TriangleMesh>::null_halfedge()) return 1.0;
  const Eigen::Vector3d n = to_vector(get(normals, v));
  double sum = 0;
  std::size_t valence = 0;
  for (auto around : CGAL::halfedges_around_target(h, tm)) {
    sum += n.dot(to_vector(get(normals, source(around, tm))));
    ++valence;
  }
  return sum / double(valence);
}

// The normalised sum of the unit face normals (eq. 10); zero for an isolated vertex.
template <typename TriangleMesh, typename VertexPointMap>
Stored_normal curvature_vertex_normal(
    typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, const TriangleMesh& tm,
    const VertexPointMap& vpm) {
  if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge()) return {};
  return to_stored_normal(vertex_normal(v, tm, vpm, Normal_weighting::unit));
}

template <typename TriangleMesh, typename VertexPointMap, typename NormalMap, typename CurvatureMap>
void compute_approximate_curvatures(const TriangleMesh& tm, const VertexPointMap& vpm,
                                    NormalMap normals, CurvatureMap curvatures) {
  for (auto v : vertices(tm)) put(normals, v, curvature_vertex_normal(v, tm, vpm));
  for (auto v : vertices(tm)) put(curvatures, v, approximate_curvature(v, tm, normals));
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_APPROXIMATE_CURVATURE_H
