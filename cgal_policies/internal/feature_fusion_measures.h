// The local measures of the multi-feature fusion cost of [Wang13] (docs/fusion.md): the side ratio
// of eq. 9, and the normal angle and twist that reconstruct the missing eqs. 4-8.
#ifndef CGAL_POLICIES_INTERNAL_FEATURE_FUSION_MEASURES_H
#define CGAL_POLICIES_INTERNAL_FEATURE_FUSION_MEASURES_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cgal_policies {
namespace internal {

// Eq. 9 (four other edges inside, two on a border); zero when they have no length.
template <typename TriangleMesh, typename VertexPointMap>
double side_ratio(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                  const TriangleMesh& tm, const VertexPointMap& vpm) {
  auto length = [&](auto g) {
    return (to_eigen(get(vpm, target(g, tm))) - to_eigen(get(vpm, source(g, tm)))).norm();
  };
  double others = 0;
  for (auto g : {h, opposite(h, tm)})
    if (!CGAL::is_border(g, tm)) others += length(next(g, tm)) + length(prev(g, tm));
  return others > 0 ? length(h) / others : 0.0;
}

// From the normals' difference: accurate near 0, where acos is not, and cheaper than atan2.
inline double normal_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return 2 * std::asin((std::min)(1.0, 0.5 * (b - a).norm()));
}

// (n_j - n_v) . (nbar x t), t the unit edge v -> j and nbar the mean normal made perpendicular to
// t: about geodesic torsion times edge length, zero on planes and spheres (docs/fusion.md).
inline double normal_twist(const Eigen::Vector3d& p_v, const Eigen::Vector3d& n_v,
                           const Eigen::Vector3d& p_j, const Eigen::Vector3d& n_j) {
  const Eigen::Vector3d t = unit_or_zero(p_j - p_v);
  const Eigen::Vector3d mean = n_v + n_j;
  const Eigen::Vector3d nbar = unit_or_zero(mean - mean.dot(t) * t);
  return (n_j - n_v).dot(nbar.cross(t));
}

struct Normal_variation {
  double angle = 0;  // radians
  double twist = 0;  // absolute normal twist
};

// Symmetric in the ends, so one value per edge serves both; the twist only when `with_twist`.
template <typename TriangleMesh, typename VertexPointMap, typename NormalFunction>
Normal_variation edge_normal_variation(
    typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm,
    const VertexPointMap& vpm, const NormalFunction& normal, bool with_twist) {
  const auto v = source(h, tm), j = target(h, tm);
  const Eigen::Vector3d n_v = normal(v), n_j = normal(j);
  Normal_variation variation;
  variation.angle = normal_angle(n_v, n_j);
  if (with_twist)
    variation.twist =
        std::abs(normal_twist(to_eigen(get(vpm, v)), n_v, to_eigen(get(vpm, j)), n_j));
  return variation;
}

// In fixed point (units of 2^-44) with their count of edges: integer sums do not depend on the
// order of their terms, so a sum updated after each collapse equals the sum computed afresh.
struct Normal_variation_sum {
  static constexpr double unit = 0x1p-44;
  std::int64_t angle = 0;
  std::int64_t twist = 0;
  std::int64_t count = 0;

  static Normal_variation_sum of(const Normal_variation& variation) {
    return {std::llround(variation.angle / unit), std::llround(variation.twist / unit), 1};
  }
  Normal_variation_sum& operator+=(const Normal_variation_sum& other) {
    angle += other.angle;
    twist += other.twist;
    count += other.count;
    return *this;
  }
  Normal_variation_sum& operator-=(const Normal_variation_sum& other) {
    angle -= other.angle;
    twist -= other.twist;
    count -= other.count;
    return *this;
  }
  double mean_angle() const { return count > 0 ? double(angle) * unit / double(count) : 0.0; }
  double mean_twist() const { return count > 0 ? double(twist) * unit / double(count) : 0.0; }
};

template <typename TriangleMesh, typename EdgeTerm>
Normal_variation_sum normal_variation_sum(
    typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, const TriangleMesh& tm,
    const EdgeTerm& edge_term) {
  Normal_variation_sum sum;
  for (auto h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) sum += edge_term(h);
  return sum;
}

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
