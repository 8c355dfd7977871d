// The placement chain of [QEM-tutorial] (docs/quadric_core.md): the quadric's minimiser when well
// defined, else the best point of the edge, else the best of its ends and midpoint.
#ifndef CGAL_POLICIES_INTERNAL_QUADRIC_PLACEMENT_H
#define CGAL_POLICIES_INTERNAL_QUADRIC_PLACEMENT_H

#include <cgal_policies/internal/Quadric.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>

namespace cgal_policies {
namespace internal {

enum class Placement_branch { solve, segment, best_of_three };

struct Quadric_placement {
  Eigen::Vector3d point;
  Placement_branch branch;
};

// Smallest over largest eigenvalue of A below which the 3x3 solve is not trusted: a plain
// determinant test passes nearly flat quadrics whose minimiser flies far away.
constexpr double kMinimumConditioning = 1e-6;
// A minimiser farther than this many edge lengths from the edge is rejected as unstable.
constexpr double kMaximumSolveDistance = 2.0;

inline double squared_distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& p0,
                                          const Eigen::Vector3d& p1) {
  const Eigen::Vector3d d = p1 - p0;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((x - p0).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (x - (p0 + t * d)).squaredNorm();
}

// a is PSD with eigenvalues l0 <= l1 <= l2, so l2 lies in [trace / 3, trace], l1 l2 in [e2 / 3, e2]
// (e2 = l0 l1 + l0 l2 + l1 l2, the sum of the principal 2x2 minors), l1 <= 3 e2 / trace and l0
// = det / (l1 l2) in [det / e2, 3 det / e2]. These bounds settle the test, outside a band around
// the limit, without the eigen solver: most quadrics of a dense scan are nearly flat (tiny e2).
inline bool is_well_conditioned(const Eigen::Matrix3d& a) {
  const double trace = a.trace();
  if (!(trace > 0)) return false;
  const double det = a.determinant();
  // A large det settles curved stretches before e2 is needed (e2 <= trace^2 / 3, so the test on
  // det / e2 below would pass them too).
  if (det > kMinimumConditioning * trace * trace * trace) return true;
  const double e2 = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) + a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0) +
                    a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
  const double below_limit = kMinimumConditioning * trace / 3;  // at most the limit, k l2
  if (3 * e2 / trace <= below_limit || 3 * det / e2 <= below_limit) return false;
  if (det / e2 > kMinimumConditioning * trace) return true;  // l0 above k trace, so above k l2
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(a, Eigen::EigenvaluesOnly);
  const double largest = eigen.eigenvalues()(2);
  return largest > 0 && eigen.eigenvalues()(0) > kMinimumConditioning * largest;
}

inline Quadric_placement optimal_placement(const Quadric& q, const Eigen::Vector3d& p0,
                                           const Eigen::Vector3d& p1) {
  const Eigen::Matrix3d a = q.linear_part();
  const Eigen::Vector3d b = q.offset();
  const Eigen::Vector3d d = p1 - p0;

  if (is_well_conditioned(a)) {
    const Eigen::Vector3d x = a.inverse() * (-b);
    const double limit = kMaximumSolveDistance * kMaximumSolveDistance * d.squaredNorm();
    if (x.allFinite() && squared_distance_to_segment(x, p0, p1) <= limit)
      return {x, Placement_branch::solve};
  }

  // Along p0 + t d the quadric is (d.A.d) t^2 + 2 (A p0 + b).d t + const.
  const double curvature = d.dot(a * d);
  if (curvature > 1e-12 * a.trace() * d.squaredNorm()) {
    const double t = std::clamp(-(a * p0 + b).dot(d) / curvature, 0.0, 1.0);
    return {p0 + t * d, Placement_branch::segment};
  }

  // Ties go to the first in this order, so flat regions keep original vertex positions.
  const Eigen::Vector3d candidates[] = {p0, p1, 0.5 * (p0 + p1)};
  const Eigen::Vector3d* best = &candidates[0];
  double best_cost = q.evaluate(*best);
  for (const Eigen::Vector3d& c : candidates) {
    const double cost = q.evaluate(c);
    if (cost < best_cost) {
      best_cost = cost;
      best = &c;
    }
  }
  return {*best, Placement_branch::best_of_three};
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_QUADRIC_PLACEMENT_H
