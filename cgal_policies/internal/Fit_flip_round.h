// The flip round of the fitting pass (docs/fitting.md): each interior edge is flipped when its two
// faces' two-sided error drops, the combinatorics stay manifold, Fit_guard allows the new faces
// and, in bounded mode, they are certified within the tolerance.
#ifndef CGAL_POLICIES_INTERNAL_FIT_FLIP_ROUND_H
#define CGAL_POLICIES_INTERNAL_FIT_FLIP_ROUND_H

#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/internal/Fit_guard.h>
#include <cgal_policies/internal/Fit_input.h>
#include <cgal_policies/internal/Fit_matching.h>
#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>
#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/surface_samples.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr int kFitFlipLevel = 2;  // samples per output face when a flip is weighed: its square

template <typename TriangleMesh>
class Fit_flip_round {
  using Output_mesh = Fit_output_mesh<TriangleMesh>;
  using vertex_descriptor = typename Output_mesh::vertex_descriptor;
  using halfedge_descriptor = typename Output_mesh::halfedge_descriptor;
  using Bounded_state = Hausdorff_bounded_state<TriangleMesh>;
  using Pair = std::array<Indexed_triangle, 2>;

  // An edge's two faces and the two triangles a flip would make of them.
  struct Flip {
    std::uint32_t f0, f1;
    Pair before, after;
  };

 public:
  // The flips it makes are added to `flips`, so that the round can be undone.
  Fit_flip_round(Output_mesh& mesh, Fit_guard& guard, Bounded_state* bounded,
                 Fit_matching<TriangleMesh>& matching, const Fit_input<TriangleMesh>& input,
                 bool target_mean, std::vector<halfedge_descriptor>& flips)
      : m_mesh(&mesh),
        m_guard(&guard),
        m_bounded(bounded),
        m_matching(&matching),
        m_input(&input),
        m_target_mean(target_mean),
        m_flips(&flips) {}

  // After a fit round: the faces are those the last match refreshed, only their corners moved.
  void run(Two_sided_fit_report& report) {
    bucket_samples();
    m_output_area = m_mesh->area();
    if (!(m_output_area > 0)) return;
    m_output_error.resize(m_mesh->face_count());
    // Each face's own error, on the matching's cores; the flips then go one after the other.
    for_each_in_blocks(
        m_mesh->face_count(), kFitFacesPerTask, m_matching->threads(), [&](std::size_t f) {
          m_output_error[f] =
              output_error(m_mesh->triangle(std::uint32_t(f)), m_matching->face_hints()[f]);
        });
    std::vector<halfedge_descriptor> candidates;
    for (auto e : edges(m_mesh->mesh()))
      if (!CGAL::is_border(e, m_mesh->mesh())) candidates.push_back(halfedge(e, m_mesh->mesh()));
    for (halfedge_descriptor h : candidates) try_flip(h, report);
  }

 private:
  void bucket_samples() {
    const std::vector<std::uint32_t>& sample_faces = m_matching->sample_faces();
    m_face_samples.assign(m_mesh->face_count(), {});
    for (std::uint32_t s = 0; s < sample_faces.size(); ++s)
      if (sample_faces[s] != kFitNoFace) m_face_samples[sample_faces[s]].push_back(s);
  }

  void try_flip(halfedge_descriptor h, Two_sided_fit_report& report) {
    const std::optional<Flip> flip = flip_of(h);
    if (!flip) return;
    std::array<double, 2> output_after;
    if (!lowers_error(*flip, output_after)) return;
    const Eigen::Vector3d reference =
        unit_or_zero(m_guard->reference(flip->f0) + m_guard->reference(flip->f1));
    const std::vector<Eigen::Vector3d> references = {reference, reference};
    const std::vector<std::uint32_t> changed = {flip->f0, flip->f1};
    if (!m_guard->allows(changed, {flip->after[0], flip->after[1]}, references) ||
        !flip_within_tolerance(h, *flip)) {
      ++report.refused_flips;
      return;
    }
    ++report.flips;
    for (const std::uint32_t f : changed) m_mesh->refresh_corners(f);
    m_guard->apply(changed, {m_mesh->triangle(flip->f0), m_mesh->triangle(flip->f1)}, references);
    // Euler::flip_edge decides which face becomes which triangle: the one with a is after[0].
    const Fit_face_corners& corners0 = m_mesh->corners()[flip->f0];
    const bool f0_has_a =
        std::find(corners0.begin(), corners0.end(), flip->after[0].vertices[0]) != corners0.end();
    m_output_error[flip->f0] = f0_has_a ? output_after[0] : output_after[1];
    m_output_error[flip->f1] = f0_has_a ? output_after[1] : output_after[0];
    rebucket_samples(flip->f0, flip->f1);
  }

  // The edge (a, b) of h flipped to (c, d), unless that makes an edge twice, a vertex of degree
  // < 4 one of degree < 3, or joins a vertex to itself.
  std::optional<Flip> flip_of(halfedge_descriptor h) const {
    const TriangleMesh& tm = m_mesh->mesh();
    const vertex_descriptor a = source(h, tm), b = target(h, tm);
    const vertex_descriptor c = target(next(h, tm), tm);
    const vertex_descriptor d = target(next(opposite(h, tm), tm), tm);
    if (c == d || halfedge(c, d, tm).second || degree(a, tm) < 4 || degree(b, tm) < 4)
      return std::nullopt;
    return Flip{m_mesh->face_index(face(h, tm)),
                m_mesh->face_index(face(opposite(h, tm), tm)),
                {m_mesh->triangle(a, b, c), m_mesh->triangle(b, a, d)},
                {m_mesh->triangle(a, d, c), m_mesh->triangle(d, b, c)}};
  }

  // Whether the flip lowers the pair's error strictly, beyond rounding: a flip of a flat quad
  // changes nothing. Each new face's error stops early once the flip cannot pay off; when it
  // does, `output_after` holds them.
  bool lowers_error(const Flip& flip, std::array<double, 2>& output_after) const {
    const double rounding = penalty(CGAL::square(1e-9 * m_input->surface().diagonal()));
    const double budget = (1 - 1e-9) * (pair_input_error(flip.f0, flip.f1, flip.before) +
                                        m_output_error[flip.f0] + m_output_error[flip.f1]) -
                          rounding;
    const std::vector<std::size_t>& hints = m_matching->face_hints();
    const double input_after = pair_input_error(flip.f0, flip.f1, flip.after);
    if (!(input_after < budget)) return false;
    output_after[0] = output_error(flip.after[0], hints[flip.f0], budget - input_after);
    if (!(input_after + output_after[0] < budget)) return false;
    output_after[1] =
        output_error(flip.after[1], hints[flip.f1], budget - input_after - output_after[0]);
    return input_after + output_after[0] + output_after[1] < budget;
  }

  // Flips h (it then joins c and d) and keeps the flip when the bound, if any, certifies the new
  // faces; false, the edge as it was, otherwise.
  bool flip_within_tolerance(halfedge_descriptor h, const Flip& flip) {
    TriangleMesh& tm = m_mesh->mesh();
    CGAL::Euler::flip_edge(h, tm);
    m_flips->push_back(h);
    if (m_bounded &&
        !m_bounded->try_reshape(tm, m_mesh->vertex_point_map(),
                                {m_mesh->face_at(flip.f0), m_mesh->face_at(flip.f1)})) {
      CGAL::Euler::flip_edge(h, tm);
      m_flips->pop_back();
      return false;
    }
    return true;
  }

  // The input samples of the pair go to the nearer of its new faces.
  void rebucket_samples(std::uint32_t f0, std::uint32_t f1) {
    std::vector<std::uint32_t> pooled = m_face_samples[f0];
    pooled.insert(pooled.end(), m_face_samples[f1].begin(), m_face_samples[f1].end());
    m_face_samples[f0].clear();
    m_face_samples[f1].clear();
    for (const std::uint32_t s : pooled) {
      const Eigen::Vector3d& p = m_input->samples()[s].point;
      const std::uint32_t f =
          m_mesh->squared_distance(p, f0) <= m_mesh->squared_distance(p, f1) ? f0 : f1;
      m_matching->set_sample_face(s, f);
      m_face_samples[f].push_back(s);
    }
  }

  // The error of a pair of triangles replacing faces f0 and f1 seen from the input: its samples
  // matched to those faces, distances squared (or not, aiming at the mean).
  double pair_input_error(std::uint32_t f0, std::uint32_t f1, const Pair& pair) const {
    const std::vector<Fit_input_sample>& samples = m_input->samples();
    double error = 0;
    for (const std::uint32_t f : {f0, f1})
      for (const std::uint32_t s : m_face_samples[f]) {
        const Eigen::Vector3d& p = samples[s].point;
        double d2 = std::numeric_limits<double>::infinity();
        for (const Indexed_triangle& t : pair)
          d2 = (std::min)(d2,
                          squared_distance_to_triangle(p, t.points[0], t.points[1], t.points[2]));
        error += samples[s].weight * penalty(d2);
      }
    return error;
  }

  // The error of a triangle seen from itself: its samples and their nearest input points. It
  // stops once the sum passes `budget`, so a flip that cannot pay off is dropped early.
  double output_error(const Indexed_triangle& t, std::size_t hint,
                      double budget = std::numeric_limits<double>::infinity()) const {
    static const std::vector<Eigen::Vector3d> grid = barycentric_grid(kFitFlipLevel);
    const double w = triangle_area(t) / (m_output_area * double(grid.size()));
    double error = 0;
    for (const Eigen::Vector3d& b : grid) {
      const Reference_sample near = m_input->surface().nearest(
          b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2], hint);
      hint = near.triangle;
      error += w * penalty(near.distance * near.distance);
      if (error > budget) break;
    }
    return error;
  }

  double penalty(double squared_distance) const {
    return m_target_mean ? std::sqrt(squared_distance) : squared_distance;
  }

  Output_mesh* m_mesh;
  Fit_guard* m_guard;
  Bounded_state* m_bounded;
  Fit_matching<TriangleMesh>* m_matching;
  const Fit_input<TriangleMesh>* m_input;
  bool m_target_mean;
  std::vector<halfedge_descriptor>* m_flips;
  std::vector<std::vector<std::uint32_t>> m_face_samples;  // the input samples of each face
  double m_output_area = 0;
  std::vector<double> m_output_error;  // each face's output_error()
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_FLIP_ROUND_H
