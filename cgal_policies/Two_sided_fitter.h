// Two_sided_fitter: fits a simplified mesh to the input it came from, its connectivity fixed but
// for edge flips, after Hoppe et al.'s mesh optimization [Hoppe93] (the distance energy solved as a
// sparse linear least-squares problem, then edge swaps), with the distance measured both ways
// (docs/fitting.md). Each round matches samples of the input to their nearest output points (a
// walk from the face they were on last round; an AABB tree of the output at first and when a walk
// loses its way) and samples of the output to their nearest input points (an AABB tree of the
// input, built once), then solves for every vertex at once (Eigen's sparse Cholesky), each match
// measured as the distance to its tangent plane, so vertices slide along the surface. Reweighting
// by the distances aims the fit at the mean (L1) distance. A vertex moves at most a fraction of its
// mean edge length per round; a flip round then flips each interior edge whose two faces' two-sided
// error drops, never making an edge twice, a vertex of degree < 4 one of degree < 3, or a fold.
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
// The input must outlive the fitter; output and input are triangle meshes of the same type, their
// points read through their vertex_point maps. Deterministic: the same meshes give the same bytes.
// fit() may be told which vertices must stay where they are (a mesh's texture seams, say;
// docs/fitting.md, "Texture coordinates, normals and colours").
// Usage:
//   cgal_policies::Two_sided_fitter<Mesh> fitter(input);
//   const cgal_policies::Two_sided_fit_report report = fitter.fit(simplified);
#ifndef CGAL_POLICIES_TWO_SIDED_FITTER_H
#define CGAL_POLICIES_TWO_SIDED_FITTER_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/Two_sided_fit_options.h>
#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/internal/Border_curve.h>
#include <cgal_policies/internal/Fit_guard.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/surface_samples.h>
#include <cgal_policies/internal/triangle_closest_point.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace cgal_policies {

namespace internal {
// Input samples wanted per output face, up to one per input face (docs/fitting.md).
constexpr std::size_t kFitSamplesPerFace = 32;
constexpr int kFitMaxInputLevel = 6;
constexpr int kFitOutputLevel = 3;  // samples per output face: its square
constexpr int kFitFlipLevel = 2;    // the same when a flip is weighed

constexpr std::size_t kFitWalkSteps = 32;
constexpr int kFitUndoneRounds = 2;  // undone rounds in a row that end the pass
constexpr std::uint32_t kFitNoFace = 0xffffffffu;
}  // namespace internal

template <typename TriangleMesh>
class Two_sided_fitter {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using Vertex_point_map = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<Vertex_point_map>::value_type;
  using Input_surface = internal::Hausdorff_input_surface;
  using Bounded_state = internal::Hausdorff_bounded_state<TriangleMesh>;
  using Vector3 = Eigen::Vector3d;
  using Face_corners = std::array<std::uint32_t, 3>;

 public:
  explicit Two_sided_fitter(const TriangleMesh& input,
                            const Two_sided_fit_options& options = Two_sided_fit_options())
      : m_input_mesh(&input),
        m_options(options),
        // A tolerance of 0: every nearest point is the tree's, seeded by a walk (exact distances;
        // a walk alone may stop at a local minimum).
        m_input(input, get(CGAL::vertex_point, input), 0.0, true),
        m_border(input, get(CGAL::vertex_point, input)) {
    CGAL_precondition(options.rounds >= 0);
    CGAL_precondition(options.trust_fraction > 0);
    CGAL_precondition(options.tangent_weight >= 0 && options.tangent_weight <= 1);
    CGAL_precondition(options.max_normal_angle_deg >= 0 && options.max_normal_angle_deg <= 180);
    CGAL_precondition(options.tolerance >= 0);
    CGAL_precondition(options.min_input_samples >= 1);
  }

  // `pinned`, when given, names the vertices that do not move.
  Two_sided_fit_report fit(TriangleMesh& output,
                           const std::function<bool(vertex_descriptor)>& pinned = {}) {
    Two_sided_fit_report report;
    if (faces(output).empty()) return report;
    sample_input(num_faces(output));
    if (m_samples.empty()) return report;
    Pass pass(output, *this, pinned);
    // Each round must lower the two-sided mean distance of the samples. One that does not is
    // undone, and the next round moves at most half as far; the second undone round in a row ends
    // the pass.
    double error = pass.match();
    double reach = 1;
    int undone_in_a_row = 0;
    for (int round = 0; round < m_options.rounds; ++round) {
      Two_sided_fit_report step;
      pass.begin_round();
      if (!pass.fit_round(step, error, reach)) break;
      if (m_options.flips) pass.flip_round(step);
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
  // A point of the input, weighted by the area it stands for (the weights sum to 1).
  struct Input_sample {
    Vector3 point;
    double weight;
    std::uint32_t triangle;  // the input triangle it lies on (its index in m_input)
  };

  // About max(min_input_samples, min(input faces, kFitSamplesPerFace * output faces)) samples: a
  // grid on every input face when there are fewer faces, else the centroids of every k-th face,
  // weighted by k.
  void sample_input(std::size_t output_faces) {
    m_samples.clear();
    const auto vpm = get(CGAL::vertex_point, *m_input_mesh);
    const std::size_t face_count = num_faces(*m_input_mesh);
    const std::size_t wanted =
        (std::max)(m_options.min_input_samples,
                   (std::min)(face_count, internal::kFitSamplesPerFace * output_faces));
    int level = 1;
    while (level < internal::kFitMaxInputLevel && face_count * std::size_t(level * level) < wanted)
      ++level;
    const std::size_t stride = (std::max)(std::size_t(1), face_count / wanted);
    const std::vector<Vector3> grid = internal::barycentric_grid(level);
    double total = 0;
    std::uint32_t index = 0;
    for (face_descriptor f : faces(*m_input_mesh)) {
      const std::uint32_t triangle = index++;
      if (triangle % stride != 0) continue;
      const internal::Triangle_corners t = internal::face_corners(f, *m_input_mesh, vpm);
      const double area = 0.5 * internal::triangle_area_normal(t[0], t[1], t[2]).norm();
      for (const Vector3& b : grid)
        m_samples.push_back(
            {b[0] * t[0] + b[1] * t[1] + b[2] * t[2], area / double(grid.size()), triangle});
      total += area;
    }
    if (!(total > 0)) m_samples.clear();
    for (Input_sample& s : m_samples) s.weight /= total;
  }

  // The state of one fit of one output mesh.
  class Pass {
   public:
    Pass(TriangleMesh& tm, Two_sided_fitter& fitter,
         const std::function<bool(vertex_descriptor)>& pinned)
        : m_tm(&tm),
          m_vpm(get(CGAL::vertex_point, tm)),
          m_fitter(&fitter),
          m_options(fitter.m_options),
          m_vertex_index(get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm)),
          m_face_index(get(CGAL::dynamic_face_property_t<std::uint32_t>(), tm)) {
      for (vertex_descriptor v : vertices(tm)) {
        put(m_vertex_index, v, std::uint32_t(m_vertices.size()));
        m_vertices.push_back(v);
        m_pinned.push_back(pinned && pinned(v));
        m_points.push_back(internal::to_eigen(get(m_vpm, v)));
      }
      for (face_descriptor f : faces(tm)) {
        put(m_face_index, f, std::uint32_t(m_faces.size()));
        m_faces.push_back(f);
      }
      m_sample_face.assign(fitter.m_samples.size(), internal::kFitNoFace);
      m_face_hint.assign(m_faces.size(), internal::Reference_sample::kNoTriangle);
      if (m_options.tolerance > 0)
        m_bounded = std::make_unique<Bounded_state>(
            *fitter.m_input_mesh, get(CGAL::vertex_point, *fitter.m_input_mesh), tm,
            m_options.tolerance, Hausdorff_bounded_options());
      refresh_faces();
      start_guards();
      // A border vertex the simplification placed off the input's border curve is not snapped
      // onto it: that made the border worse than where the policy put it (docs/fitting.md).
      m_off_curve.assign(m_vertices.size(), false);
      if (!fitter.m_border.empty())
        for (std::uint32_t v = 0; v < m_vertices.size(); ++v)
          m_off_curve[v] = CGAL::is_border(m_vertices[v], tm) &&
                           fitter.m_border.distance(m_points[v]) > 1e-9 * fitter.m_input.diagonal();
    }

    // Matches both ways as the mesh is now; returns the two directions' mean distances, averaged.
    double match() {
      refresh_faces();
      match_input_samples();
      m_output_matches = match_output_samples();
      double sum = 0;
      for (std::size_t s = 0; s < m_matches.size(); ++s)
        sum += m_fitter->m_samples[s].weight * m_matches[s].distance;
      for (const Matched_output_sample& o : m_output_matches) sum += o.weight * o.distance;
      return 0.5 * sum;  // each direction's weights sum to 1
    }

    // Keeps what a round may have to undo: the points, and the flips it makes.
    void begin_round() {
      m_round_start = m_points;
      m_round_flips.clear();
    }

    // Back to where the round began; the guard, and the bound's attachment, start from there.
    void undo_round() {
      for (auto it = m_round_flips.rbegin(); it != m_round_flips.rend(); ++it)
        CGAL::Euler::flip_edge(*it, *m_tm);
      m_points = m_round_start;
      for (std::uint32_t v = 0; v < m_vertices.size(); ++v)
        put(m_vpm, m_vertices[v], internal::to_point<Point>(m_points[v]));
      refresh_faces();
      start_guards();
    }

    // Solves for the points the last matches ask for and moves toward them; `scale` is the mean
    // distance match() returned, `reach` scales the trust region. False when the system could not
    // be solved.
    bool fit_round(Two_sided_fit_report& report, double scale, double reach) {
      const std::size_t n = m_vertices.size();
      using Block = Eigen::Matrix<double, 9, 9>;
      using Side = Eigen::Matrix<double, 9, 1>;
      std::vector<Block> blocks(m_faces.size(), Block::Zero());
      std::vector<Side> sides(m_faces.size(), Side::Zero());
      // A match's squared distance, measured along its direction in full and across it at
      // tangent_weight: the distance to the tangent plane, which lets a vertex slide along the
      // surface instead of being held to last round's nearest points.
      const auto add = [&](std::uint32_t f, const Vector3& b, double w, const Vector3& target) {
        const Face_corners& c = m_corners[f];
        Vector3 along =
            b[0] * m_points[c[0]] + b[1] * m_points[c[1]] + b[2] * m_points[c[2]] - target;
        if (!(along.norm() > 0))
          along = internal::triangle_area_normal(m_points[c[0]], m_points[c[1]], m_points[c[2]]);
        along = internal::unit_or_zero(along);
        const Eigen::Matrix3d metric =
            w * (m_options.tangent_weight * Eigen::Matrix3d::Identity() +
                 (1 - m_options.tangent_weight) * along * along.transpose());
        const Vector3 pulled = metric * target;
        for (int r = 0; r < 3; ++r) {
          sides[f].segment<3>(3 * r) += b[r] * pulled;
          for (int k = 0; k < 3; ++k) blocks[f].block<3, 3>(3 * r, 3 * k) += b[r] * b[k] * metric;
        }
      };
      const auto weight = [&](double base, double distance) {
        return m_options.target_mean ? base / std::max(distance, 0.1 * scale) : base;
      };
      for (std::size_t s = 0; s < m_matches.size(); ++s) {
        const Input_match& m = m_matches[s];
        add(m.face, m.barycentric, weight(m_fitter->m_samples[s].weight, m.distance),
            m_fitter->m_samples[s].point);
      }
      for (const Matched_output_sample& o : m_output_matches)
        add(o.face, o.barycentric, weight(o.weight, o.distance), o.target);
      std::vector<Eigen::Triplet<double>> entries;
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(3 * n));
      double trace = 0;
      for (std::uint32_t f = 0; f < m_faces.size(); ++f)
        for (int r = 0; r < 3; ++r) {
          const Eigen::Index row = 3 * Eigen::Index(m_corners[f][r]);
          for (int k = 0; k < 3; ++k) {
            const Eigen::Index column = 3 * Eigen::Index(m_corners[f][k]);
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j)
                entries.emplace_back(row + i, column + j, blocks[f](3 * r + i, 3 * k + j));
          }
          rhs.segment<3>(row) += sides[f].segment<3>(3 * r);
          trace += blocks[f].block<3, 3>(3 * r, 3 * r).trace();
        }
      // A light pull toward where each vertex is keeps the system definite (a vertex no sample
      // reaches stays, and so does a vertex's slide along a flat tangent plane).
      const double pull = 1e-3 * trace / double(3 * n);
      for (std::uint32_t v = 0; v < n; ++v)
        for (int i = 0; i < 3; ++i) {
          entries.emplace_back(3 * v + i, 3 * v + i, pull);
          rhs[3 * v + i] += pull * m_points[v][i];
        }
      Eigen::SparseMatrix<double> system{Eigen::Index(3 * n), Eigen::Index(3 * n)};
      system.setFromTriplets(entries.begin(), entries.end());
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
      if (solver.info() != Eigen::Success) return false;
      const Eigen::VectorXd solved = solver.solve(rhs);
      if (solver.info() != Eigen::Success || !solved.allFinite()) return false;
      move_vertices(solved, reach, report);
      return true;
    }

    // After fit_round: the faces are those match() refreshed, only their corners moved.
    void flip_round(Two_sided_fit_report& report) {
      bucket_samples();
      m_output_area = output_area();
      if (!(m_output_area > 0)) return;
      m_output_error.resize(m_faces.size());
      for (std::uint32_t f = 0; f < m_faces.size(); ++f)
        m_output_error[f] = output_error(triangle(f), m_face_hint[f]);
      std::vector<halfedge_descriptor> candidates;
      for (auto e : edges(*m_tm))
        if (!CGAL::is_border(e, *m_tm)) candidates.push_back(halfedge(e, *m_tm));
      for (halfedge_descriptor h : candidates) try_flip(h, report);
    }

   private:
    struct Input_match {
      std::uint32_t face;
      Vector3 barycentric;
      double distance;
    };
    struct Matched_output_sample {
      std::uint32_t face;
      Vector3 barycentric;
      double weight, distance;
      Vector3 target;
    };

    // The guard, and in bounded mode the input's pieces, tied to the mesh as it is now.
    void start_guards() {
      std::vector<internal::Indexed_triangle> triangles;
      double edge_sum = 0;
      for (std::uint32_t f = 0; f < m_faces.size(); ++f) {
        triangles.push_back(triangle(f));
        for (int k = 0; k < 3; ++k)
          edge_sum += (triangles.back().points[(k + 1) % 3] - triangles.back().points[k]).norm();
      }
      const double mean_edge = edge_sum / (3.0 * double(m_faces.size()));
      m_guard.emplace(std::move(triangles), m_options.max_normal_angle_deg,
                      mean_edge > 0 ? 2 * mean_edge : 1.0);
      if (m_bounded) m_bounded->attach_to_approximation(*m_tm, m_vpm);
    }

    void refresh_faces() {
      m_corners.resize(m_faces.size());
      m_neighbours.resize(m_faces.size());
      for (std::uint32_t f = 0; f < m_faces.size(); ++f) {
        int k = 0;
        for (halfedge_descriptor h :
             CGAL::halfedges_around_face(halfedge(m_faces[f], *m_tm), *m_tm)) {
          m_corners[f][k] = get(m_vertex_index, target(h, *m_tm));
          const face_descriptor g = face(opposite(next(h, *m_tm), *m_tm), *m_tm);
          m_neighbours[f][k++] =
              g == Graph_traits::null_face() ? internal::kFitNoFace : get(m_face_index, g);
        }
      }
    }

    internal::Indexed_triangle triangle(std::uint32_t f) const {
      internal::Indexed_triangle t;
      for (int k = 0; k < 3; ++k) {
        t.vertices[k] = m_corners[f][k];
        t.points[k] = m_points[m_corners[f][k]];
      }
      return t;
    }

    double squared_distance(const Vector3& p, std::uint32_t f) const {
      return internal::squared_distance_to_triangle(
          p, m_points[m_corners[f][0]], m_points[m_corners[f][1]], m_points[m_corners[f][2]]);
    }

    // Each input sample's nearest output point: a walk from last round's face, or the tree.
    void match_input_samples() {
      std::optional<Input_surface::Search_tree> tree;
      Input_surface::Search_triangles triangles;
      std::optional<Input_surface::Search_tree::Point_and_primitive_id> hint;
      const auto nearest_by_tree = [&](const Vector3& p) {
        if (!tree) {
          for (std::uint32_t f = 0; f < m_faces.size(); ++f) {
            const internal::Indexed_triangle t = triangle(f);
            triangles.emplace_back(Input_surface::search_point(t.points[0]),
                                   Input_surface::search_point(t.points[1]),
                                   Input_surface::search_point(t.points[2]));
          }
          tree.emplace(triangles.begin(), triangles.end());
          tree->accelerate_distance_queries();
        }
        // Seeded with the last answer: consecutive samples are mostly neighbours.
        hint = hint ? tree->closest_point_and_primitive(Input_surface::search_point(p), *hint)
                    : tree->closest_point_and_primitive(Input_surface::search_point(p));
        return std::uint32_t(hint->second - triangles.cbegin());
      };
      const std::vector<Input_sample>& samples = m_fitter->m_samples;
      m_matches.resize(samples.size());
      for (std::size_t s = 0; s < samples.size(); ++s) {
        const Vector3& p = samples[s].point;
        std::uint32_t f = m_sample_face[s];
        bool lost = f == internal::kFitNoFace;
        if (!lost) {
          double d2 = squared_distance(p, f);
          std::size_t step = 0;
          for (; step < internal::kFitWalkSteps; ++step) {
            const std::uint32_t from = f;
            for (const std::uint32_t g : m_neighbours[from]) {
              if (g == internal::kFitNoFace) continue;
              const double e2 = squared_distance(p, g);
              if (e2 < d2) {
                d2 = e2;
                f = g;
              }
            }
            if (f == from) break;
          }
          lost = step == internal::kFitWalkSteps;
        }
        if (lost) f = nearest_by_tree(p);
        m_sample_face[s] = f;
        const internal::Indexed_triangle t = triangle(f);
        const Vector3 b = internal::closest_barycentric(p, t.points[0], t.points[1], t.points[2]);
        m_matches[s] = {f, b,
                        (b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2] - p).norm()};
      }
    }

    // Samples of every output face and their nearest input points.
    std::vector<Matched_output_sample> match_output_samples() {
      static const std::vector<Vector3> grid =
          internal::barycentric_grid(internal::kFitOutputLevel);
      std::vector<Matched_output_sample> matched;
      const double total_area = output_area();
      if (!(total_area > 0)) return matched;
      // In the first round a face has no input triangle of its own yet: its walks start from the
      // triangle of an input sample matched to it, which lies near the face.
      for (std::size_t s = 0; s < m_sample_face.size(); ++s) {
        if (m_sample_face[s] == internal::kFitNoFace) continue;
        std::size_t& hint = m_face_hint[m_sample_face[s]];
        if (hint == internal::Reference_sample::kNoTriangle) hint = m_fitter->m_samples[s].triangle;
      }
      for (std::uint32_t f = 0; f < m_faces.size(); ++f) {
        const internal::Indexed_triangle t = triangle(f);
        const double w = triangle_area(t) / (total_area * double(grid.size()));
        for (const Vector3& b : grid) {
          const Vector3 y = b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2];
          const internal::Reference_sample near = m_fitter->m_input.nearest(y, m_face_hint[f]);
          m_face_hint[f] = near.triangle;
          const internal::Triangle_corners& q = m_fitter->m_input.corners(near.triangle);
          const Vector3 c = internal::closest_barycentric(y, q[0], q[1], q[2]);
          matched.push_back({f, b, w, near.distance, c[0] * q[0] + c[1] * q[1] + c[2] * q[2]});
        }
      }
      return matched;
    }

    static double triangle_area(const internal::Indexed_triangle& t) {
      return 0.5 * internal::triangle_area_normal(t.points[0], t.points[1], t.points[2]).norm();
    }

    double output_area() const {
      double area = 0;
      for (std::uint32_t f = 0; f < m_faces.size(); ++f) area += triangle_area(triangle(f));
      return area;
    }

    void move_vertices(const Eigen::VectorXd& solved, double reach, Two_sided_fit_report& report) {
      std::vector<double> edge_sum(m_vertices.size(), 0.0);
      std::vector<int> edge_count(m_vertices.size(), 0);
      for (const Face_corners& c : m_corners)
        for (int k = 0; k < 3; ++k) {
          const double length = (m_points[c[(k + 1) % 3]] - m_points[c[k]]).norm();
          for (const std::uint32_t v : {c[k], c[(k + 1) % 3]}) {
            edge_sum[v] += length;
            ++edge_count[v];
          }
        }
      for (std::uint32_t v = 0; v < m_vertices.size(); ++v) {
        if (edge_count[v] == 0 || m_pinned[v]) continue;
        Vector3 step = solved.segment<3>(3 * Eigen::Index(v)) - m_points[v];
        const double limit = reach * m_options.trust_fraction * edge_sum[v] / edge_count[v];
        if (step.norm() > limit) step *= limit / step.norm();
        if (!(step.norm() > 0)) continue;
        if (try_move(v, m_points[v] + step, limit) || try_move(v, m_points[v] + 0.5 * step, limit))
          ++report.moves;
        else
          ++report.refused_moves;
      }
    }

    // Moves v to p when the guards allow it and it stays within `limit`. A border vertex on the
    // input's border curve goes to the point of the curve nearest p along its own stretch of it;
    // one off the curve may move only where it is no farther from the curve.
    bool try_move(std::uint32_t v, Vector3 p, double limit) {
      const vertex_descriptor vd = m_vertices[v];
      if (CGAL::is_border(vd, *m_tm) && !m_fitter->m_border.empty()) {
        if (!m_off_curve[v])
          p = m_fitter->m_border.nearest_along(m_points[v], p, limit);
        else if (m_fitter->m_border.distance(p) > m_fitter->m_border.distance(m_points[v]))
          return false;
      }
      if (p == m_points[v] || (p - m_points[v]).norm() > limit) return false;
      std::vector<std::uint32_t> star;
      std::vector<internal::Indexed_triangle> moved;
      std::vector<Vector3> references;
      for (face_descriptor f : CGAL::faces_around_target(halfedge(vd, *m_tm), *m_tm)) {
        if (f == Graph_traits::null_face()) continue;
        const std::uint32_t i = get(m_face_index, f);
        star.push_back(i);
        internal::Indexed_triangle t = triangle(i);
        for (int k = 0; k < 3; ++k)
          if (t.vertices[k] == v) t.points[k] = p;
        moved.push_back(t);
        references.push_back(m_guard->reference(i));
      }
      if (!m_guard->allows(star, moved, references)) return false;
      if (m_bounded && !m_bounded->try_move(*m_tm, m_vpm, vd, p)) return false;
      put(m_vpm, vd, internal::to_point<Point>(p));
      m_points[v] = p;
      m_guard->apply(star, moved, references);
      return true;
    }

    void bucket_samples() {
      m_face_samples.assign(m_faces.size(), {});
      for (std::uint32_t s = 0; s < m_sample_face.size(); ++s)
        if (m_sample_face[s] != internal::kFitNoFace) m_face_samples[m_sample_face[s]].push_back(s);
    }

    // The error of a pair of triangles replacing faces f0 and f1 seen from the input: its samples
    // matched to those faces, distances squared (or not, aiming at the mean).
    double pair_input_error(std::uint32_t f0, std::uint32_t f1,
                            const std::array<internal::Indexed_triangle, 2>& pair) const {
      double error = 0;
      for (const std::uint32_t f : {f0, f1})
        for (const std::uint32_t s : m_face_samples[f]) {
          const Vector3& p = m_fitter->m_samples[s].point;
          double d2 = std::numeric_limits<double>::infinity();
          for (const internal::Indexed_triangle& t : pair)
            d2 = (std::min)(d2, internal::squared_distance_to_triangle(p, t.points[0], t.points[1],
                                                                       t.points[2]));
          error += m_fitter->m_samples[s].weight * penalty(d2);
        }
      return error;
    }

    // The error of a triangle seen from itself: its samples and their nearest input points. It
    // stops once the sum passes `budget`, so a flip that cannot pay off is dropped early.
    double output_error(const internal::Indexed_triangle& t, std::size_t hint,
                        double budget = std::numeric_limits<double>::infinity()) {
      static const std::vector<Vector3> grid = internal::barycentric_grid(internal::kFitFlipLevel);
      const double w = triangle_area(t) / (m_output_area * double(grid.size()));
      double error = 0;
      for (const Vector3& b : grid) {
        const internal::Reference_sample near = m_fitter->m_input.nearest(
            b[0] * t.points[0] + b[1] * t.points[1] + b[2] * t.points[2], hint);
        hint = near.triangle;
        error += w * penalty(near.distance * near.distance);
        if (error > budget) break;
      }
      return error;
    }

    double penalty(double squared_distance) const {
      return m_options.target_mean ? std::sqrt(squared_distance) : squared_distance;
    }

    void try_flip(halfedge_descriptor h, Two_sided_fit_report& report) {
      TriangleMesh& tm = *m_tm;
      const vertex_descriptor a = source(h, tm), b = target(h, tm);
      const vertex_descriptor c = target(next(h, tm), tm);
      const vertex_descriptor d = target(next(opposite(h, tm), tm), tm);
      if (c == d || halfedge(c, d, tm).second || degree(a, tm) < 4 || degree(b, tm) < 4) return;
      const std::uint32_t f0 = get(m_face_index, face(h, tm));
      const std::uint32_t f1 = get(m_face_index, face(opposite(h, tm), tm));
      const auto indexed = [&](vertex_descriptor x, vertex_descriptor y, vertex_descriptor z) {
        internal::Indexed_triangle t;
        const std::array<vertex_descriptor, 3> corners = {x, y, z};
        for (int k = 0; k < 3; ++k) {
          t.vertices[k] = get(m_vertex_index, corners[k]);
          t.points[k] = m_points[t.vertices[k]];
        }
        return t;
      };
      const std::array<internal::Indexed_triangle, 2> before = {indexed(a, b, c), indexed(b, a, d)};
      const std::array<internal::Indexed_triangle, 2> after = {indexed(a, d, c), indexed(d, b, c)};
      // Strictly lower, beyond rounding: a flip of a flat quad changes nothing.
      const double rounding = penalty(CGAL::square(1e-9 * m_fitter->m_input.diagonal()));
      const double budget = (1 - 1e-9) * (pair_input_error(f0, f1, before) + m_output_error[f0] +
                                          m_output_error[f1]) -
                            rounding;
      const double input_after = pair_input_error(f0, f1, after);
      if (!(input_after < budget)) return;
      const double output_after0 = output_error(after[0], m_face_hint[f0], budget - input_after);
      if (!(input_after + output_after0 < budget)) return;
      const double output_after1 =
          output_error(after[1], m_face_hint[f1], budget - input_after - output_after0);
      if (!(input_after + output_after0 + output_after1 < budget)) return;
      const Vector3 reference =
          internal::unit_or_zero(m_guard->reference(f0) + m_guard->reference(f1));
      const std::vector<Vector3> references = {reference, reference};
      const std::vector<std::uint32_t> changed = {f0, f1};
      if (!m_guard->allows(changed, {after[0], after[1]}, references)) {
        ++report.refused_flips;
        return;
      }
      CGAL::Euler::flip_edge(h, tm);  // h now joins c and d
      m_round_flips.push_back(h);
      if (m_bounded && !m_bounded->try_reshape(tm, m_vpm, {m_faces[f0], m_faces[f1]})) {
        CGAL::Euler::flip_edge(h, tm);
        m_round_flips.pop_back();
        ++report.refused_flips;
        return;
      }
      ++report.flips;
      for (const std::uint32_t f : changed) {
        int k = 0;
        for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(m_faces[f], tm), tm))
          m_corners[f][k++] = get(m_vertex_index, v);
      }
      m_guard->apply(changed, {triangle(f0), triangle(f1)}, references);
      // Euler::flip_edge decides which face becomes which triangle: the one with a is after[0].
      const bool f0_has_a = std::find(m_corners[f0].begin(), m_corners[f0].end(),
                                      after[0].vertices[0]) != m_corners[f0].end();
      m_output_error[f0] = f0_has_a ? output_after0 : output_after1;
      m_output_error[f1] = f0_has_a ? output_after1 : output_after0;
      // The input samples of the pair go to the nearer of its new faces.
      std::vector<std::uint32_t> pooled = m_face_samples[f0];
      pooled.insert(pooled.end(), m_face_samples[f1].begin(), m_face_samples[f1].end());
      m_face_samples[f0].clear();
      m_face_samples[f1].clear();
      for (const std::uint32_t s : pooled) {
        const Vector3& p = m_fitter->m_samples[s].point;
        const std::uint32_t f = squared_distance(p, f0) <= squared_distance(p, f1) ? f0 : f1;
        m_sample_face[s] = f;
        m_face_samples[f].push_back(s);
      }
    }

    TriangleMesh* m_tm;
    Vertex_point_map m_vpm;
    Two_sided_fitter* m_fitter;
    Two_sided_fit_options m_options;
    typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::uint32_t>>::type
        m_vertex_index;
    typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::uint32_t>>::type
        m_face_index;
    std::vector<vertex_descriptor> m_vertices;
    std::vector<face_descriptor> m_faces;
    std::vector<Vector3> m_points;
    std::vector<bool> m_off_curve;  // border vertices off the input's border curve
    std::vector<bool> m_pinned;     // vertices fit() was told to leave where they are
    std::vector<Face_corners> m_corners, m_neighbours;
    std::optional<internal::Fit_guard> m_guard;
    std::vector<std::uint32_t> m_sample_face;
    std::vector<Input_match> m_matches;
    std::vector<std::size_t> m_face_hint;  // an input triangle near each output face
    std::vector<std::vector<std::uint32_t>> m_face_samples;
    double m_output_area = 0;
    std::vector<double> m_output_error;  // each face's output_error() in a flip round
    std::unique_ptr<Bounded_state> m_bounded;
    std::vector<Matched_output_sample> m_output_matches;
    std::vector<Vector3> m_round_start;
    std::vector<halfedge_descriptor> m_round_flips;
  };

  const TriangleMesh* m_input_mesh;
  Two_sided_fit_options m_options;
  Input_surface m_input;
  internal::Border_curve m_border;
  std::vector<Input_sample> m_samples;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_TWO_SIDED_FITTER_H
