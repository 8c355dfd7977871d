// The point of a triangle nearest to a point, as barycentric coordinates (Ericson, "Real-Time
// Collision Detection" §5.1.5), for the fitting pass's correspondences (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLE_CLOSEST_POINT_H
#define CGAL_POLICIES_INTERNAL_TRIANGLE_CLOSEST_POINT_H

#include <Eigen/Core>

namespace cgal_policies {
namespace internal {

inline Eigen::Vector3d closest_barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {1 - t, t, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {1 - t, 0, t};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - t, t};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) {  // degenerate: the nearest corner
    const double da = ap.squaredNorm(), db = bp.squaredNorm(), dc = cp.squaredNorm();
    if (da <= db && da <= dc) return {1, 0, 0};
    return db <= dc ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(0, 0, 1);
  }
  return {va / sum, vb / sum, vc / sum};
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLE_CLOSEST_POINT_H
