// Conservative sampled distance tests from a patch to the reference, and a cheap lower bound the
// other way (docs/hausdorff.md, "New patch to reference", "Ranking the candidates").
#ifndef CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H
#define CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H

#include <cgal_policies/internal/triangle_distance.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace cgal_policies {
namespace internal {

struct Sampled_triangle {
  Triangle_corners corners;
  std::array<Reference_sample, 3> samples;
};

// True when every point of the triangles is provably within `limit` of the reference (the tests:
// docs/hausdorff.md); a triangle that fails is split in four, at most `depth` times and for
// `budget` samples in all. A sample beyond `limit`, or running out, refuses.
template <typename Sample, typename Reference, typename Flat>
bool triangles_within(std::vector<Sampled_triangle> level, double limit, int depth,
                      std::size_t budget, const Sample& sample, const Reference& reference,
                      const Flat& flat) {
  const double limit2 = limit * limit;
  std::vector<Sampled_triangle> next;
  for (int d = 0; !level.empty(); ++d) {
    for (const Sampled_triangle& t : level)
      for (const Reference_sample& s : t.samples)
        if (s.distance > limit) return false;
    next.clear();
    for (const Sampled_triangle& t : level) {
      const Eigen::Vector3d &a = t.corners[0], &b = t.corners[1], &c = t.corners[2];
      const double worst =
          (std::max)({t.samples[0].distance, t.samples[1].distance, t.samples[2].distance});
      if (worst + covering_radius(a, b, c) <= limit) continue;
      bool covered = false;
      for (const Reference_sample& s : t.samples) {
        if (s.triangle == Reference_sample::kNoTriangle) continue;
        const Triangle_corners& r = reference(s.triangle);
        if (squared_distance_to_triangle(a, r) <= limit2 &&
            squared_distance_to_triangle(b, r) <= limit2 &&
            squared_distance_to_triangle(c, r) <= limit2) {
          covered = true;
          break;
        }
      }
      if (covered || flat(t)) continue;
      if (d == depth || budget < 3) return false;
      budget -= 3;
      const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
      const auto& s = t.samples;
      const Reference_sample sab = sample(ab, s[0].triangle), sbc = sample(bc, s[1].triangle),
                             sca = sample(ca, s[2].triangle);
      next.push_back({{a, ab, ca}, {s[0], sab, sca}});
      next.push_back({{ab, b, bc}, {sab, s[1], sbc}});
      next.push_back({{ca, bc, c}, {sca, sbc, s[2]}});
      next.push_back({{ab, bc, ca}, {sab, sbc, sca}});
    }
    level.swap(next);
  }
  return true;
}

// A lower bound of the one-sided Hausdorff distance from the pieces to the patch, on the corners
// of about `budget` pieces evenly spread; returned early once it reaches `stop`.
inline double corner_distance_lower_bound(const std::vector<Triangle_corners>& pieces,
                                          const std::vector<Triangle_corners>& patch, double stop,
                                          std::size_t budget) {
  double worst2 = 0;
  const double stop2 = stop * stop;
  const std::size_t stride = (std::max)(std::size_t(1), pieces.size() / budget);
  for (std::size_t i = 0; i < pieces.size(); i += stride)
    for (const Eigen::Vector3d& corner : pieces[i]) {
      double nearest2 = std::numeric_limits<double>::infinity();
      for (const Triangle_corners& t : patch) {
        nearest2 = (std::min)(nearest2, squared_distance_to_triangle(corner, t));
        if (nearest2 <= worst2) break;
      }
      worst2 = (std::max)(worst2, nearest2);
      if (worst2 >= stop2) return std::sqrt(worst2);
    }
  return std::sqrt(worst2);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H
