// The state of one fit of one output mesh by Two_sided_fitter (docs/fitting.md), and the steps
// its fit() calls: match, begin a round, fit it, flip edges, undo it.
#ifndef CGAL_POLICIES_INTERNAL_TWO_SIDED_FIT_PASS_H
#define CGAL_POLICIES_INTERNAL_TWO_SIDED_FIT_PASS_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/Two_sided_fit_options.h>
#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/internal/Fit_flip_round.h>
#include <cgal_policies/internal/Fit_guard.h>
#include <cgal_policies/internal/Fit_input.h>
#include <cgal_policies/internal/Fit_least_squares.h>
#include <cgal_policies/internal/Fit_matching.h>
#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Fit_vertex_mover.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr int kFitUndoneRounds = 2;  // undone rounds in a row that end the pass

template <typename TriangleMesh>
class Two_sided_fit_pass {
  using Output_mesh = Fit_output_mesh<TriangleMesh>;
  using vertex_descriptor = typename Output_mesh::vertex_descriptor;
  using halfedge_descriptor = typename Output_mesh::halfedge_descriptor;
  using Bounded_state = Hausdorff_bounded_state<TriangleMesh>;

 public:
  // `input` must be sampled; `pinned`, when given, names the vertices that do not move.
  Two_sided_fit_pass(TriangleMesh& tm, const Fit_input<TriangleMesh>& input,
                     const Two_sided_fit_options& options,
                     const std::function<bool(vertex_descriptor)>& pinned)
      : m_input(&input),
        m_options(options),
        m_mesh(tm),
        m_mover(m_mesh, input.border(), input.surface().diagonal(), pinned, options.trust_fraction),
        m_matching(input.samples().size(), m_mesh.face_count(), options.threads) {
    if (m_options.tolerance > 0) {
      CGAL_precondition(input.mesh() != nullptr);
      m_bounded =
          std::make_unique<Bounded_state>(*input.mesh(), get(CGAL::vertex_point, *input.mesh()), tm,
                                          m_options.tolerance, Hausdorff_bounded_options());
    }
    m_mesh.refresh_faces();
    start_guards();
  }

  // Matches both ways as the mesh is now; returns the two directions' mean distances, averaged.
  double match() {
    m_mesh.refresh_faces();
    return m_matching.match(m_mesh, *m_input);
  }

  // Keeps what a round may have to undo: the points, and the flips it makes.
  void begin_round() {
    m_round_start = m_mesh.points();
    m_round_flips.clear();
  }

  // Solves for the points the last matches ask for and moves toward them; `scale` is the mean
  // distance match() returned, `reach` scales the trust region. False when the system could not
  // be solved.
  bool fit_round(Two_sided_fit_report& report, double scale, double reach) {
    Fit_least_squares system(m_mesh.corners(), m_mesh.points(), m_options, scale);
    add_matches(system);
    const std::optional<Eigen::VectorXd> solved = system.solve();
    if (!solved) return false;
    m_mover.move_vertices(m_mesh, *m_guard, m_bounded.get(), *solved, reach, report);
    return true;
  }

  // After fit_round: the faces are those match() refreshed, only their corners moved.
  void flip_round(Two_sided_fit_report& report) {
    Fit_flip_round<TriangleMesh>(m_mesh, *m_guard, m_bounded.get(), m_matching, *m_input,
                                 m_options.target_mean, m_round_flips)
        .run(report);
  }

  // Back to where the round began; the guard, and the bound's attachment, start from there.
  void undo_round() {
    for (auto it = m_round_flips.rbegin(); it != m_round_flips.rend(); ++it)
      CGAL::Euler::flip_edge(*it, m_mesh.mesh());
    m_mesh.set_points(m_round_start);
    m_mesh.refresh_faces();
    start_guards();
  }

 private:
  // The last matches, input samples first, then output samples.
  void add_matches(Fit_least_squares& system) const {
    const std::vector<Fit_input_sample>& samples = m_input->samples();
    const auto& input_matches = m_matching.input_matches();
    for (std::size_t s = 0; s < input_matches.size(); ++s) {
      const auto& m = input_matches[s];
      system.add(m.face, m.barycentric, samples[s].weight, m.distance, samples[s].point);
    }
    for (const auto& o : m_matching.output_matches())
      system.add(o.face, o.barycentric, o.weight, o.distance, o.target);
  }

  // The guard, and in bounded mode the input's pieces, tied to the mesh as it is now.
  void start_guards() {
    std::vector<Indexed_triangle> triangles;
    double edge_sum = 0;
    for (std::uint32_t f = 0; f < m_mesh.face_count(); ++f) {
      triangles.push_back(m_mesh.triangle(f));
      for (int k = 0; k < 3; ++k)
        edge_sum += (triangles.back().points[(k + 1) % 3] - triangles.back().points[k]).norm();
    }
    const double mean_edge = edge_sum / (3.0 * double(m_mesh.face_count()));
    m_guard.emplace(std::move(triangles), m_options.max_normal_angle_deg,
                    mean_edge > 0 ? 2 * mean_edge : 1.0);
    if (m_bounded) m_bounded->attach_to_approximation(m_mesh.mesh(), m_mesh.vertex_point_map());
  }

  const Fit_input<TriangleMesh>* m_input;
  Two_sided_fit_options m_options;
  Output_mesh m_mesh;
  Fit_vertex_mover<TriangleMesh> m_mover;
  Fit_matching<TriangleMesh> m_matching;
  std::optional<Fit_guard> m_guard;
  std::unique_ptr<Bounded_state> m_bounded;
  std::vector<Eigen::Vector3d> m_round_start;
  std::vector<halfedge_descriptor> m_round_flips;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TWO_SIDED_FIT_PASS_H
