// The input side of the fitting pass (docs/fitting.md): the input's triangles for nearest-point
// queries, its border curve and its samples, built by Two_sided_fitter and read by every pass;
// from an input mesh, or from the triangles of a cell of one (a fit by cells).
#ifndef CGAL_POLICIES_INTERNAL_FIT_INPUT_H
#define CGAL_POLICIES_INTERNAL_FIT_INPUT_H

#include <cgal_policies/internal/Border_curve.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/fit_input_samples.h>

#include <CGAL/boost/graph/properties.h>

#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Fit_input {
 public:
  // `input` must outlive this. Its hierarchy is built on up to `threads` cores.
  // A tolerance of 0: every nearest point is the tree's, seeded by a walk (exact distances; a walk
  // alone may stop at a local minimum).
  Fit_input(const TriangleMesh& input, std::size_t threads)
      : m_mesh(&input),
        m_border(input, get(CGAL::vertex_point, input)),
        m_surface(input, get(CGAL::vertex_point, input), 0.0, true, threads) {}

  // Without a mesh: no bounded fit (which certifies against the mesh).
  Fit_input(Input_triangles triangles, std::size_t threads)
      : m_mesh(nullptr), m_border(triangles), m_surface(std::move(triangles), 0.0, threads) {}

  // Samples the input anew for an output of `output_faces` faces (sample_fit_input()).
  void resample(std::size_t output_faces, std::size_t min_input_samples) {
    m_samples = sample_fit_input(m_surface, output_faces, min_input_samples);
  }

  // The input mesh; null for triangles.
  const TriangleMesh* mesh() const { return m_mesh; }
  const Hausdorff_input_surface& surface() const { return m_surface; }
  const Border_curve& border() const { return m_border; }
  const std::vector<Fit_input_sample>& samples() const { return m_samples; }

 private:
  const TriangleMesh* m_mesh;
  Border_curve m_border;
  Hausdorff_input_surface m_surface;
  std::vector<Fit_input_sample> m_samples;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_INPUT_H
