// The flat-array engine of Fast_threshold_simplifier ([Hu14] §2.2; docs/fast.md): threshold
// passes over triangles that store their edges' errors, with the checks the report lacks.
#ifndef CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
#define CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/Fast_threshold_options.h>
#include <cgal_policies/internal/Flat_collapse_mesh.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

struct Fast_threshold_vertex {
  Eigen::Vector3d point;
  Quadric quadric;  // face planes plus border planes (docs/quadric_core.md)
  bool border = false;
  bool locked = false;  // never moved nor removed (the cut vertices of a partitioned run)
};

// Corners as Flat_collapse_mesh takes them; with values (mesh().set_corner_values), the collapses
// keep the seam rules of Corner_attribute_carrier (docs/attributes.md).
template <class Corners = No_corner_values>
class Fast_threshold_engine {
 public:
  // The flags sit in the padding after v: 48 bytes instead of 56 for the sweeps of every pass.
  struct Triangle {
    std::array<int, 3> v;
    bool deleted;
    bool dirty;                   // touched by a collapse in this pass
    bool refused;                 // every edge it offered was refused, and it has not changed since
    std::array<double, 3> error;  // of edge (v[j], v[j+1])
    double min_error;
  };
  using Mesh = Flat_collapse_mesh<Corners, Fast_threshold_vertex, Triangle>;

  // The arrays, for the corner values before simplify() and the result after it.
  Mesh& mesh() { return m_mesh; }

  // t_k = kThresholdScale (k + 3)^a D^2: [FQMS]'s schedule, made relative to D^2.
  static constexpr double kThresholdScale = 1e-9;
  // Errors below this fraction of D^2 are round-off: the lossless mode collapses only those.
  static constexpr double kLosslessTolerance = 1e-14;
  // The level cap: a pass takes only errors within this share of the open triangles (neither
  // deleted nor refused since they changed), so that cheap edges still go first (docs/fast.md).
  static constexpr double kPassShare = 0.2;
  // The pass indexes are doubles (idle passes are jumped); above 2^53 they are not all exact.
  static constexpr double kLargestExactIndex =
      double(std::uint64_t(1) << std::numeric_limits<double>::digits);
  // Passes between two rebuilds of the reference lists.
  static constexpr std::size_t kCompactionPeriod = 5;

  // `planes`: how the face and border planes of the vertices' quadrics are weighted.
  // Precondition: every triangle has three distinct vertex indices in range.
  Fast_threshold_engine(std::vector<Fast_threshold_vertex> vertices,
                        const std::vector<std::array<int, 3>>& triangles, double bbox_diagonal,
                        Face_weighting planes)
      : m_mesh(divided_by_mean_face_area(planes, triangles, std::move(vertices)),
               triangles_of(triangles)),
        m_squared_diagonal(bbox_diagonal * bbox_diagonal) {}

  struct Outcome {
    std::size_t passes = 0;
    bool target_reached = false;
  };

  // Pass k collapses, in storage order and at most once per triangle, edges below its threshold
  // and the level cap, until the target is reached or no allowed collapse is left.
  Outcome simplify(std::size_t target_faces, const Fast_threshold_options& options,
                   const std::function<void(std::size_t)>& on_progress = {}) {
    CGAL_precondition(options.aggressiveness > 0);
    m_options = options;
    m_cos_max_angle = std::cos(options.max_normal_angle_deg * (std::acos(-1.0) / 180.0));
    collect_errors();

    Outcome outcome;
    double k = 0;  // a double: empty passes are skipped by jumping k
    for (std::size_t pass = 0; m_mesh.live_triangles() > target_faces; ++pass) {
      // The deleted triangles leave the lists (the constructor's lists have none).
      if (pass > 0 && pass % kCompactionPeriod == 0) m_mesh.compact();
      // The pass takes errors below t_k and the level cap: cheap edges first.
      const Pass_result result = run_pass(threshold_of_pass(k), level_cap(), target_faces);
      outcome.passes = pass + 1;
      if (on_progress) on_progress(m_mesh.live_triangles());
      // k + 1, or past the idle passes; none when nothing is left to wait for.
      const std::optional<double> next = next_pass_index(k, result);
      if (!next) break;
      k = *next;
    }
    m_mesh.compact();
    outcome.target_reached = m_mesh.live_triangles() <= target_faces;
    return outcome;
  }

 private:
  using Reference = typename Mesh::Reference;

  // With planes weighted by area an error is an area times a squared distance: the quadrics are
  // divided by the mean face area, so that the errors are squared distances again, in the units of
  // the thresholds, and a run is the same at any scale of the model. As they are with unit weights.
  static std::vector<Fast_threshold_vertex> divided_by_mean_face_area(
      Face_weighting planes, const std::vector<std::array<int, 3>>& triangles,
      std::vector<Fast_threshold_vertex> vertices) {
    if (planes != Face_weighting::area) return vertices;
    const auto point = [&](int v) -> const Eigen::Vector3d& {
      return vertices[std::size_t(v)].point;
    };
    double twice_area = 0;
    for (const std::array<int, 3>& t : triangles)
      twice_area += triangle_area_normal(point(t[0]), point(t[1]), point(t[2])).norm();
    if (!(twice_area > 0)) return vertices;
    const double scale = 2 * double(triangles.size()) / twice_area;
    for (Fast_threshold_vertex& v : vertices) v.quadric = v.quadric.scaled(scale);
    return vertices;
  }

  static std::vector<Triangle> triangles_of(const std::vector<std::array<int, 3>>& triangles) {
    std::vector<Triangle> result;
    result.reserve(triangles.size());
    for (const auto& t : triangles) result.push_back({t, false, false, false, {}, 0});
    return result;
  }

  // What a pass did.
  struct Pass_result {
    std::size_t collapses = 0;
    bool held_back = false;  // some triangle below t_k waited for a higher level
    double smallest_waiting = std::numeric_limits<double>::infinity();  // of those not below t_k
  };

  // Every triangle's edge errors, before the first pass.
  void collect_errors() {
    for (std::size_t t = 0; t < m_mesh.triangles().size(); ++t) compute_errors(t);
  }

  // t_k; in the lossless mode, round-off whatever k.
  double threshold_of_pass(double k) const {
    return m_options.lossless
               ? kLosslessTolerance * m_squared_diagonal
               : kThresholdScale * std::pow(k + 3, m_options.aggressiveness) * m_squared_diagonal;
  }

  // The kPassShare quantile of the open triangles' smallest errors; none in the lossless mode.
  // Refused triangles are left out: cheap but blocked, they would hold the level down for good.
  double level_cap() {
    if (m_options.lossless) return std::numeric_limits<double>::infinity();
    m_scratch.clear();
    for (const Triangle& t : m_mesh.triangles())
      if (!t.deleted && !t.refused) m_scratch.push_back(t.min_error);
    if (m_scratch.empty()) return std::numeric_limits<double>::infinity();
    const auto at = m_scratch.begin() + std::ptrdiff_t(kPassShare * double(m_scratch.size() - 1));
    std::nth_element(m_scratch.begin(), at, m_scratch.end());
    return *at;
  }

  // One pass over the triangles that no collapse of this pass touched, until the target is reached.
  Pass_result run_pass(double threshold, double level, std::size_t target_faces) {
    std::vector<Triangle>& triangles = m_mesh.triangles();
    for (Triangle& t : triangles) t.dirty = false;
    Pass_result result;
    for (std::size_t t = 0; t < triangles.size() && m_mesh.live_triangles() > target_faces; ++t) {
      const Triangle& triangle = triangles[t];
      if (triangle.deleted || triangle.dirty) continue;
      if (!(triangle.min_error < threshold)) {
        result.smallest_waiting = (std::min)(result.smallest_waiting, triangle.min_error);
        continue;
      }
      if (!(triangle.min_error <= level)) {
        result.held_back = true;
        continue;
      }
      // try_collapse leaves t deleted or refuses: then t stays refused until it changes.
      if (collapse_an_edge(t, threshold, level))
        ++result.collapses;
      else
        triangles[t].refused = true;
    }
    return result;
  }

  // Tries t's edges below both bounds in order, up to the first that collapses.
  bool collapse_an_edge(std::size_t t, double threshold, double level) {
    for (int j = 0; j < 3; ++j) {
      const double error = m_mesh.triangles()[t].error[j];
      if (error < threshold && error <= level && try_collapse(t, j)) return true;
    }
    return false;
  }

  // The k of the pass after pass k, or none: the passes are over.
  std::optional<double> next_pass_index(double k, const Pass_result& pass) const {
    if (pass.collapses > 0 || pass.held_back) return k + 1;
    // Idle, nothing held back: jump to the first pass whose threshold exceeds the smallest
    // waiting error, or stop if none waits. (Held back: the level rises, those tries refused.)
    if (m_options.lossless || !std::isfinite(pass.smallest_waiting)) return std::nullopt;
    const double relative = pass.smallest_waiting / (kThresholdScale * m_squared_diagonal);
    double next =
        (std::max)(k + 1, std::ceil(std::pow(relative, 1.0 / m_options.aggressiveness)) - 3);
    // Past 2^53 a step of one is lost in the rounding: the step doubles there, so the search ends.
    for (double step = 1; threshold_of_pass(next) <= pass.smallest_waiting; next += step)
      if (next >= kLargestExactIndex) step *= 2;
    return next;
  }

  // The error of merging a and b, an edge of triangle `on`, and where the merged vertex goes: the
  // border planes hold a border vertex near its border line. With corner values the seam rules
  // choose, and an edge they refuse costs infinity.
  double edge_error(int a, int b, std::size_t on, Eigen::Vector3d& placement) {
    const Fast_threshold_vertex& va = m_mesh.vertex(a);
    const Fast_threshold_vertex& vb = m_mesh.vertex(b);
    const Quadric q = va.quadric + vb.quadric;
    constexpr double kRefused = std::numeric_limits<double>::infinity();
    if (va.locked || vb.locked) return kRefused;
    placement = optimal_placement(q, va.point, vb.point).point;
    if (m_mesh.carries_values() && !m_mesh.place_by_seams(a, b, on, placement)) return kRefused;
    const double error = q.evaluate(placement);
    return std::isfinite(error) ? (std::max)(0.0, error) : kRefused;
  }

  void compute_errors(std::size_t t) {
    Triangle& triangle = m_mesh.triangles()[t];
    Eigen::Vector3d unused;
    for (int j = 0; j < 3; ++j)
      triangle.error[j] = edge_error(triangle.v[j], triangle.v[(j + 1) % 3], t, unused);
    triangle.min_error = (std::min)({triangle.error[0], triangle.error[1], triangle.error[2]});
    triangle.refused = false;
  }

  // m_star_errors: this collapse's errors by the edge's other end (each edge is in two triangles).
  void refresh_corner(std::size_t triangle, int at) {
    Triangle& t = m_mesh.triangles()[triangle];
    for (int j : {at, (at + 2) % 3}) {
      const int other = t.v[j == at ? (at + 1) % 3 : j];
      const auto known = std::find_if(m_star_errors.begin(), m_star_errors.end(),
                                      [other](const auto& e) { return e.first == other; });
      if (known != m_star_errors.end()) {
        t.error[j] = known->second;
      } else {
        Eigen::Vector3d unused;
        t.error[j] = edge_error(t.v[at], other, triangle, unused);
        m_star_errors.emplace_back(other, t.error[j]);
      }
    }
    t.min_error = (std::min)({t.error[0], t.error[1], t.error[2]});
    t.refused = false;
  }

  // The collapse of t's edge from `corner`, unless a check refuses it.
  bool try_collapse(std::size_t triangle, int corner) {
    const int a = m_mesh.triangles()[triangle].v[corner];
    const int b = m_mesh.triangles()[triangle].v[(corner + 1) % 3];
    Eigen::Vector3d p;
    const double error = edge_error(a, b, triangle, p);
    if (!std::isfinite(error)) return false;  // refused: a locked end, or the seam rules
    if (!m_mesh.satisfies_link_condition(a, b) || m_mesh.turns_too_far(a, b, p, m_cos_max_angle) ||
        m_mesh.turns_too_far(b, a, p, m_cos_max_angle))
      return false;
    if (!m_mesh.plan_corner_values(a, b, p)) return false;

    m_mesh.vertex(a).quadric += m_mesh.vertex(b).quadric;
    m_mesh.collapse(a, b, p, [](Triangle& t) { t.dirty = true; });
    // Errors after the whole star is rewired: the seam tests look across its edges.
    refresh_star_errors(a);
    return true;
  }

  void refresh_star_errors(int a) {
    m_star_errors.clear();
    for (const Reference* r = m_mesh.references_begin(a); r != m_mesh.references_end(a); ++r)
      refresh_corner(std::size_t(r->triangle), r->corner);
  }

  Mesh m_mesh;
  std::vector<std::pair<int, double>> m_star_errors;  // refresh_corner's, for one collapse
  std::vector<double> m_scratch;                      // level_cap's buffer, kept between passes
  double m_squared_diagonal;
  Fast_threshold_options m_options;  // simplify()'s
  double m_cos_max_angle = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
