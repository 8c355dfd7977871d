// Flat_collapse_mesh: a triangle mesh on flat arrays for the engines that collapse edges there
// (Fast_threshold_engine, Lindstrom_turk_engine): the vertices with a slice each of a shared list
// of references to their triangles, the checks a collapse must pass (link condition, flip and
// sliver guard, seam rules), and the collapse itself, carrying the corner values (docs/fast.md,
// docs/flat_lt.md).
#ifndef CGAL_POLICIES_INTERNAL_FLAT_COLLAPSE_MESH_H
#define CGAL_POLICIES_INTERNAL_FLAT_COLLAPSE_MESH_H

#include <cgal_policies/internal/nearest_corner_values.h>
#include <cgal_policies/internal/seam_collapse_rule.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// No corner values: the engines move points only.
struct No_corner_values {
  struct Values {};
  static Values blend(const std::array<Values, 3>&, const std::array<double, 3>&) { return {}; }
  static bool same(const Values&, const Values&) { return true; }
  static double uv_area(const Values&, const Values&, const Values&) { return 0; }
};

// Corners: the values a triangle holds at its corners (Values), how they blend at barycentric
// weights, when two are the same, and the signed area of their texture triangle (NaN without
// texture coordinates), as No_corner_values spells them. Vertex_data has `point`, `border` and
// `locked` (never moved nor removed: the cut vertices of a partitioned run); Triangle has
// `std::array<int, 3> v` and `bool deleted`, and whatever else its engine keeps per triangle.
template <class Corners, class Vertex_data, class Triangle>
class Flat_collapse_mesh {
 public:
  using Values = typename Corners::Values;

  // Twice the area over the squared longest edge (sqrt(3)/2 when equilateral) below which a face
  // has no reliable normal: no collapse makes one, or a thinner one (docs/fast.md, "Sliver guard").
  static constexpr double kMinimumFaceShape = 1e-6;

  struct Reference {
    int triangle;
    int corner;  // the vertex's position in the triangle
  };

  // Precondition: every triangle has three distinct vertex indices in range.
  Flat_collapse_mesh(std::vector<Vertex_data> vertices, std::vector<Triangle> triangles)
      : m_triangles(std::move(triangles)) {
    m_vertices.reserve(vertices.size());
    for (Vertex_data& v : vertices) m_vertices.push_back({0, 0, 0, false, std::move(v)});
    CGAL_precondition(std::all_of(m_triangles.begin(), m_triangles.end(), [](const Triangle& t) {
      return !t.deleted && t.v[0] != t.v[1] && t.v[1] != t.v[2] && t.v[2] != t.v[0];
    }));
    m_live_triangles = m_triangles.size();
    compact();
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

  bool carries_values() const { return !m_corners.empty(); }
  std::size_t live_triangles() const { return m_live_triangles; }
  std::size_t vertex_count() const { return m_vertices.size(); }
  // References, live or not: each collapse adds its kept vertex's anew.
  std::size_t reference_count() const { return m_references.size(); }

  Vertex_data& vertex(int v) { return m_vertices[std::size_t(v)].data; }
  const Vertex_data& vertex(int v) const { return m_vertices[std::size_t(v)].data; }
  const Eigen::Vector3d& point(int v) const { return vertex(v).point; }
  bool removed(int v) const { return m_vertices[std::size_t(v)].removed; }
  std::vector<Triangle>& triangles() { return m_triangles; }
  const std::vector<Triangle>& triangles() const { return m_triangles; }

  // v's references, deleted triangles among them until the next compact().
  const Reference* references_begin(int v) const {
    return m_references.data() + m_vertices[std::size_t(v)].first_reference;
  }
  const Reference* references_end(int v) const {
    return references_begin(v) + m_vertices[std::size_t(v)].reference_count;
  }

  static bool contains(const Triangle& t, int v) {
    return t.v[0] == v || t.v[1] == v || t.v[2] == v;
  }

  // Whether no live triangle but t has the edge of u and w.
  bool is_border_edge(std::size_t t, int u, int w) const { return other_triangle(t, u, w) < 0; }

  // Where the seam rules put the merged vertex of a and b, an edge of triangle `on`, given the
  // policy's point; false when they refuse the collapse. Without corner values: the point as is.
  bool place_by_seams(int a, int b, std::size_t on, Eigen::Vector3d& placement) {
    if (!carries_values()) return true;
    const Eigen::Vector3d &pa = point(a), &pb = point(b);
    switch (seam_collapse_rule(
        seam_count(a), seam_count(b), [&] { return is_seam_edge(on, a, b); },
        [&] { return closes_chart(a, b); },
        [&] { return (placement - pa).squaredNorm() < (placement - pb).squaredNorm(); })) {
      case Seam_placement::anywhere:
        return true;
      case Seam_placement::at_first:
        placement = pa;
        return true;
      case Seam_placement::at_second:
        placement = pb;
        return true;
      case Seam_placement::nowhere:
        return false;
    }
    return false;
  }

  // The link condition [Dey99], borders closed by a virtual vertex as in CGAL's
  // Euler::does_satisfy_link_condition; also no emptied component, no faces glued back to back.
  bool satisfies_link_condition(int a, int b) {
    next_stamp();
    int opposite[2];
    int opposite_count = 0;
    for (const Reference* r = references_begin(b); r != references_end(b); ++r) {
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
      if (t.deleted || !contains(t, a)) continue;
      if (opposite_count == 2) return false;  // a non-manifold edge
      opposite[opposite_count++] =
          t.v[(r->corner + 1) % 3] == a ? t.v[(r->corner + 2) % 3] : t.v[(r->corner + 1) % 3];
    }
    if (opposite_count == 0) return false;
    const bool border_edge = opposite_count == 1;
    if (!border_edge && (opposite[0] == opposite[1] || (vertex(a).border && vertex(b).border)))
      return false;

    // Mark a's neighbours; count a's triangles that hold an opposite vertex (2 unless the edge
    // from a to it is a border edge) or both opposite vertices (a tetrahedron corner).
    Opposite_counts at_a, at_b;
    for (const Reference* r = references_begin(a); r != references_end(a); ++r) {
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
      if (t.deleted) continue;
      mark(t.v[(r->corner + 1) % 3]);
      mark(t.v[(r->corner + 2) % 3]);
      at_a.count(t, opposite, border_edge);
    }
    for (const Reference* r = references_begin(b); r != references_end(b); ++r) {
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
      if (t.deleted) continue;
      for (int w : {t.v[(r->corner + 1) % 3], t.v[(r->corner + 2) % 3]})
        if (w != a && marked(w) && w != opposite[0] && (border_edge || w != opposite[1]))
          return false;
      at_b.count(t, opposite, border_edge);
    }
    // A lone triangle: its three edges are border edges.
    if (border_edge && at_a.with_opposite == 1 && at_b.with_opposite == 1) return false;
    return !(at_a.with_both > 0 && at_b.with_both > 0);
  }

  // Whether moving `moved` to p turns a triangle around it without `other` by the angle whose
  // cosine is cos_max_angle or more, or thins it below kMinimumFaceShape; a face already
  // degenerate blocks nothing.
  bool turns_too_far(int moved, int other, const Eigen::Vector3d& p, double cos_max_angle) const {
    const Eigen::Vector3d& old_point = point(moved);
    for (const Reference* r = references_begin(moved); r != references_end(moved); ++r) {
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
      if (t.deleted || contains(t, other)) continue;
      const Eigen::Vector3d& q1 = point(t.v[(r->corner + 1) % 3]);
      const Eigen::Vector3d& q2 = point(t.v[(r->corner + 2) % 3]);
      const Eigen::Vector3d before = (q1 - old_point).cross(q2 - old_point);
      const Eigen::Vector3d after = (q1 - p).cross(q2 - p);
      const double after_norm = after.norm();
      const double before_norm = before.norm();
      const double after_shape = shape(after_norm, p, q1, q2);
      if (after_shape < kMinimumFaceShape && after_shape < shape(before_norm, old_point, q1, q2))
        return true;
      if (before_norm > 0 && !(after.dot(before) > cos_max_angle * after_norm * before_norm))
        return true;
    }
    return false;
  }

  // m_planned: the values each corner at a or b takes when they merge at p, interpolated at the
  // closest point of the old triangles on its own side of the seams. False when a texture
  // triangle would turn over or become flat. Call before collapse(); true without corner values.
  bool plan_corner_values(int a, int b, const Eigen::Vector3d& p) {
    if (!carries_values()) return true;
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

  // b into a, which moves to p: the triangles on their edge go, a takes b's others, and each of
  // them is handed to on_rewired; with corner values, those plan_corner_values() planned.
  template <class On_rewired>
  void collapse(int a, int b, const Eigen::Vector3d& p, const On_rewired& on_rewired) {
    Vertex& va = m_vertices[std::size_t(a)];
    Vertex& vb = m_vertices[std::size_t(b)];
    va.data.point = p;
    va.data.border = va.data.border || vb.data.border;
    vb.removed = true;
    const int first = int(m_references.size());
    for (int from : {a, b}) {
      // Indices, not pointers: push_back below may move m_references.
      const int begin = m_vertices[std::size_t(from)].first_reference;
      const int end = begin + m_vertices[std::size_t(from)].reference_count;
      for (int i = begin; i < end; ++i) {
        const Reference r = m_references[std::size_t(i)];
        Triangle& t = m_triangles[std::size_t(r.triangle)];
        if (t.deleted) continue;
        if (contains(t, a) && contains(t, b)) {
          t.deleted = true;
          --m_live_triangles;
          continue;
        }
        t.v[r.corner] = a;
        on_rewired(t);
        m_references.push_back(r);
      }
    }
    va.first_reference = first;
    va.reference_count = int(m_references.size()) - first;
    if (carries_values()) apply_planned_corner_values(a);
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
      for (int v : t.v) ++m_vertices[std::size_t(v)].reference_count;
    int first = 0;
    for (Vertex& v : m_vertices) {
      v.first_reference = first;
      first += v.reference_count;
      v.reference_count = 0;
    }
    m_references.resize(std::size_t(first));
    for (std::size_t t = 0; t < m_triangles.size(); ++t)
      for (int j = 0; j < 3; ++j) {
        Vertex& v = m_vertices[std::size_t(m_triangles[t].v[j])];
        m_references[std::size_t(v.first_reference + v.reference_count++)] = {int(t), j};
      }
  }

  // The live points and triangles; with corner values, `corners` and `origins` (the
  // constructor's index of each triangle) too; `kept`, when given, gets the constructor's index of
  // each point.
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
      triangles.push_back(
          {index[std::size_t(t.v[0])], index[std::size_t(t.v[1])], index[std::size_t(t.v[2])]});
    if (corners) *corners = m_corners;
    if (origins) *origins = m_origins;
  }

  // A new stamp, which no vertex's mark holds yet; mark() and marked() use it.
  void next_stamp() {
    if (++m_stamp == 0) {  // wrapped: clear the stale marks once
      for (Vertex& v : m_vertices) v.mark = 0;
      m_stamp = 1;
    }
  }
  void mark(int v) { m_vertices[std::size_t(v)].mark = m_stamp; }
  bool marked(int v) const { return m_vertices[std::size_t(v)].mark == m_stamp; }

 private:
  // The bookkeeping first, then the engine's data, whose point comes first: the link condition's
  // marks then bring in the cache line of the point that the flip guard reads next.
  struct Vertex {
    int first_reference;  // its triangles are m_references[first, first + count)
    int reference_count;
    unsigned mark;  // m_stamp when marked
    bool removed;   // merged into another vertex
    Vertex_data data;
  };

  // A vertex's triangles that hold the first vertex opposite an edge, and those that hold both.
  struct Opposite_counts {
    int with_opposite = 0, with_both = 0;
    void count(const Triangle& t, const int (&opposite)[2], bool border_edge) {
      with_opposite += contains(t, opposite[0]);
      with_both += !border_edge && contains(t, opposite[0]) && contains(t, opposite[1]);
    }
  };

  static double shape(double twice_area, const Eigen::Vector3d& p, const Eigen::Vector3d& q1,
                      const Eigen::Vector3d& q2) {
    const double longest =
        (std::max)({(q1 - p).squaredNorm(), (q2 - p).squaredNorm(), (q2 - q1).squaredNorm()});
    return longest > 0 ? twice_area / longest : 0.0;
  }

  // m_planned into the merged vertex a's corners; the seam counts around it are forgotten.
  void apply_planned_corner_values(int a) {
    for (const Planned_corner& planned : m_planned)
      m_corners[planned.triangle][std::size_t(planned.corner)] = planned.values;
    for (const Reference* r = references_begin(a); r != references_end(a); ++r)
      for (int v : m_triangles[std::size_t(r->triangle)].v)
        m_seam_counts[std::size_t(v)] = kUnknownSeams;
  }

  // The triangle other than `t` on the edge of u and w, or -1 on a border.
  int other_triangle(std::size_t t, int u, int w) const {
    for (const Reference* r = references_begin(u); r != references_end(u); ++r)
      if (std::size_t(r->triangle) != t && !m_triangles[std::size_t(r->triangle)].deleted &&
          contains(m_triangles[std::size_t(r->triangle)], w))
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
      if (!Corners::same(m_corners[t][std::size_t(corner_of(here, v))],
                         m_corners[std::size_t(other)][std::size_t(corner_of(there, v))]))
        return true;
    return false;
  }

  // Remembered per vertex, forgotten around each collapse.
  std::size_t seam_count(int v) {
    int& count = m_seam_counts[std::size_t(v)];
    if (count != kUnknownSeams) return std::size_t(count);
    count = 0;
    for (const Reference* r = references_begin(v); r != references_end(v); ++r) {
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
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
      const Triangle& t = m_triangles[std::size_t(r->triangle)];
      if (t.deleted || !contains(t, b)) continue;
      const int c = t.v[0] != a && t.v[0] != b   ? t.v[0]
                    : t.v[1] != a && t.v[1] != b ? t.v[1]
                                                 : t.v[2];
      const std::size_t at = std::size_t(r->triangle);
      if (is_seam_edge(at, a, c) && is_seam_edge(at, b, c)) return true;
    }
    return false;
  }

  // m_star: a's live triangles, then b's others.
  void collect_star(int a, int b) {
    m_star.clear();
    for (int v : {a, b})
      for (const Reference* r = references_begin(v); r != references_end(v); ++r)
        if (!m_triangles[std::size_t(r->triangle)].deleted &&
            (v == a || !contains(m_triangles[std::size_t(r->triangle)], a)))
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
          return std::array<Eigen::Vector3d, 3>{point(v[0]), point(v[1]), point(v[2])};
        });
    return values_at_weights<Corners>(m_corners[triangle(nearest.triangle)], nearest.weights);
  }

  std::vector<Vertex> m_vertices;
  std::vector<Triangle> m_triangles;
  std::vector<Reference> m_references;
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
  unsigned m_stamp = 0;
  std::size_t m_live_triangles = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FLAT_COLLAPSE_MESH_H
