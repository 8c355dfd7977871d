// Point-triangle distances in double precision, for the Hausdorff checks (docs/hausdorff.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLE_DISTANCE_H
#define CGAL_POLICIES_INTERNAL_TRIANGLE_DISTANCE_H

#include <cgal_policies/internal/quadric_placement.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace cgal_policies {
namespace internal {

using Triangle_corners = std::array<Eigen::Vector3d, 3>;

inline double squared_distance_to_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (ap - (d1 / (d1 - d3)) * ab).squaredNorm();
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (ap - (d2 / (d2 - d6)) * ac).squaredNorm();
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)).squaredNorm();
  const double sum = va + vb + vc;
  if (!(sum > 0))
    return std::min({squared_distance_to_segment(p, a, b), squared_distance_to_segment(p, b, c),
                     squared_distance_to_segment(p, c, a)});
  const double v = vb / sum, w = vc / sum;
  return (ap - v * ab - w * ac).squaredNorm();
}

inline double squared_distance_to_triangle(const Eigen::Vector3d& p, const Triangle_corners& t) {
  return squared_distance_to_triangle(p, t[0], t[1], t[2]);
}

// The largest distance from a point of the triangle to its nearest corner: the circumradius when
// the triangle is acute, else at most half the longest edge.
inline double covering_radius(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
  std::array<double, 3> e2 = {(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()};
  std::sort(e2.begin(), e2.end());
  if (e2[2] >= e2[0] + e2[1]) return 0.5 * std::sqrt(e2[2]);
  const double twice_area = (b - a).cross(c - a).norm();
  return std::sqrt(e2[0] * e2[1] * e2[2]) / (2 * twice_area);
}

// The distance from a point to one triangle of the reference (kNoTriangle when unknown): an upper
// bound of its distance to the reference, which is all the conservative tests need.
struct Reference_sample {
  double distance = 0;
  std::size_t triangle = kNoTriangle;
  static constexpr std::size_t kNoTriangle = std::size_t(-1);
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLE_DISTANCE_H
