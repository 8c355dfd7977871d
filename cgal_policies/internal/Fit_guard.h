// The checks every change of the fitting pass must pass (docs/fitting.md): no face normal turns by
// more than the limit from where it was before the pass, no face becomes degenerate, and no changed
// face crosses another one (the faces around a moved vertex, or the two of a flipped edge).
#ifndef CGAL_POLICIES_INTERNAL_FIT_GUARD_H
#define CGAL_POLICIES_INTERNAL_FIT_GUARD_H

#include <cgal_policies/internal/Face_grid.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/triangles_intersect.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// Faces thinner than this (twice the area over the longest edge squared) count as degenerate.
constexpr double kMinFaceShape = 1e-6;

inline Eigen::Vector3d unit_normal(const Indexed_triangle& t) {
  return unit_or_zero(triangle_area_normal(t.points[0], t.points[1], t.points[2]));
}

class Fit_guard {
 public:
  // `faces[i]` is face i of the mesh as it is before the pass; `cell` is the grid's cell size.
  Fit_guard(std::vector<Indexed_triangle> faces, double max_normal_angle_deg, double cell)
      : m_min_cosine(std::cos(max_normal_angle_deg * 3.14159265358979323846 / 180)),
        m_grid(faces.size(), cell),
        m_current(std::move(faces)) {
    for (std::uint32_t i = 0; i < m_current.size(); ++i) {
      m_reference.push_back(unit_normal(m_current[i]));
      m_grid.insert(i, m_current[i].points);
    }
    // Faces that cross already may go on crossing: the pass adds no crossing, it removes none.
    for (std::uint32_t i = 0; i < m_current.size(); ++i)
      m_grid.any_near(m_current[i].points, i, [&](std::uint32_t g) {
        if (g > i && faces_intersect(m_current[i], m_current[g]))
          m_crossing_before.push_back({i, g});
        return false;
      });
    std::sort(m_crossing_before.begin(), m_crossing_before.end());
  }

  const Eigen::Vector3d& reference(std::uint32_t face) const { return m_reference[face]; }

  // Whether faces `changed` may become `triangles`: each stays proper and within the angle of its
  // reference normal, and none crosses another face of the mesh as it would then be.
  bool allows(const std::vector<std::uint32_t>& changed,
              const std::vector<Indexed_triangle>& triangles,
              const std::vector<Eigen::Vector3d>& references) {
    for (std::size_t i = 0; i < triangles.size(); ++i)
      if (!keeps_normal(triangles[i], references[i])) return false;
    for (std::size_t i = 0; i < triangles.size(); ++i)
      for (std::size_t j = i + 1; j < triangles.size(); ++j)
        if (crossing(changed[i], changed[j], triangles[i], triangles[j])) return false;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const bool crosses = m_grid.any_near(triangles[i].points, changed[i], [&](std::uint32_t g) {
        if (std::find(changed.begin(), changed.end(), g) != changed.end()) return false;
        return crossing(changed[i], g, triangles[i], m_current[g]);
      });
      if (crosses) return false;
    }
    return true;
  }

  // Faces `changed` became `triangles`, which keep `references` from now on.
  void apply(const std::vector<std::uint32_t>& changed,
             const std::vector<Indexed_triangle>& triangles,
             const std::vector<Eigen::Vector3d>& references) {
    for (std::size_t i = 0; i < changed.size(); ++i) {
      m_grid.erase(changed[i]);
      m_grid.insert(changed[i], triangles[i].points);
      m_current[changed[i]] = triangles[i];
      m_reference[changed[i]] = references[i];
    }
  }

 private:
  // A crossing of faces f and g as they would be, unless they crossed before the pass.
  bool crossing(std::uint32_t f, std::uint32_t g, const Indexed_triangle& s,
                const Indexed_triangle& t) const {
    if (!faces_intersect(s, t)) return false;
    const std::pair<std::uint32_t, std::uint32_t> pair = std::minmax(f, g);
    return !std::binary_search(m_crossing_before.begin(), m_crossing_before.end(), pair);
  }

  bool keeps_normal(const Indexed_triangle& t, const Eigen::Vector3d& reference) const {
    const Eigen::Vector3d n = triangle_area_normal(t.points[0], t.points[1], t.points[2]);
    const double longest = std::max({(t.points[1] - t.points[0]).squaredNorm(),
                                     (t.points[2] - t.points[1]).squaredNorm(),
                                     (t.points[0] - t.points[2]).squaredNorm()});
    if (!(n.norm() > kMinFaceShape * longest)) return false;
    return reference.isZero() || n.normalized().dot(reference) >= m_min_cosine;
  }

  double m_min_cosine;
  Face_grid m_grid;
  std::vector<Indexed_triangle> m_current;
  std::vector<Eigen::Vector3d> m_reference;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_crossing_before;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_GUARD_H
