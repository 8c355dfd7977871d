// A symmetric 4x4 error quadric as its 10 distinct coefficients ([GH97]; docs/quadric_core.md):
// Q(x) = x~^T Q x~, A = upper-left 3x3, b = last column, c = corner.
#ifndef CGAL_POLICIES_INTERNAL_QUADRIC_H
#define CGAL_POLICIES_INTERNAL_QUADRIC_H

#include <Eigen/Core>

#include <array>

namespace cgal_policies {
namespace internal {

class Quadric {
 public:
  // Layout: a00 a01 a02 b0 a11 a12 b1 a22 b2 c.
  Quadric() : m_q{} {}

  // The squared distance to the plane n.x + d = 0 (|n| = 1), times weight.
  static Quadric from_plane(const Eigen::Vector3d& n, double d, double weight) {
    Quadric q;
    q.m_q = {n.x() * n.x(), n.x() * n.y(), n.x() * n.z(), n.x() * d, n.y() * n.y(),
             n.y() * n.z(), n.y() * d,     n.z() * n.z(), n.z() * d, d * d};
    for (double& x : q.m_q) x *= weight;
    return q;
  }

  // x^T a x + 2 b.x + c, a symmetric.
  static Quadric from_parts(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double c) {
    Quadric q;
    q.m_q = {a(0, 0), a(0, 1), a(0, 2), b.x(), a(1, 1), a(1, 2), b.y(), a(2, 2), b.z(), c};
    return q;
  }

  Quadric& operator+=(const Quadric& other) {
    for (std::size_t i = 0; i < m_q.size(); ++i) m_q[i] += other.m_q[i];
    return *this;
  }
  friend Quadric operator+(Quadric a, const Quadric& b) { return a += b; }

  Quadric scaled(double s) const {
    Quadric q = *this;
    for (double& x : q.m_q) x *= s;
    return q;
  }

  double evaluate(const Eigen::Vector3d& p) const {
    const double x = p.x(), y = p.y(), z = p.z();
    return x * (m_q[0] * x + 2 * (m_q[1] * y + m_q[2] * z + m_q[3])) +
           y * (m_q[4] * y + 2 * (m_q[5] * z + m_q[6])) + z * (m_q[7] * z + 2 * m_q[8]) + m_q[9];
  }

  Eigen::Matrix3d linear_part() const {
    Eigen::Matrix3d a;
    a << m_q[0], m_q[1], m_q[2], m_q[1], m_q[4], m_q[5], m_q[2], m_q[5], m_q[7];
    return a;
  }
  Eigen::Vector3d offset() const { return {m_q[3], m_q[6], m_q[8]}; }
  double constant() const { return m_q[9]; }

 private:
  std::array<double, 10> m_q;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_QUADRIC_H
