// An error quadric over a position and up to kMaxAttributes scalar attributes ([Hoppe99], "New
// quadric metric"; docs/attributes.md): for a face, the squared distance of p to the face's plane
// plus, for each attribute j, the squared difference between s_j and the face's linear field of j
// at p. Summed over faces it is x^T A x + 2 b^T x + c with x = (p, s), where the attribute block of
// A is diagonal (one unit term per face and attribute), so the best attributes for a given p, and
// the position quadric they leave, take no matrix inverse.
#ifndef CGAL_POLICIES_INTERNAL_ATTRIBUTE_QUADRIC_H
#define CGAL_POLICIES_INTERNAL_ATTRIBUTE_QUADRIC_H

#include <cgal_policies/internal/Quadric.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <limits>

namespace cgal_policies {
namespace internal {

class Attribute_quadric {
 public:
  // Two texture coordinates, a normal and a colour (red, green, blue, alpha).
  static constexpr int kMaxAttributes = 9;
  using Attributes = Eigen::Matrix<double, kMaxAttributes, 1>;

  Attribute_quadric()
      : m_a_pp(Eigen::Matrix3d::Zero()),
        m_a_ps(Eigen::Matrix<double, 3, kMaxAttributes>::Zero()),
        m_a_ss(Attributes::Zero()),
        m_b_p(Eigen::Vector3d::Zero()),
        m_b_s(Attributes::Zero()),
        m_c(0) {}

  // The face (p[0], p[1], p[2]) with attribute values s[k] at its corners, times `weight`. An
  // attribute that is NaN at any corner adds no term; a face of zero area adds nothing.
  static Attribute_quadric from_face(const std::array<Eigen::Vector3d, 3>& p,
                                     const std::array<Attributes, 3>& s, double weight) {
    Attribute_quadric q;
    const Eigen::Vector3d area_normal = (p[1] - p[0]).cross(p[2] - p[0]);
    const double twice_area = area_normal.norm();
    if (!(twice_area > 0)) return q;
    const Eigen::Vector3d n = area_normal / twice_area;
    const double d = -n.dot(p[0]);
    q.m_a_pp = weight * n * n.transpose();
    q.m_b_p = weight * d * n;
    q.m_c = weight * d * d;
    // The field's gradient g lies in the plane: g.(p1 - p0) = s1 - s0, g.(p2 - p0) = s2 - s0.
    Eigen::Matrix3d frame;
    frame.row(0) = p[1] - p[0];
    frame.row(1) = p[2] - p[0];
    frame.row(2) = n;
    const Eigen::PartialPivLU<Eigen::Matrix3d> solver(frame);
    for (int j = 0; j < kMaxAttributes; ++j) {
      if (!std::isfinite(s[0][j]) || !std::isfinite(s[1][j]) || !std::isfinite(s[2][j])) continue;
      const Eigen::Vector3d g =
          solver.solve(Eigen::Vector3d(s[1][j] - s[0][j], s[2][j] - s[0][j], 0));
      const double e = s[0][j] - g.dot(p[0]);  // the field is g.p + e
      q.m_a_pp += weight * g * g.transpose();
      q.m_a_ps.col(j) = -weight * g;
      q.m_a_ss[j] = weight;
      q.m_b_p += weight * e * g;
      q.m_b_s[j] = -weight * e;
      q.m_c += weight * e * e;
    }
    return q;
  }

  Attribute_quadric& operator+=(const Attribute_quadric& o) {
    m_a_pp += o.m_a_pp;
    m_a_ps += o.m_a_ps;
    m_a_ss += o.m_a_ss;
    m_b_p += o.m_b_p;
    m_b_s += o.m_b_s;
    m_c += o.m_c;
    return *this;
  }
  friend Attribute_quadric operator+(Attribute_quadric a, const Attribute_quadric& b) {
    return a += b;
  }

  // The error at position p with attributes s (attributes without a term are ignored).
  double evaluate(const Eigen::Vector3d& p, const Attributes& s) const {
    const Attributes t = defined(s);
    return p.dot(m_a_pp * p) + 2 * p.dot(m_a_ps * t) + t.dot(m_a_ss.cwiseProduct(t)) +
           2 * m_b_p.dot(p) + 2 * m_b_s.dot(t) + m_c;
  }

  // The attributes that make the error at p smallest; NaN for an attribute without a term.
  Attributes best_attributes(const Eigen::Vector3d& p) const {
    Attributes s;
    for (int j = 0; j < kMaxAttributes; ++j)
      s[j] = m_a_ss[j] > 0 ? -(m_a_ps.col(j).dot(p) + m_b_s[j]) / m_a_ss[j]
                           : std::numeric_limits<double>::quiet_NaN();
    return s;
  }

  // The position quadric left once the attributes take their best values: its value at p is
  // evaluate(p, best_attributes(p)).
  Quadric position_quadric() const {
    Eigen::Matrix3d a = m_a_pp;
    Eigen::Vector3d b = m_b_p;
    double c = m_c;
    for (int j = 0; j < kMaxAttributes; ++j) {
      if (!(m_a_ss[j] > 0)) continue;
      a -= m_a_ps.col(j) * m_a_ps.col(j).transpose() / m_a_ss[j];
      b -= m_a_ps.col(j) * m_b_s[j] / m_a_ss[j];
      c -= m_b_s[j] * m_b_s[j] / m_a_ss[j];
    }
    return Quadric::from_parts(a, b, c);
  }

 private:
  Attributes defined(const Attributes& s) const {
    Attributes t;
    for (int j = 0; j < kMaxAttributes; ++j) t[j] = m_a_ss[j] > 0 ? s[j] : 0;
    return t;
  }

  Eigen::Matrix3d m_a_pp;
  Eigen::Matrix<double, 3, kMaxAttributes> m_a_ps;
  Attributes m_a_ss;  // the diagonal of the attribute block
  Eigen::Vector3d m_b_p;
  Attributes m_b_s;
  double m_c;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_ATTRIBUTE_QUADRIC_H
