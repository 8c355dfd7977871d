// The flat-array engine of Fast_threshold_simplifier ([Hu14] §2.2; docs/fast.md): threshold
// passes over triangles that store their edges' errors, with the checks the report lacks.
#ifndef CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
#define CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H

#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

struct Fast_threshold_settings {
  double aggressiveness = 7;  // a in t_k = 1e-9 (k + 3)^a D^2; larger is faster and coarser
  bool lossless = false;      // only collapses whose error is zero up to round-off
  double max_normal_angle_deg = 90;
  std::size_t compaction_period = 5;  // passes between two rebuilds of the reference lists
};

struct Fast_threshold_vertex {
  Eigen::Vector3d point;
  Quadric quadric;  // face planes plus border planes (docs/quadric_core.md)
  bool border = false;
};

class Fast_threshold_engine {
 public:
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

  struct Outcome {
    std::size_t passes = 0;
    bool target_reached = false;
  };

  Outcome simplify(std::size_t target_faces, const Fast_threshold_settings& settings,
                   const std::function<void(std::size_t)>& on_progress = {}) {
    CGAL_precondition(settings.aggressiveness > 0 && settings.compaction_period > 0);
    m_cos_max_angle = std::cos(settings.max_normal_angle_deg * (std::acos(-1.0) / 180.0));
    for (Triangle& t : m_triangles) compute_errors(t);

    Outcome outcome;
    double k = 0;  // a double: empty passes are skipped by jumping k
    for (std::size_t pass = 0;; ++pass) {
      if (m_live_triangles <= target_faces) {
        outcome.target_reached = true;
        break;
      }
      if (pass % settings.compaction_period == 0) compact();
      for (Triangle& t : m_triangles) t.dirty = false;
      const double threshold =
          settings.lossless
              ? kLosslessTolerance * m_squared_diagonal
              : kThresholdScale * std::pow(k + 3, settings.aggressiveness) * m_squared_diagonal;
      const double level =
          settings.lossless ? std::numeric_limits<double>::infinity() : open_error_quantile();

      std::size_t collapses = 0;
      bool held_back = false;  // some triangle below t_k waited for a higher level
      double smallest_waiting = std::numeric_limits<double>::infinity();
      const std::size_t count = m_triangles.size();  // triangles appended later are not new
      for (std::size_t t = 0; t < count && m_live_triangles > target_faces; ++t) {
        const Triangle& triangle = m_triangles[t];
        if (triangle.deleted || triangle.dirty) continue;
        if (!(triangle.min_error < threshold)) {
          smallest_waiting = (std::min)(smallest_waiting, triangle.min_error);
          continue;
        }
        if (!(triangle.min_error <= level)) {
          held_back = true;
          continue;
        }
        bool collapsed = false;
        for (int j = 0; j < 3 && !collapsed; ++j) {
          const double error = m_triangles[t].error[j];
          collapsed = error < threshold && error <= level && try_collapse(t, j);
        }
        // try_collapse leaves t deleted or refuses: then t stays refused until it changes.
        if (collapsed)
          ++collapses;
        else
          m_triangles[t].refused = true;
      }
      outcome.passes = pass + 1;
      if (on_progress) on_progress(m_live_triangles);

      if (collapses == 0 && !held_back) {
        // Idle, nothing held back: jump to the first pass whose threshold exceeds the smallest
        // waiting error, or stop if none waits. (Held back: the level rises, those tries refused.)
        if (settings.lossless || !std::isfinite(smallest_waiting)) break;
        k = (std::max)(k + 1,
                       std::ceil(std::pow(smallest_waiting / (kThresholdScale * m_squared_diagonal),
                                          1.0 / settings.aggressiveness)) -
                           3);
        while (kThresholdScale * std::pow(k + 3, settings.aggressiveness) * m_squared_diagonal <=
               smallest_waiting)
          k += 1;
      } else {
        k += 1;
      }
    }
    compact();
    outcome.target_reached = m_live_triangles <= target_faces;
    return outcome;
  }

  std::size_t face_count() const { return m_live_triangles; }

  void extract(std::vector<Eigen::Vector3d>& points, std::vector<std::array<int, 3>>& triangles) {
    compact();
    std::vector<int> index(m_vertices.size(), -1);
    points.clear();
    for (std::size_t v = 0; v < m_vertices.size(); ++v)
      if (!m_vertices[v].removed) {
        index[v] = int(points.size());
        points.push_back(m_vertices[v].data.point);
      }
    triangles.clear();
    for (const Triangle& t : m_triangles)
      triangles.push_back({index[t.v[0]], index[t.v[1]], index[t.v[2]]});
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

  // With one end on the border, the merged vertex stays at that end.
  double edge_error(int a, int b, Eigen::Vector3d& placement) const {
    const Fast_threshold_vertex& va = m_vertices[a].data;
    const Fast_threshold_vertex& vb = m_vertices[b].data;
    const Quadric q = va.quadric + vb.quadric;
    if (va.border != vb.border)
      placement = va.border ? va.point : vb.point;
    else
      placement = optimal_placement(q, va.point, vb.point).point;
    const double error = q.evaluate(placement);
    return std::isfinite(error) ? (std::max)(0.0, error) : std::numeric_limits<double>::infinity();
  }

  void compute_errors(Triangle& t) {
    Eigen::Vector3d unused;
    for (int j = 0; j < 3; ++j) t.error[j] = edge_error(t.v[j], t.v[(j + 1) % 3], unused);
    t.min_error = (std::min)({t.error[0], t.error[1], t.error[2]});
    t.refused = false;
  }

  // m_star_errors: this collapse's errors by the edge's other end (each edge is in two triangles).
  void refresh_corner(Triangle& t, int at) {
    for (int j : {at, (at + 2) % 3}) {
      const int other = t.v[j == at ? (at + 1) % 3 : j];
      const auto known = std::find_if(m_star_errors.begin(), m_star_errors.end(),
                                      [other](const auto& e) { return e.first == other; });
      if (known != m_star_errors.end()) {
        t.error[j] = known->second;
      } else {
        Eigen::Vector3d unused;
        t.error[j] = edge_error(t.v[at], other, unused);
        m_star_errors.emplace_back(other, t.error[j]);
      }
    }
    t.min_error = (std::min)({t.error[0], t.error[1], t.error[2]});
    t.refused = false;
  }

  // Refused triangles are left out: cheap but blocked, they would hold the level down for good.
  double open_error_quantile() {
    m_scratch.clear();
    for (const Triangle& t : m_triangles)
      if (!t.deleted && !t.refused) m_scratch.push_back(t.min_error);
    if (m_scratch.empty()) return std::numeric_limits<double>::infinity();
    const auto at = m_scratch.begin() + std::ptrdiff_t(kPassShare * double(m_scratch.size() - 1));
    std::nth_element(m_scratch.begin(), at, m_scratch.end());
    return *at;
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

  // The link condition [Dey99], borders closed by a virtual vertex as in CGAL's
  // Euler::does_satisfy_link_condition; also no emptied component, no faces glued back to back.
  bool satisfies_link_condition(int a, int b) {
    if (++m_stamp == 0) {  // wrapped: clear the stale marks once
      std::fill(m_mark.begin(), m_mark.end(), 0);
      m_stamp = 1;
    }
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
    int a_with_opposite = 0, a_with_both = 0;
    for (const Reference* r = references_begin(a); r != references_end(a); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted) continue;
      m_mark[t.v[(r->corner + 1) % 3]] = m_stamp;
      m_mark[t.v[(r->corner + 2) % 3]] = m_stamp;
      a_with_opposite += contains(t, opposite[0]);
      a_with_both += !border_edge && contains(t, opposite[0]) && contains(t, opposite[1]);
    }
    int b_with_opposite = 0, b_with_both = 0;
    for (const Reference* r = references_begin(b); r != references_end(b); ++r) {
      const Triangle& t = m_triangles[r->triangle];
      if (t.deleted) continue;
      for (int w : {t.v[(r->corner + 1) % 3], t.v[(r->corner + 2) % 3]})
        if (w != a && m_mark[w] == m_stamp && w != opposite[0] && (border_edge || w != opposite[1]))
          return false;
      b_with_opposite += contains(t, opposite[0]);
      b_with_both += !border_edge && contains(t, opposite[0]) && contains(t, opposite[1]);
    }
    // A lone triangle: its three edges are border edges.
    if (border_edge && a_with_opposite == 1 && b_with_opposite == 1) return false;
    return !(a_with_both > 0 && b_with_both > 0);
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

  bool try_collapse(std::size_t triangle, int corner) {
    const int a = m_triangles[triangle].v[corner];
    const int b = m_triangles[triangle].v[(corner + 1) % 3];
    Eigen::Vector3d p;
    edge_error(a, b, p);
    if (!satisfies_link_condition(a, b) || turns_too_far(a, b, p) || turns_too_far(b, a, p))
      return false;

    Vertex& va = m_vertices[a];
    Vertex& vb = m_vertices[b];
    va.data.point = p;
    va.data.quadric += vb.data.quadric;
    va.data.border = va.data.border || vb.data.border;
    vb.removed = true;
    const int first = int(m_references.size());
    m_star_errors.clear();
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
        refresh_corner(t, r.corner);
        m_references.push_back(r);
      }
    }
    va.first_reference = first;
    va.reference_count = int(m_references.size()) - first;
    return true;
  }

  // Drops deleted triangles and rebuilds the reference lists (a counting sort).
  void compact() {
    m_triangles.erase(std::remove_if(m_triangles.begin(), m_triangles.end(),
                                     [](const Triangle& t) { return t.deleted; }),
                      m_triangles.end());
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
  std::vector<double> m_scratch;  // open_error_quantile's buffer, kept between passes
  std::vector<unsigned> m_mark;   // m_stamp where a vertex neighbours the edge being checked
  unsigned m_stamp = 0;
  std::size_t m_live_triangles = 0;
  double m_squared_diagonal;
  double m_cos_max_angle = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FAST_THRESHOLD_ENGINE_H
