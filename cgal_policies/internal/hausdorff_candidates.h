// Where a Hausdorff-bounded collapse may put the merged vertex (docs/hausdorff.md): the border
// rule, and the candidates probed at a constant step along the edge.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_CANDIDATES_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_CANDIDATES_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <vector>

namespace cgal_policies {
namespace internal {

enum class Border_case {
  free,        // no border vertex: anywhere
  keep_v0,     // v0 is on the border, v1 is not: the merged vertex stays at p0
  keep_v1,     // the other way round
  along_edge,  // a border edge: the merged vertex slides along it
  refused      // two border vertices not joined by a border edge, or locked borders
};

template <typename Profile>
Border_case border_case(const Profile& profile, Border_rule rule) {
  const auto& tm = profile.surface_mesh();
  const bool b0 = bool(CGAL::is_border(profile.v0(), tm));
  const bool b1 = bool(CGAL::is_border(profile.v1(), tm));
  if (b0 && b1) {
    const bool border_edge = profile.is_v0_v1_a_border() || profile.is_v1_v0_a_border();
    return rule == Border_rule::slide && border_edge ? Border_case::along_edge
                                                     : Border_case::refused;
  }
  if (b0) return Border_case::keep_v0;
  if (b1) return Border_case::keep_v1;
  return Border_case::free;
}

template <typename Profile>
Optional<Eigen::Vector3d> restrict_to_border_case(const Profile& profile, Border_case c,
                                                  const Eigen::Vector3d& preferred) {
  const Eigen::Vector3d p0 = to_eigen(profile.p0()), p1 = to_eigen(profile.p1());
  switch (c) {
    case Border_case::free:
      return preferred;
    case Border_case::keep_v0:
      return p0;
    case Border_case::keep_v1:
      return p1;
    case Border_case::along_edge: {
      const Eigen::Vector3d d = p1 - p0;
      const double length2 = d.squaredNorm();
      const double t = length2 > 0 ? std::clamp((preferred - p0).dot(d) / length2, 0.0, 1.0) : 0.0;
      return Eigen::Vector3d(p0 + t * d);
    }
    case Border_case::refused:
      break;
  }
  return {};
}

// The restricted preferred point, then K + 1 points along the edge where the border case allows.
template <typename Profile>
std::vector<Eigen::Vector3d> collapse_candidates(const Profile& profile, Border_case c,
                                                 const Eigen::Vector3d& preferred, int steps) {
  std::vector<Eigen::Vector3d> candidates;
  const Optional<Eigen::Vector3d> first = restrict_to_border_case(profile, c, preferred);
  if (!first) return candidates;
  candidates.push_back(*first);
  if (c != Border_case::free && c != Border_case::along_edge) return candidates;
  const Eigen::Vector3d p0 = to_eigen(profile.p0()), p1 = to_eigen(profile.p1());
  for (int i = 0; i <= steps; ++i) candidates.push_back(p0 + (double(i) / steps) * (p1 - p0));
  return candidates;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_CANDIDATES_H
