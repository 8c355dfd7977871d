// Lindstrom_turk_constraints: the placement of Lindstrom and Turk's memoryless simplification
// ([LT98] §3; docs/flat_lt.md): up to three linear constraints a·x = d on the new point, each
// taken from the next objective in turn and kept only when it is not within alpha = 1 degree of
// the span of those before it, so that a nearly degenerate objective leaves the choice to the next.
#ifndef CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_CONSTRAINTS_H
#define CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_CONSTRAINTS_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <optional>

namespace cgal_policies {
namespace internal {

class Lindstrom_turk_constraints {
 public:
  bool complete() const { return m_count == 3; }

  // a·x = d, unless a is zero, not finite, or too close to the span of the constraints so far.
  void add(const Eigen::Vector3d& a, double d) {
    const double squared_length = a.squaredNorm();
    if (!std::isfinite(squared_length) || squared_length == 0 || complete()) return;
    if (m_count == 1) {
      const double along = m_rows.row(0).dot(a);
      if (along * along > squared_length * kSquaredCosAlpha) return;
    } else if (m_count == 2) {
      const Eigen::Vector3d normal = m_rows.row(0).cross(m_rows.row(1));
      const double along = normal.dot(a);
      if (along * along <= normal.squaredNorm() * squared_length * kSquaredSinAlpha) return;
    }
    const double length = std::sqrt(squared_length);
    m_rows.row(m_count) = a / length;
    m_values[m_count] = d / length;
    ++m_count;
  }

  // The minimum of x^T H x + 2 c·x (H symmetric) within the constraints so far: its gradient
  // H x + c = 0 along the directions they leave free.
  void add_minimum_of(const Eigen::Matrix3d& h, const Eigen::Vector3d& c) {
    if (m_count == 0) {
      for (int i = 0; i < 3; ++i) add(h.row(i), -c[i]);
    } else if (m_count == 1) {
      const Eigen::Vector3d first = m_rows.row(0);
      const Eigen::Vector3d free1 = orthogonal_to(first);
      const Eigen::Vector3d free2 = first.cross(free1);
      add(h * free1, -free1.dot(c));
      add(h * free2, -free2.dot(c));
    } else if (m_count == 2) {
      const Eigen::Vector3d free = m_rows.row(0).cross(m_rows.row(1));
      add(h * free, -free.dot(c));
    }
  }

  // The point the three constraints meet at; none with fewer, or when they do not meet in one.
  std::optional<Eigen::Vector3d> solve() const {
    if (!complete()) return std::nullopt;
    const double determinant = m_rows.determinant();
    if (determinant == 0 || !std::isfinite(determinant)) return std::nullopt;
    const Eigen::Vector3d x = m_rows.inverse() * m_values;
    if (!x.allFinite()) return std::nullopt;
    return x;
  }

 private:
  // cos^2 and sin^2 of alpha = 1 degree, [LT98]'s choice.
  static constexpr double kSquaredCosAlpha = 0.99969541350954794;
  static constexpr double kSquaredSinAlpha = 3.0458649045205886e-4;

  // A vector orthogonal to a (not zero), from its largest component.
  static Eigen::Vector3d orthogonal_to(const Eigen::Vector3d& a) {
    const Eigen::Vector3d magnitude = a.cwiseAbs();
    if (magnitude.x() >= magnitude.y() && magnitude.x() >= magnitude.z())
      return {-a.z() / a.x(), 0, 1};
    if (magnitude.y() >= magnitude.z()) return {0, -a.z() / a.y(), 1};
    return {1, 0, -a.x() / a.z()};
  }

  int m_count = 0;
  Eigen::Matrix3d m_rows = Eigen::Matrix3d::Zero();
  Eigen::Vector3d m_values = Eigen::Vector3d::Zero();
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_CONSTRAINTS_H
