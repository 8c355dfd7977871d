// Bounded_normal_angle_filter: a CGAL `Filter` that refuses a collapse turning the normal of a
// surviving face by more than a bound (CGAL's Bounded_normal_change_filter fixes it at 90 degrees)
// or leaving that face degenerate (docs/quadric_core.md). It decorates a base filter, run first.
// Parameter: max_angle_degrees, the largest allowed turn of a face normal in degrees (default 90).
// Usage:
//   cgal_policies::Bounded_normal_angle_filter<> filter(60.0);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::filter(filter));
#ifndef CGAL_POLICIES_BOUNDED_NORMAL_ANGLE_FILTER_H
#define CGAL_POLICIES_BOUNDED_NORMAL_ANGLE_FILTER_H

#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/Surface_mesh_simplification/internal/Common.h>

#include <cmath>

namespace cgal_policies {

template <typename BaseFilter = CGAL::Surface_mesh_simplification::internal::Dummy_filter>
class Bounded_normal_angle_filter {
 public:
  explicit Bounded_normal_angle_filter(double max_angle_degrees = 90.0,
                                       const BaseFilter& base_filter = BaseFilter())
      : m_min_cosine(std::cos(max_angle_degrees * M_PI / 180.0)), m_base_filter(base_filter) {}

  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(
      const Profile& profile, internal::Optional<typename Profile::Point> placement) const {
    placement = m_base_filter(profile, placement);
    if (!placement) return placement;
    const Eigen::Vector3d moved = internal::to_eigen(*placement);
    const auto& vpm = profile.vertex_point_map();
    // triangles() lists the edge's own faces (which vanish) first; in the others v1 moves.
    const auto& triangles = profile.triangles();
    std::size_t first = std::size_t(profile.left_face_exists()) + profile.right_face_exists();
    for (std::size_t i = first; i < triangles.size(); ++i) {
      const auto& t = triangles[i];
      const Eigen::Vector3d p = internal::to_eigen(get(vpm, t.v0));
      const Eigen::Vector3d q = internal::to_eigen(get(vpm, t.v1));
      const Eigen::Vector3d r = internal::to_eigen(get(vpm, t.v2));
      const Eigen::Vector3d before = internal::triangle_area_normal(p, q, r);
      const Eigen::Vector3d after = internal::triangle_area_normal(p, moved, r);
      const double lengths = before.norm() * after.norm();
      if (!(lengths > 0) || before.dot(after) <= m_min_cosine * lengths) return {};
    }
    return placement;
  }

 private:
  double m_min_cosine;
  BaseFilter m_base_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_BOUNDED_NORMAL_ANGLE_FILTER_H
