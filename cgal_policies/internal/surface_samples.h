// Area-weighted samples of a triangle mesh on a regular barycentric grid, the fitting pass's
// correspondences in both directions (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_SURFACE_SAMPLES_H
#define CGAL_POLICIES_INTERNAL_SURFACE_SAMPLES_H

#include <Eigen/Core>

#include <vector>

namespace cgal_policies {
namespace internal {

// The centroids of the level * level triangles of a triangle cut into `level` parts per edge.
inline std::vector<Eigen::Vector3d> barycentric_grid(int level) {
  std::vector<Eigen::Vector3d> grid;
  const double l = 3.0 * level;
  for (int i = 0; i < level; ++i)
    for (int j = 0; i + j < level; ++j) {
      const int k = level - 1 - i - j;
      grid.emplace_back((3 * i + 1) / l, (3 * j + 1) / l, (3 * k + 1) / l);
      if (k > 0) grid.emplace_back((3 * i + 2) / l, (3 * j + 2) / l, (3 * k - 1) / l);
    }
  return grid;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_SURFACE_SAMPLES_H
