// The matches of one round of the fitting pass, both ways (docs/fitting.md): each input sample's
// nearest output point, found by a walk from the face it was on last round or by a bounding-volume
// hierarchy of the output, and samples of every output face with their nearest input points. Each
// match depends on its sample alone, so the matches are the same on any number of cores.
#ifndef CGAL_POLICIES_INTERNAL_FIT_MATCHING_H
#define CGAL_POLICIES_INTERNAL_FIT_MATCHING_H

#include <cgal_policies/internal/Fit_input.h>
#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Fit_output_tree.h>
#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/surface_samples.h>
#include <cgal_policies/internal/triangle_closest_point.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr std::size_t kFitWalkSteps = 32;
constexpr int kFitOutputLevel = 3;  // samples per output face: its square
// Input samples and output faces matched by one task: enough to outweigh a task's cost.
constexpr std::size_t kFitSamplesPerTask = 2048;
constexpr std::size_t kFitFacesPerTask = 256;

template <typename TriangleMesh>
class Fit_matching {
  using Output_mesh = Fit_output_mesh<TriangleMesh>;

 public:
  // An input sample's nearest output point.
  struct Input_match {
    std::uint32_t face;
    Eigen::Vector3d barycentric;
    double distance;
  };
  // A sample of an output face and its nearest input point, `target`.
  struct Output_match {
    std::uint32_t face;
    Eigen::Vector3d barycentric;
    double weight, distance;
    Eigen::Vector3d target;
  };

  // Matches on up to `threads` cores (0: all of them).
  Fit_matching(std::size_t input_samples, std::size_t output_faces, std::size_t threads)
      : m_threads(threads),
        m_sample_face(input_samples, kFitNoFace),
        m_face_hint(output_faces, Reference_sample::kNoTriangle),
        m_output_sample_hint(output_faces * kFitOutputLevel * kFitOutputLevel,
                             Reference_sample::kNoTriangle) {}

  // Matches both ways as `mesh` is now (its faces refreshed); returns the two directions' mean
  // distances, averaged.
  double match(const Output_mesh& mesh, const Fit_input<TriangleMesh>& input) {
    match_input_samples(mesh, input.samples());
    m_output_matches = match_output_samples(mesh, input);
    double sum = 0;
    for (std::size_t s = 0; s < m_input_matches.size(); ++s)
      sum += input.samples()[s].weight * m_input_matches[s].distance;
    for (const Output_match& o : m_output_matches) sum += o.weight * o.distance;
    return 0.5 * sum;  // each direction's weights sum to 1
  }

  const std::vector<Input_match>& input_matches() const { return m_input_matches; }
  const std::vector<Output_match>& output_matches() const { return m_output_matches; }

  // The output face each input sample was matched to (kFitNoFace before the first match); a flip
  // gives the samples of its two faces to the nearer of the new ones.
  const std::vector<std::uint32_t>& sample_faces() const { return m_sample_face; }
  void set_sample_face(std::uint32_t sample, std::uint32_t face) { m_sample_face[sample] = face; }

  // An input triangle near each output face.
  const std::vector<std::size_t>& face_hints() const { return m_face_hint; }

  // The cores it matches on.
  std::size_t threads() const { return m_threads; }

 private:
  // Each input sample's nearest output point: a walk from last round's face; the tree, built only
  // when a sample needs it, for a sample without a face or whose walk lost its way (its face
  // kFitNoFace between the two sweeps).
  void match_input_samples(const Output_mesh& mesh, const std::vector<Fit_input_sample>& samples) {
    m_input_matches.resize(samples.size());
    for_each_block(samples.size(), kFitSamplesPerTask, m_threads,
                   [&](std::size_t begin, std::size_t end) {
                     for (std::size_t s = begin; s < end; ++s) {
                       std::uint32_t f = m_sample_face[s];
                       if (f == kFitNoFace || !walk_to_nearest(mesh, samples[s].point, f))
                         m_sample_face[s] = kFitNoFace;
                       else
                         settle(mesh, samples[s].point, s, f);
                     }
                   });
    if (std::find(m_sample_face.begin(), m_sample_face.end(), kFitNoFace) == m_sample_face.end())
      return;
    const Fit_output_tree<TriangleMesh> tree(mesh, m_threads);
    for_each_block(samples.size(), kFitSamplesPerTask, m_threads,
                   [&](std::size_t begin, std::size_t end) {
                     // The last answer bounds the next search: consecutive samples are mostly
                     // neighbours.
                     std::uint32_t near = kFitNoFace;
                     for (std::size_t s = begin; s < end; ++s) {
                       if (m_sample_face[s] != kFitNoFace) continue;
                       near = tree.nearest(samples[s].point, near);
                       settle(mesh, samples[s].point, s, near);
                     }
                   });
  }

  // Sample s, at p, matched to its nearest point on face f.
  void settle(const Output_mesh& mesh, const Eigen::Vector3d& p, std::size_t s, std::uint32_t f) {
    m_sample_face[s] = f;
    m_input_matches[s] = closest_match(mesh, p, f);
  }

  // Walks from face f across edges while the distance to p drops; false when it has not stopped
  // within kFitWalkSteps steps (lost its way).
  static bool walk_to_nearest(const Output_mesh& mesh, const Eigen::Vector3d& p, std::uint32_t& f) {
    double d2 = mesh.squared_distance(p, f);
    for (std::size_t step = 0; step < kFitWalkSteps; ++step) {
      const std::uint32_t from = f;
      for (const std::uint32_t g : mesh.neighbours()[from]) {
        if (g == kFitNoFace) continue;
        const double e2 = mesh.squared_distance(p, g);
        if (e2 < d2) {
          d2 = e2;
          f = g;
        }
      }
      if (f == from) return true;
    }
    return false;
  }

  static Input_match closest_match(const Output_mesh& mesh, const Eigen::Vector3d& p,
                                   std::uint32_t f) {
    const Indexed_triangle t = mesh.triangle(f);
    const Eigen::Vector3d b = closest_barycentric(p, t.points[0], t.points[1], t.points[2]);
    return {f, b, (b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2] - p).norm()};
  }

  // Where an output face is sampled, in barycentric coordinates.
  static const std::vector<Eigen::Vector3d>& face_grid() {
    static const std::vector<Eigen::Vector3d> grid = barycentric_grid(kFitOutputLevel);
    return grid;
  }

  // Samples of every output face and their nearest input points.
  std::vector<Output_match> match_output_samples(const Output_mesh& mesh,
                                                 const Fit_input<TriangleMesh>& input) {
    const std::vector<Eigen::Vector3d>& grid = face_grid();
    std::vector<Output_match> matched;
    const double total_area = mesh.area();
    if (!(total_area > 0)) return matched;
    seed_face_hints(input.samples());
    matched.resize(mesh.face_count() * grid.size());
    for_each_block(mesh.face_count(), kFitFacesPerTask, m_threads,
                   [&](std::size_t begin, std::size_t end) {
                     for (std::size_t f = begin; f < end; ++f)
                       match_face_samples(mesh, input, std::uint32_t(f), total_area,
                                          &matched[f * grid.size()]);
                   });
    return matched;
  }

  // The samples of output face f of a mesh of that area and their nearest input points, into
  // `matched`.
  void match_face_samples(const Output_mesh& mesh, const Fit_input<TriangleMesh>& input,
                          std::uint32_t f, double total_area, Output_match* matched) {
    const std::vector<Eigen::Vector3d>& grid = face_grid();
    const Indexed_triangle t = mesh.triangle(f);
    const double w = triangle_area(t) / (total_area * double(grid.size()));
    for (std::size_t g = 0; g < grid.size(); ++g) {
      const Eigen::Vector3d& b = grid[g];
      const Eigen::Vector3d y = b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2];
      // The sample's own match of the last round bounds the search tightly, the vertices having
      // moved little since; in the first round, the previous sample's of the face.
      std::size_t& hint = m_output_sample_hint[f * grid.size() + g];
      const Reference_sample near =
          input.surface().nearest(y, hint != Reference_sample::kNoTriangle ? hint : m_face_hint[f]);
      hint = m_face_hint[f] = near.triangle;
      const Triangle_corners& q = input.surface().corners(near.triangle);
      const Eigen::Vector3d c = closest_barycentric(y, q[0], q[1], q[2]);
      matched[g] = {f, b, w, near.distance, c[0] * q[0] + c[1] * q[1] + c[2] * q[2]};
    }
  }

  // In the first round a face has no input triangle of its own yet: its walks start from the
  // triangle of an input sample matched to it, which lies near the face.
  void seed_face_hints(const std::vector<Fit_input_sample>& samples) {
    for (std::size_t s = 0; s < m_sample_face.size(); ++s) {
      if (m_sample_face[s] == kFitNoFace) continue;
      std::size_t& hint = m_face_hint[m_sample_face[s]];
      if (hint == Reference_sample::kNoTriangle) hint = samples[s].triangle;
    }
  }

  std::size_t m_threads;
  std::vector<std::uint32_t> m_sample_face;
  std::vector<Input_match> m_input_matches;
  std::vector<std::size_t> m_face_hint;
  std::vector<std::size_t> m_output_sample_hint;  // by face, then by sample of the grid
  std::vector<Output_match> m_output_matches;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_MATCHING_H
