// Two_sided_fitter: fits a simplified mesh to the input it came from, its connectivity fixed but
// for edge flips, after Hoppe et al.'s mesh optimization [Hoppe93] (the distance energy solved as a
// sparse linear least-squares problem, then edge swaps), with the distance measured both ways
// (docs/fitting.md). Each round matches samples of the input to their nearest output points (a walk
// from the face they were on last round; a bounding-volume hierarchy of the output at first and
// when a walk loses its way) and samples of the output to their nearest input points (a hierarchy
// of the input, built once), then solves for every vertex at once (Eigen's sparse Cholesky), each
// match measured as the distance to its tangent plane, so vertices slide along the surface.
// Reweighting by the distances aims the fit at the mean (L1) distance. A vertex moves at most a
// fraction of its mean edge length per round; a flip round then flips each interior edge whose two
// faces' two-sided error drops, never making an edge twice, a vertex of degree < 4 one of
// degree < 3, or a fold.
// Guarantees: no face normal turns by more than max_normal_angle_deg from its direction before the
// pass (a flipped edge's faces: from their old normals' mean), no face becomes degenerate, no
// moved or flipped face crosses another face (exact predicates; intersections the mesh had before
// stay, no new ones appear), border vertices stay border vertices and slide along the input's
// border curve (one the simplification left off the curve never moves farther from it), the
// combinatorics stay manifold. With a tolerance (bounded mode), every move and every flip is
// certified against the input in both directions as Hausdorff_bounded_policies certifies collapses:
// an output within the tolerance stays within it.
// Parameters (Two_sided_fit_options):
//   rounds                fit rounds, >= 0 (default 4)
//   flips                 a flip round after each fit round (default true)
//   trust_fraction        largest move per round, a fraction of the mean edge length around the
//                         vertex, > 0 (default 0.3)
//   tangent_weight        in [0, 1], how much a match's distance across its direction counts: 1 is
//                         the plain distance to the matched point (default 0.001)
//   target_mean           reweight toward the mean distance rather than the RMS (default false)
//   max_normal_angle_deg  in [0, 180], as --max-normal-angle takes it; 0: no face normal may turn
//                         (default 90)
//   min_input_samples     the input is sampled at least this densely, >= 1 (default 100000)
//   tolerance             >= 0, a fraction of the input's bounding-box diagonal; 0: unbounded
//   threads               cores that index the input and match the samples, 0: all of them
//                         (default 1); the fit is the same for every count
// The input must outlive the fitter; output and input are triangle meshes of the same type, their
// points read through their vertex_point maps. Deterministic: the same meshes give the same bytes.
// fit() may be told which vertices must stay where they are (a mesh's texture seams, say;
// docs/fitting.md, "Texture coordinates, normals and colours").
// Usage:
//   cgal_policies::Two_sided_fitter<Mesh> fitter(input);
//   const cgal_policies::Two_sided_fit_report report = fitter.fit(simplified);
#ifndef CGAL_POLICIES_TWO_SIDED_FITTER_H
#define CGAL_POLICIES_TWO_SIDED_FITTER_H

#include <cgal_policies/Two_sided_fit_options.h>
#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/internal/Fit_input.h>
#include <cgal_policies/internal/Two_sided_fit_pass.h>
#include <cgal_policies/internal/fit_input_samples.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>

#include <functional>
#include <utility>

namespace cgal_policies {

template <typename TriangleMesh>
class Two_sided_fitter {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

 public:
  explicit Two_sided_fitter(const TriangleMesh& input,
                            const Two_sided_fit_options& options = Two_sided_fit_options())
      : m_options(options), m_input(input, options.threads) {
    check_options();
  }

  // The input given by its triangles (a cell of a larger input: the fit by cells); unbounded.
  explicit Two_sided_fitter(internal::Input_triangles input,
                            const Two_sided_fit_options& options = Two_sided_fit_options())
      : m_options(options), m_input(std::move(input), options.threads) {
    CGAL_precondition(options.tolerance == 0);
    check_options();
  }

  // `pinned`, when given, names the vertices that do not move.
  Two_sided_fit_report fit(TriangleMesh& output,
                           const std::function<bool(vertex_descriptor)>& pinned = {}) {
    Two_sided_fit_report report;
    if (faces(output).empty()) return report;
    // Sample the input, as densely as the output's size asks (internal/fit_input_samples.h).
    m_input.resample(internal::live_face_count(output), m_options.min_input_samples);
    if (m_input.samples().empty()) return report;
    // Start the pass: number the output, tie the guards to it (internal/Two_sided_fit_pass.h).
    internal::Two_sided_fit_pass<TriangleMesh> pass(output, m_input, m_options, pinned);
    // Match the samples both ways as the output is now.
    double error = pass.match();
    // Each round must lower the two-sided mean distance of the samples. One that does not is
    // undone, and the next round moves at most half as far; the second undone round in a row ends
    // the pass.
    double reach = 1;
    int undone_in_a_row = 0;
    for (int round = 0; round < m_options.rounds; ++round) {
      Two_sided_fit_report step;
      // Keep what the round may have to undo.
      pass.begin_round();
      // Solve for every vertex at once, then move each within the guards.
      if (!pass.fit_round(step, error, reach)) break;
      // Flip the edges whose two faces' error drops.
      if (m_options.flips) pass.flip_round(step);
      // Match again; accept the round, or undo it.
      const double now = pass.match();
      if (!(now < error)) {
        pass.undo_round();
        if (++undone_in_a_row == internal::kFitUndoneRounds) break;
        reach *= 0.5;
        error = pass.match();
        continue;
      }
      undone_in_a_row = 0;
      error = now;
      ++report.rounds;
      report.moves += step.moves;
      report.refused_moves += step.refused_moves;
      report.flips += step.flips;
      report.refused_flips += step.refused_flips;
    }
    return report;
  }

 private:
  void check_options() const {
    CGAL_precondition(m_options.rounds >= 0);
    CGAL_precondition(m_options.trust_fraction > 0);
    CGAL_precondition(m_options.tangent_weight >= 0 && m_options.tangent_weight <= 1);
    CGAL_precondition(m_options.max_normal_angle_deg >= 0 && m_options.max_normal_angle_deg <= 180);
    CGAL_precondition(m_options.tolerance >= 0);
    CGAL_precondition(m_options.min_input_samples >= 1);
  }

  Two_sided_fit_options m_options;
  internal::Fit_input<TriangleMesh> m_input;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_TWO_SIDED_FITTER_H
