// Reading the values a surface carries at the point nearest to a new vertex: shared by the
// attributes policy, the fast engine and the fitting pass (docs/attributes.md).
#ifndef CGAL_POLICIES_INTERNAL_NEAREST_CORNER_VALUES_H
#define CGAL_POLICIES_INTERNAL_NEAREST_CORNER_VALUES_H

#include <cgal_policies/internal/triangle_closest_point.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <limits>

namespace cgal_policies {
namespace internal {

struct Nearest_triangle_point {
  std::size_t triangle = 0;
  std::array<double, 3> weights{};  // barycentric, of the triangle's corners in points() order
};

// Of the triangles 0..count-1 that `included(k)` takes, the one whose closest point to p is the
// nearest; `points(k)` gives triangle k's three corners.
template <class Included, class Points>
Nearest_triangle_point nearest_triangle_point(const Eigen::Vector3d& p, std::size_t count,
                                              const Included& included, const Points& points) {
  double best = std::numeric_limits<double>::infinity();
  Nearest_triangle_point nearest;
  for (std::size_t k = 0; k < count; ++k) {
    if (!included(k)) continue;
    const std::array<Eigen::Vector3d, 3> q = points(k);
    const Eigen::Vector3d w = closest_barycentric(p, q[0], q[1], q[2]);
    const double distance = (w[0] * q[0] + w[1] * q[1] + w[2] * q[2] - p).squaredNorm();
    if (distance < best) {
      best = distance;
      nearest = {k, {w[0], w[1], w[2]}};
    }
  }
  return nearest;
}

// A corner's own values when the weights single it out (exactly, with no rounding of a blend),
// else Blender::blend of the three at the weights.
template <class Blender, class Values>
Values values_at_weights(const std::array<Values, 3>& corner,
                         const std::array<double, 3>& weights) {
  for (int k = 0; k < 3; ++k)
    if (weights[k] == 1) return corner[k];
  return Blender::blend(corner, weights);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_NEAREST_CORNER_VALUES_H
