// The samples of the input that the fitting pass matches to the output (docs/fitting.md): area-
// weighted points on the input's faces, as many as the output's size asks for.
#ifndef CGAL_POLICIES_INTERNAL_FIT_INPUT_SAMPLES_H
#define CGAL_POLICIES_INTERNAL_FIT_INPUT_SAMPLES_H

#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/surface_samples.h>

#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

namespace cgal_policies {
namespace internal {

// Input samples wanted per output face, up to one per input face (docs/fitting.md).
constexpr std::size_t kFitSamplesPerFace = 16;
constexpr int kFitMaxInputLevel = 6;

// A point of the input, weighted by the area it stands for (the weights sum to 1).
struct Fit_input_sample {
  Eigen::Vector3d point;
  double weight;
  std::uint32_t triangle;  // the input triangle it lies on (its index in Hausdorff_input_surface)
};

// The faces of a mesh that are there: num_faces() also counts the removed faces of a
// CGAL::Surface_mesh until its garbage is collected.
template <typename FaceGraph>
std::size_t live_face_count(const FaceGraph& g) {
  return std::size_t(std::distance(faces(g).begin(), faces(g).end()));
}

// About max(min_input_samples, min(input faces, kFitSamplesPerFace * output faces)) samples: a
// grid on every input triangle when there are fewer triangles, else the centroids of every k-th
// triangle, weighted by k. None when the input has no area.
inline std::vector<Fit_input_sample> sample_fit_input(const Hausdorff_input_surface& input,
                                                      std::size_t output_faces,
                                                      std::size_t min_input_samples) {
  std::vector<Fit_input_sample> samples;
  const std::size_t face_count = input.size();
  const std::size_t wanted =
      (std::max)(min_input_samples, (std::min)(face_count, kFitSamplesPerFace * output_faces));
  int level = 1;
  while (level < kFitMaxInputLevel && face_count * std::size_t(level * level) < wanted) ++level;
  const std::size_t stride = (std::max)(std::size_t(1), face_count / wanted);
  const std::vector<Eigen::Vector3d> grid = barycentric_grid(level);
  double total = 0;
  for (std::uint32_t triangle = 0; triangle < face_count; triangle += std::uint32_t(stride)) {
    const Triangle_corners& t = input.corners(triangle);
    const double area = 0.5 * triangle_area_normal(t[0], t[1], t[2]).norm();
    for (const Eigen::Vector3d& b : grid)
      samples.push_back(
          {b[0] * t[0] + b[1] * t[1] + b[2] * t[2], area / double(grid.size()), triangle});
    total += area;
  }
  if (!(total > 0)) samples.clear();
  for (Fit_input_sample& s : samples) s.weight /= total;
  return samples;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_INPUT_SAMPLES_H
