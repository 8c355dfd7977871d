// The flat-array engine of Fast_threshold_simplifier ([Hu14] §2.2; docs/fast.md): threshold
// passes over triangles that store their edges' errors, with the checks the report lacks.
#ifndef CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
#define CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H

#include <cgal_policies/Fast_threshold_options.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/nearest_corner_values.h>
#include <cgal_policies/internal/quadric_placement.h>
#include <cgal_policies/internal/seam_collapse_rule.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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

// No corner values: the engine moves points only.
struct No_corner_values {
  struct Values {};
  static Values blend(const std::array<Values, 3>&, const std::array<double, 3>&) { return {}; }
  static bool same(const Values&, const Values&) { return true; }
  static double uv_area(const Values&, const Values&, const Values&) { return 0; }
};

// Corners: the values a triangle holds at its corners (Values), how they blend at barycentric
// weights, when two are the same, and the signed area of their texture triangle (NaN without
// texture coordinates), as No_corner_values spells them. With values (set_corner_values), the
// collapses keep the seam rules of Corner_attribute_carrier (docs/attributes.md).
template <class Corners = No_corner_values>
class Fast_threshold_engine {
 public:
  using Values = typename Corners::Values;

  // t_k = kThresholdScale (k + 3)^a D^2: [FQMS]'s schedule, made relative to D^2.
  static constexpr double kThresholdScale = 1e-9;
  // Errors below this fraction of D^2 are round-off: the lossless mode collapses only those.
  static constexpr double kLosslessTolerance = 1e-14;
  // The level cap: a pass takes only errors within this share of the open triangles (neither
  // deleted nor refused since they changed), so that cheap edges still go first (docs/fast.md).
  static constexpr double kPassShare = 0.4;
  // Twice the area over the squared longest edge (sqrt(3)/2 when equilateral) below which a face
  // has no reliable normal: no collapse makes one, or a thinner one (docs/fast.md, "Sliver guard").
  static constexpr double kMinimumFaceShape = 1e-6;
  // Passes between two rebuilds of the reference lists.
  static constexpr std::size_t kCompactionPeriod = 5;

  // Precondition: every triangle has three distinct vertex indices in range.
  Fast_threshold_engine(std::vector<Fast_threshold_vertex> vertices,
                        std::vector<std::array<int, 3>> triangles, double bbox_diagonal)
      : m_squared_diagonal(bbox_diagonal * bbox_diagonal) {
    m_vertices.reserve(vertices.size());
    for (Fast_threshold_vertex& v : vertices) m_vertices.push_back({std::move(v), 0, 0, false});
    m_triangles.reserve(triangles.size());
    for (const auto& t : triangles) {
      CGAL_precondition(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
      m_triangles.push_back({t, false, false, false, {}, 0});
    }
    m_live_triangles = m_triangles.size();
    m_mark.assign(m_vertices.size(), 0);
  }

  // The values at each triangle's corners, in the constructor's order; from then on the
  // collapses carry them. The borders count as seams: a border vertex stays where it is or slides
  // along the border to a neighbour's point.
  void set_corner_values(std::vector<std::array<Values, 3>> corners) {
    CGAL_precondition(corners.size() == m_triangles.size());
    m_corners = std::move(corners);
    m_origins.resize(m_triangles.size());
    for (std::size_t t = 0; t < m_origins.size(); ++t) m_origins[t] = int(t);
    m_seam_counts.assign(m_vertices.size(), kUnknownSeams);
  }

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
    for (std::size_t pass = 0; m_live_triangles > target_faces; ++pass) {
      if (pass % kCompactionPeriod == 0) compact();  // the deleted triangles leave the lists
      // The pass takes errors below t_k and the level cap: cheap edges first.
      const Pass_result result = run_pass(threshold_of_pass(k), level_cap(), target_faces);
      outcome.passes = pass + 1;
      if (on_progress) on_progress(m_live_triangles);
      // k + 1, or past the idle passes; none when nothing is left to wait for.
      const std::optional<double> next = next_pass_index(k, result);
      if (!next) break;
      k = *next;
    }
    compact();
    outcome.target_reached = m_live_triangles <= target_faces;
    return outcome;
  }

  // With corner values: `corners` and `origins` (the constructor's index of each triangle) too;
  // `kept`, when given, gets the constructor's index of each point.
  void extract(std::vector<Eigen::Vector3d>& points, std::vector<std::array<int, 3>>& triangles,
               std::vector<std::array<Values, 3>>* corners = nullptr,
               std::vector<int>* origins = nullptr, std::vector<int>* kept = nullptr) {
    compact();
    std::vector<int> index(m_vertices.size(), -1);
    points.clear();
    if (kept) kept->clear();
    for (std::size_t v = 0; v < m_vertices.size(); ++v)
      if (!m_vertices[v].removed) {
        index[v] = int(points.size());
        points.push_back(m_vertices[v].data.point);
        if (kept) kept->push_back(int(v));
      }
    triangles.clear();
    for (const Triangle& t : m_triangles)
      triangles.push_back({index[t.v[0]], index[t.v[1]], index[t.v[2]]});
    if (corners) *corners = m_corners;
    if (origins) *origins = m_origins;
  }

 private:
  struct Vertex {
    Fast_threshold_vertex data;
    int first_reference;  // its triangles are m_references[first, first + count)
    int reference_count;
    bool removed;  // merged into another vertex
  };
  // The flags sit in the padding after v: 48 bytes instead of 56 for the sweeps of every pass.
  struct Triangle {
    std::array<int, 3> v;
    bool deleted;
    bool dirty;                   // touched by a collapse in this pass
    bool refused;                 // every edge it offered was refused, and it has not changed since
    std::array<double, 3> error;  // of edge (v[j], v[j+1])
    double min_error;
  };
  struct Reference {
    int triangle;
    int corner;  // v's position in the triangle
  };

  // What a pass did.
  struct Pass_result {
    std::size_t collapses = 0;
    bool held_back = false;  // some triangle below t_k waited for a higher level
    double smallest_waiting = std::numeric_limits<double>::infinity();  // of those not below t_k
  };

  bool carries_values() const { return !m_corners.empty(); }

  // Every triangle's edge errors, before the first pass.
  void collect_errors() {
    if (carries_values()) compact();  // the seam tests walk the reference lists
    for (std::size_t t = 0; t < m_triangles.size(); ++t) compute_errors(t);
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
    for (const Triangle& t : m_triangles)
      if (!t.deleted && !t.refused) m_scratch.push_back(t.min_error);
    if (m_scratch.empty()) return std::numeric_limits<double>::infinity();
    const auto at = m_scratch.begin() + std::ptrdiff_t(kPassShare * double(m_scratch.size() - 1));
    std::nth_element(m_scratch.begin(), at, m_scratch.end());
    return *at;
  }

  // One pass over the triangles that no collapse of this pass touched, until the target is reached.
  Pass_result run_pass(double threshold, double level, std::size_t target_faces) {
    for (Triangle& t : m_triangles) t.dirty = false;
    Pass_result result;
    for (std::size_t t = 0; t < m_triangles.size() && m_live_triangles > target_faces; ++t) {
      const Triangle& triangle = m_triangles[t];
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
        m_triangles[t].refused = true;
    }
    return result;
  }

  // Tries t's edges below both bounds in order, up to the first that collapses.
  bool collapse_an_edge(std::size_t t, double threshold, double level) {
    for (int j = 0; j < 3; ++j) {
      const double error = m_triangles[t].error[j];
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
    while (threshold_of_pass(next) <= pass.smallest_waiting) next += 1;
    return next;
  }

  // The error of merging a and b, an edge of triangle `on`, and where the merged vertex goes. With
  // one end on the border, it stays at that end. With corner values the seam rules choose, and an
  // edge they refuse costs infinity.
  double edge_error(int a, int b, std::size_t on, Eigen::Vector3d& placement) {
    const Fast_threshold_vertex& va = m_vertices[a].data;
    const Fast_threshold_vertex& vb = m_vertices[b].data;
    const Quadric q = va.quadric + vb.quadric;
    constexpr double kRefused = std::numeric_limits<double>::infinity();
    if (va.locked || vb.locked) return kRefused;
    if (carries_values()) {
      placement = optimal_placement(q, va.point, vb.point).point;
      switch (seam_collapse_rule(
          seam_count(a), seam_count(b), [&] { return is_seam_edge(on, a, b); },
          [&] { return closes_chart(a, b); },
          [&] {
            return (placement - va.point).squaredNorm() < (placement - vb.point).squaredNorm();
          })) {
        case Seam_placement::anywhere:
          break;
        case Seam_placement::at_first:
          placement = va.point;
          break;
        case Seam_placement::at_second:
          placement = vb.point;
          break;
        case Seam_placement::nowhere:
          return kRefused;
      }
    } else if (va.border != vb.border) {
      placement = va.border ? va.point : vb.point;
    } else {
      placement = optimal_placement(q, va.point, vb.point).point;
    }
    const double error = q.evaluate(placement);
    return std::isfinite(error) ? (std::max)(0.0, error) : kRefused;
  }

  void compute_errors(std::size_t t) {
    Triangle& triangle = m_triangles[t];
    Eigen::Vector3d unused;
    for (int j = 0; j < 3; ++j)
      triangle.error[j] = edge_error(triangle.v[j], triangle.v[(j + 1) % 3], t, unused);
    triangle.min_error = (std::min)({triangle.error[0], triangle.error[1], triangle.error[2]});
    triangle.refused = false;
  }

  // m_star_errors: this collapse's errors by the edge's other end (each edge is in two triangles).
  void refresh_corner(std::size_t triangle, int at) {
    Triangle& t = m_triangles[triangle];
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

  const Reference* references_begin(int v) const {
    return m_references.data() + m_vertices[v].first_reference;
  }
  const Reference* references_end(int v) const {
    return references_begin(v) + m_vertices[v].reference_count;
  }

  static bool contains(const Triangle& t, int v) {
    return t.v[0] == v || t.v[1] == v || t.v[2] == v;
  }

  // A vertex's triangles that hold the first vertex opposite an edge, and those that hold both.
  struct Opposite_counts {
    int with_opposite = 0, with_both = 0;
    void count(const Triangle& t, const int (&opposite)[2], bool border_edge) {
      with_opposite += contains(t, opposite[0]);
      with_both += !border_edge && contains(t, opposite[0]) && contains(t, opposite[1]);
    }
  };

  // The link condition [Dey99], borders closed by a virtual vertex as in CGAL's
  // Euler::does_satisfy_link_condition; also no emptied component, no faces glued back to back.
  bool satisfies_link_condition(int a, int b) {
    next_stamp();
    int opposite[2];
    int opposite_count = 0;
    for (const Reference* r = references_begin(b); r != references_end(b); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted || !contains(t, a)) continue;
      if (opposite_count == 2) return false;  // a non-manifold edge
      opposite[opposite_count++] =
          t.v[(r->corner + 1) % 3] == a ? t.v[(r->corner + 2) % 3] : t.v[(r->corner + 1) % 3];
    }
    if (opposite_count == 0) return false;
    const bool border_edge = opposite_count == 1;
    if (!border_edge &&
        (opposite[0] == opposite[1] || (m_vertices[a].data.border && m_vertices[b].data.border)))
      return false;

    // Mark a's neighbours; count a's triangles that hold an opposite vertex (2 unless the edge
    // from a to it is a border edge) or both opposite vertices (a tetrahedron corner).
    Opposite_counts at_a, at_b;
    for (const Reference* r = references_begin(a); r != references_end(a); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted) continue;
      m_mark[t.v[(r->corner + 1) % 3]] = m_stamp;
      m_mark[t.v[(r->corner + 2) % 3]] = m_stamp;
      at_a.count(t, opposite, border_edge);
    }
    for (const Reference* r = references_begin(b); r != references_end(b); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted) continue;
      for (int w : {t.v[(r->corner + 1) % 3], t.v[(r->corner + 2) % 3]})
        if (w != a && m_mark[w] == m_stamp && w != opposite[0] && (border_edge || w != opposite[1]))
          return false;
      at_b.count(t, opposite, border_edge);
    }
    // A lone triangle: its three edges are border edges.
    if (border_edge && at_a.with_opposite == 1 && at_b.with_opposite == 1) return false;
    return !(at_a.with_both > 0 && at_b.with_both > 0);
  }

  // A new m_stamp, which no vertex's mark holds yet.
  void next_stamp() {
    if (++m_stamp == 0) {  // wrapped: clear the stale marks once
      std::fill(m_mark.begin(), m_mark.end(), 0);
      m_stamp = 1;
    }
  }

  static double shape(double twice_area, const Eigen::Vector3d& p, const Eigen::Vector3d& q1,
                      const Eigen::Vector3d& q2) {
    const double longest =
        (std::max)({(q1 - p).squaredNorm(), (q2 - p).squaredNorm(), (q2 - q1).squaredNorm()});
    return longest > 0 ? twice_area / longest : 0.0;
  }

  // Whether moving `moved` to p flips, or thins below kMinimumFaceShape, a triangle around it
  // without `other`; a face already degenerate blocks nothing.
  bool turns_too_far(int moved, int other, const Eigen::Vector3d& p) const {
    const Eigen::Vector3d& old_point = m_vertices[moved].data.point;
    for (const Reference* r = references_begin(moved); r != references_end(moved); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted || contains(t, other)) continue;
      const Eigen::Vector3d& q1 = m_vertices[t.v[(r->corner + 1) % 3]].data.point;
      const Eigen::Vector3d& q2 = m_vertices[t.v[(r->corner + 2) % 3]].data.point;
      const Eigen::Vector3d before = (q1 - old_point).cross(q2 - old_point);
      const Eigen::Vector3d after = (q1 - p).cross(q2 - p);
      const double after_norm = after.norm();
      const double before_norm = before.norm();
      const double after_shape = shape(after_norm, p, q1, q2);
      if (after_shape < kMinimumFaceShape && after_shape < shape(before_norm, old_point, q1, q2))
        return true;
      if (before_norm > 0 && !(after.dot(before) > m_cos_max_angle * after_norm * before_norm))
        return true;
    }
    return false;
  }

  // The collapse of t's edge from `corner`, unless a check refuses it.
  bool try_collapse(std::size_t triangle, int corner) {
    const int a = m_triangles[triangle].v[corner];
    const int b = m_triangles[triangle].v[(corner + 1) % 3];
    Eigen::Vector3d p;
    const double error = edge_error(a, b, triangle, p);
    if (!std::isfinite(error)) return false;  // refused: a locked end, or the seam rules
    if (!satisfies_link_condition(a, b) || turns_too_far(a, b, p) || turns_too_far(b, a, p))
      return false;
    if (carries_values() && !plan_corner_values(a, b, p)) return false;

    merge(a, b, p);
    if (carries_values()) apply_planned_corner_values(a);
    // Errors after the whole star is rewired: the seam tests look across its edges.
    refresh_star_errors(a);
    return true;
  }

  // b into a, which moves to p: the triangles on their edge go, a takes b's others.
  void merge(int a, int b, const Eigen::Vector3d& p) {
    Vertex& va = m_vertices[a];
    Vertex& vb = m_vertices[b];
    va.data.point = p;
    va.data.quadric += vb.data.quadric;
    va.data.border = va.data.border || vb.data.border;
    vb.removed = true;
    const int first = int(m_references.size());
    for (int from : {a, b}) {
      // Indices, not pointers: push_back below may move m_references.
      const int begin = m_vertices[from].first_reference;
      const int end = begin + m_vertices[from].reference_count;
      for (int i = begin; i < end; ++i) {
        const Reference r = m_references[i];
        Triangle& t = m_triangles[r.triangle];
        if (t.deleted) continue;
        if (contains(t, a) && contains(t, b)) {
          t.deleted = true;
          --m_live_triangles;
          continue;
        }
        t.v[r.corner] = a;
        t.dirty = true;
        m_references.push_back(r);
      }
    }
    va.first_reference = first;
    va.reference_count = int(m_references.size()) - first;
  }

  // m_planned into the merged vertex a's corners; the seam counts around it are forgotten.
  void apply_planned_corner_values(int a) {
    for (const Planned_corner& planned : m_planned)
      m_corners[planned.triangle][planned.corner] = planned.values;
    for (const Reference* r = references_begin(a); r != references_end(a); ++r)
      for (int v : m_triangles[r->triangle].v) m_seam_counts[v] = kUnknownSeams;
  }

  void refresh_star_errors(int a) {
    m_star_errors.clear();
    for (const Reference* r = references_begin(a); r != references_end(a); ++r)
      refresh_corner(std::size_t(r->triangle), r->corner);
  }

  // The triangle other than `t` on the edge of u and w, or -1 on a border.
  int other_triangle(std::size_t t, int u, int w) const {
    for (const Reference* r = references_begin(u); r != references_end(u); ++r)
      if (std::size_t(r->triangle) != t && !m_triangles[r->triangle].deleted &&
          contains(m_triangles[r->triangle], w))
        return r->triangle;
    return -1;
  }

  static int corner_of(const Triangle& t, int v) { return t.v[0] == v ? 0 : t.v[1] == v ? 1 : 2; }

  // Whether the two sides of the edge of u and w (of triangle t) disagree at either end, or it is a
  // border: a seam edge.
  bool is_seam_edge(std::size_t t, int u, int w) const {
    const int other = other_triangle(t, u, w);
    if (other < 0) return true;
    const Triangle &here = m_triangles[t], &there = m_triangles[std::size_t(other)];
    for (int v : {u, w})
      if (!Corners::same(m_corners[t][corner_of(here, v)],
                         m_corners[std::size_t(other)][corner_of(there, v)]))
        return true;
    return false;
  }

  // Remembered per vertex, forgotten around each collapse.
  std::size_t seam_count(int v) {
    int& count = m_seam_counts[v];
    if (count != kUnknownSeams) return std::size_t(count);
    count = 0;
    for (const Reference* r = references_begin(v); r != references_end(v); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted) continue;
      // Each edge at v leaves v in one triangle, but a border edge may only enter it.
      const int next = t.v[(r->corner + 1) % 3], previous = t.v[(r->corner + 2) % 3];
      count += is_seam_edge(std::size_t(r->triangle), v, next) ? 1 : 0;
      count += other_triangle(std::size_t(r->triangle), previous, v) < 0 ? 1 : 0;
    }
    return std::size_t(count);
  }

  // Whether a triangle on the edge of a and b has its two other edges on seams.
  bool closes_chart(int a, int b) const {
    for (const Reference* r = references_begin(a); r != references_end(a); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted || !contains(t, b)) continue;
      const int c = t.v[0] != a && t.v[0] != b   ? t.v[0]
                    : t.v[1] != a && t.v[1] != b ? t.v[1]
                                                 : t.v[2];
      const std::size_t at = std::size_t(r->triangle);
      if (is_seam_edge(at, a, c) && is_seam_edge(at, b, c)) return true;
    }
    return false;
  }

  // m_planned: the values each corner at a or b takes when they merge at p, interpolated at the
  // closest point of the old triangles on its own side of the seams. False when a texture
  // triangle would turn over or become flat.
  bool plan_corner_values(int a, int b, const Eigen::Vector3d& p) {
    m_planned.clear();
    collect_star(a, b);
    join_sides(a, b);
    for (std::size_t i = 0; i < m_star.size(); ++i) {
      const std::size_t t = std::size_t(m_star[i].triangle);
      if (contains(m_triangles[t], a) && contains(m_triangles[t], b)) continue;  // it goes
      const int c = m_star[i].corner;
      const std::size_t side = side_of(i);
      const Values value = value_at(p, [&](std::size_t k) { return side_of(k) == side; });
      const std::array<Values, 3>& old = m_corners[t];
      const double before = Corners::uv_area(old[c], old[(c + 1) % 3], old[(c + 2) % 3]);
      const double after = Corners::uv_area(value, old[(c + 1) % 3], old[(c + 2) % 3]);
      if (std::isfinite(before) && before != 0 && !(before * after > 0)) return false;
      m_planned.push_back({t, c, value});
    }
    return true;
  }

  // m_star: a's live triangles, then b's others.
  void collect_star(int a, int b) {
    m_star.clear();
    for (int v : {a, b})
      for (const Reference* r = references_begin(v); r != references_end(v); ++r)
        if (!m_triangles[r->triangle].deleted && (v == a || !contains(m_triangles[r->triangle], a)))
          m_star.push_back(*r);
  }

  // The sides: triangles joined across the edges at a or b that are not seams, as sets of
  // m_star's indices in m_sides.
  void join_sides(int a, int b) {
    m_sides.resize(m_star.size());
    for (std::size_t i = 0; i < m_star.size(); ++i) m_sides[i] = i;
    for (std::size_t i = 0; i < m_star.size(); ++i) {
      const std::size_t t = std::size_t(m_star[i].triangle);
      for (int j = 0; j < 3; ++j) {
        const int u = m_triangles[t].v[j], w = m_triangles[t].v[(j + 1) % 3];
        if ((u != a && u != b && w != a && w != b) || is_seam_edge(t, u, w)) continue;
        const int other = other_triangle(t, u, w);
        for (std::size_t k = 0; k < m_star.size(); ++k)
          if (m_star[k].triangle == other) m_sides[side_of(i)] = side_of(k);
      }
    }
  }

  // The representative of m_star[i]'s side.
  std::size_t side_of(std::size_t i) {
    while (m_sides[i] != i) i = m_sides[i] = m_sides[m_sides[i]];
    return i;
  }

  // The corner values at the point closest to p of the star's triangles that `in_side` takes.
  template <class In_side>
  Values value_at(const Eigen::Vector3d& p, const In_side& in_side) const {
    const auto triangle = [&](std::size_t k) { return std::size_t(m_star[k].triangle); };
    const Nearest_triangle_point nearest =
        nearest_triangle_point(p, m_star.size(), in_side, [&](std::size_t k) {
          const auto& v = m_triangles[triangle(k)].v;
          return std::array<Eigen::Vector3d, 3>{m_vertices[v[0]].data.point,
                                                m_vertices[v[1]].data.point,
                                                m_vertices[v[2]].data.point};
        });
    return values_at_weights<Corners>(m_corners[triangle(nearest.triangle)], nearest.weights);
  }

  // Drops deleted triangles and rebuilds the reference lists (a counting sort).
  void compact() {
    std::size_t kept = 0;
    for (std::size_t t = 0; t < m_triangles.size(); ++t) {
      if (m_triangles[t].deleted) continue;
      m_triangles[kept] = m_triangles[t];
      if (carries_values()) {
        m_corners[kept] = m_corners[t];
        m_origins[kept] = m_origins[t];
      }
      ++kept;
    }
    m_triangles.resize(kept);
    if (carries_values()) {
      m_corners.resize(kept);
      m_origins.resize(kept);
    }
    for (Vertex& v : m_vertices) v.reference_count = 0;
    for (const Triangle& t : m_triangles)
      for (int v : t.v) ++m_vertices[v].reference_count;
    int first = 0;
    for (Vertex& v : m_vertices) {
      v.first_reference = first;
      first += v.reference_count;
      v.reference_count = 0;
    }
    m_references.resize(std::size_t(first));
    for (std::size_t t = 0; t < m_triangles.size(); ++t)
      for (int j = 0; j < 3; ++j) {
        Vertex& v = m_vertices[m_triangles[t].v[j]];
        m_references[std::size_t(v.first_reference + v.reference_count++)] = {int(t), j};
      }
  }

  std::vector<Vertex> m_vertices;
  std::vector<Triangle> m_triangles;
  std::vector<Reference> m_references;
  std::vector<std::pair<int, double>> m_star_errors;  // refresh_corner's, for one collapse
  // With corner values (set_corner_values): per triangle, its values and its first index; per
  // vertex, the seam edges at it (kUnknownSeams until asked); and one collapse's star, its sides
  // and the new values.
  static constexpr int kUnknownSeams = -1;
  struct Planned_corner {
    std::size_t triangle;
    int corner;
    Values values;
  };
  std::vector<std::array<Values, 3>> m_corners;
  std::vector<int> m_origins;
  std::vector<int> m_seam_counts;
  std::vector<Reference> m_star;
  std::vector<std::size_t> m_sides;
  std::vector<Planned_corner> m_planned;
  std::vector<double> m_scratch;  // level_cap's buffer, kept between passes
  std::vector<unsigned> m_mark;   // m_stamp where a vertex neighbours the edge being checked
  unsigned m_stamp = 0;
  std::size_t m_live_triangles = 0;
  double m_squared_diagonal;
  Fast_threshold_options m_options;  // simplify()'s
  double m_cos_max_angle = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
