// The local measures of the multi-feature fusion cost (Wang et al. 2013, seed 000; policies.md §2):
// the side ratio zeta of an edge (the paper's eq. 9), the angle between vertex normals and the
// normal twist along an edge (our reconstruction of the missing eqs. 4-8), and their means over the
// neighbours of a vertex.
#ifndef CGAL_POLICIES_INTERNAL_FEATURE_FUSION_MEASURES_H
#define CGAL_POLICIES_INTERNAL_FEATURE_FUSION_MEASURES_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace cgal_policies {
namespace internal {

// Eq. 9: the length of h's edge over the sum of the other edges of its triangles (four inside,
// two on a border). Zero for an edge whose triangles have no length at all.
template <typename TriangleMesh, typename VertexPointMap>
double side_ratio(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                  const TriangleMesh& tm, const VertexPointMap& vpm) {
  auto length = [&](auto g) {
    return (to_eigen(get(vpm, target(g, tm))) - to_eigen(get(vpm, source(g, tm)))).norm();
  };
  double others = 0;
  for (auto g : {h, opposite(h, tm)})
    if (!is_border(g, tm)) others += length(next(g, tm)) + length(prev(g, tm));
  return others > 0 ? length(h) / others : 0.0;
}

// The angle between two unit normals in radians, from their difference: accurate near 0, where
// acos is not, and cheaper than atan2 (it runs for every edge around every refreshed vertex).
inline double normal_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return 2 * std::asin((std::min)(1.0, 0.5 * (b - a).norm()));
}

// The twist of the normal along the edge v -> j: the change of normal across the edge's direction,
// (n_j - n_v) . b with b = nbar x t, t the unit edge and nbar the mean normal made perpendicular to
// t. About the geodesic torsion times the edge length: zero along principal directions, hence along
// every edge of a plane or a sphere, and largest at 45 degrees to them (saddles, cylinders).
inline double normal_twist(const Eigen::Vector3d& p_v, const Eigen::Vector3d& n_v,
                           const Eigen::Vector3d& p_j, const Eigen::Vector3d& n_j) {
  const Eigen::Vector3d t = unit_or_zero(p_j - p_v);
  const Eigen::Vector3d mean = n_v + n_j;
  const Eigen::Vector3d nbar = unit_or_zero(mean - mean.dot(t) * t);
  return (n_j - n_v).dot(nbar.cross(t));
}

struct Normal_variation {
  double mean_angle = 0;  // thbar(v), radians
  double mean_twist = 0;  // T(v)
};

// thbar(v), the mean angle between v's normal and its neighbours' normals, and T(v), the mean
// absolute normal twist along the edges around v, in one pass. `normal` maps a vertex to its unit
// normal.
template <typename TriangleMesh, typename VertexPointMap, typename NormalFunction>
Normal_variation normal_variation(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                                  const TriangleMesh& tm, const VertexPointMap& vpm,
                                  const NormalFunction& normal) {
  const Eigen::Vector3d p_v = to_eigen(get(vpm, v));
  const Eigen::Vector3d n_v = normal(v);
  Normal_variation sum;
  std::size_t count = 0;
  for (auto j : CGAL::vertices_around_target(halfedge(v, tm), tm)) {
    const Eigen::Vector3d n_j = normal(j);
    sum.mean_angle += normal_angle(n_v, n_j);
    sum.mean_twist += std::abs(normal_twist(p_v, n_v, to_eigen(get(vpm, j)), n_j));
    ++count;
  }
  if (count > 0) {
    sum.mean_angle /= double(count);
    sum.mean_twist /= double(count);
  }
  return sum;
}

// L0: the mean edge length of the mesh; zero for a mesh without edges.
template <typename TriangleMesh, typename VertexPointMap>
double mean_edge_length(const TriangleMesh& tm, const VertexPointMap& vpm) {
  double sum = 0;
  std::size_t count = 0;
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    sum += (to_eigen(get(vpm, target(h, tm))) - to_eigen(get(vpm, source(h, tm)))).norm();
    ++count;
  }
  return count > 0 ? sum / double(count) : 0.0;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FEATURE_FUSION_MEASURES_H
