// Flat_frame: a triangle t's plane seen from above, for the flatness argument (docs/hausdorff.md,
// "Flat regions"). Reference triangles within `limit` of t's plane that face its way project onto
// it without folding; if the projection of a set K of them holds t's centroid and no edge of K not
// shared by two of its triangles crosses t, it covers t: t is within `limit` of K.
#ifndef CGAL_POLICIES_INTERNAL_FLAT_FRAME_H
#define CGAL_POLICIES_INTERNAL_FLAT_FRAME_H

#include <cgal_policies/internal/triangle_distance.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace cgal_policies {
namespace internal {

class Flat_frame {
 public:
  Flat_frame(const Triangle_corners& t, double limit) : m_origin(t[0]), m_limit(limit) {
    const Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
    const double twice_area = normal.norm();
    m_valid = twice_area > 0;
    if (!m_valid) return;
    m_n = normal / twice_area;
    m_u = (t[1] - t[0]).normalized();
    m_w = m_n.cross(m_u);
    m_scale = std::sqrt(twice_area);
    for (int k = 0; k < 3; ++k) m_t[k] = project(t[k]);
    m_centroid = (m_t[0] + m_t[1] + m_t[2]) / 3;
    m_min = m_t[0].cwiseMin(m_t[1]).cwiseMin(m_t[2]);
    m_max = m_t[0].cwiseMax(m_t[1]).cwiseMax(m_t[2]);
  }

  bool valid() const { return m_valid; }

  // When false, no edge of q crosses t.
  bool may_meet(const Triangle_corners& q) const {
    Eigen::Vector2d lo = project(q[0]), hi = lo;
    for (int k = 1; k < 3; ++k) {
      const Eigen::Vector2d p = project(q[k]);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    return (lo.array() <= m_max.array()).all() && (hi.array() >= m_min.array()).all();
  }

  bool holds(const Triangle_corners& q) const {
    for (const Eigen::Vector3d& p : q)
      if (std::abs((p - m_origin).dot(m_n)) > m_limit) return false;
    return (q[1] - q[0]).cross(q[2] - q[0]).dot(m_n) > 0;
  }

  // q must face t's way.
  bool holds_centroid(const Triangle_corners& q) const {
    const Eigen::Vector2d a = project(q[0]), b = project(q[1]), c = project(q[2]);
    return cross(b - a, m_centroid - a) >= 0 && cross(c - b, m_centroid - b) >= 0 &&
           cross(a - c, m_centroid - c) >= 0;
  }

  // Whether ab has a part of positive length inside t (projected), t shrunk by a rounding margin.
  bool crosses(const Eigen::Vector3d& a3, const Eigen::Vector3d& b3) const {
    const Eigen::Vector2d a = project(a3), d = project(b3) - a;
    double lo = 0, hi = 1;
    for (int k = 0; k < 3 && lo < hi; ++k) {
      const Eigen::Vector2d e = m_t[(k + 1) % 3] - m_t[k];
      const double at = cross(e, a - m_t[k]), slope = cross(e, d);
      const double margin = 1e-12 * m_scale * e.norm();
      if (slope == 0) {
        if (at <= margin) hi = lo;
      } else if (slope > 0) {
        lo = (std::max)(lo, (margin - at) / slope);
      } else {
        hi = (std::min)(hi, (margin - at) / slope);
      }
    }
    return hi - lo > 1e-12;
  }

 private:
  static double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  }
  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - m_origin;
    return {d.dot(m_u), d.dot(m_w)};
  }

  Eigen::Vector3d m_origin, m_n, m_u, m_w;
  double m_limit;
  double m_scale = 0;
  bool m_valid = false;
  std::array<Eigen::Vector2d, 3> m_t;
  Eigen::Vector2d m_centroid, m_min, m_max;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FLAT_FRAME_H
