// Carries the corner attributes of a CGAL::Surface_mesh (Corner_attributes.h: texture coordinates,
// both sets, normals, colours and skin influences) through edge collapses, and keeps their seams.
//
// A seam edge is one whose two sides disagree at either end, or a border edge (an open chart stays
// open). A vertex on no seam edge is free; on exactly two it lies along a seam; on one or three and
// more it is a seam corner. The rules, checked before a collapse:
// - free + free: anywhere the policy proposes;
// - free + seam: at the seam vertex, so the seam does not move;
// - seam + seam: only along a seam edge, removing a vertex that lies along the seam and keeping the
//   other one where it is (two seam corners never merge), and never when a triangle on the edge has
//   its other two edges on seams too (its chart would vanish);
// - no texture triangle of the new star changes its orientation.
// The new corner values around the kept vertex are interpolated at its new point on the old star,
// one side of each seam at a time: each corner takes the value at the closest point of the faces it
// can reach around the two old vertices without crossing a seam edge. A policy that solves the
// values itself (Solver) gives them for collapses between two free vertices. A policy whose filter
// picks the point itself among several (Hausdorff_bounded_policies) asks allows() of each, and the
// values are interpolated at the point the filter accepted (accepted()), wherever CGAL puts the
// vertex first.
#ifndef CGAL_POLICIES_CORNER_ATTRIBUTE_CARRIER_H
#define CGAL_POLICIES_CORNER_ATTRIBUTE_CARRIER_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/nearest_corner_values.h>
#include <cgal_policies/internal/seam_collapse_rule.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

namespace cgal_policies {

template <class Point>
class Corner_attribute_carrier {
 public:
  using Mesh = CGAL::Surface_mesh<Point>;
  using Attributes = Corner_attributes<Point>;
  using Uv = typename Attributes::Uv;
  using Values = typename Attributes::Values;
  using Vertex = typename Mesh::Vertex_index;
  using Halfedge = typename Mesh::Halfedge_index;
  using Face = typename Mesh::Face_index;

  // A policy that solves the kept vertex's values itself (Attribute_quadric_policies): it gives
  // the values of a collapse between two free vertices, at the new point (the other collapses keep
  // their old seam values; a value it leaves NaN, or does not give, is interpolated), and hears of
  // each collapse before it happens.
  struct Solver {
    std::function<void(Halfedge edge, const Point& x, Values& values)> free_collapse_values;
    std::function<void(Halfedge edge)> before_collapse;
  };

  explicit Corner_attribute_carrier(Mesh& mesh) : m_mesh(&mesh), m_attributes(mesh) {}

  // Whether the mesh has corner values to carry.
  bool active() const { return m_attributes.any_corner_values(); }

  void solve_with(Solver solver) { m_solver = std::move(solver); }
  const Attributes& attributes() const { return m_attributes; }

  // Where the collapse of the profile's edge may put the kept vertex: `proposed`, the point of a
  // seam vertex, or nowhere.
  // Throws std::logic_error before started(): the collapses of a run whose visitor does not feed
  // the carrier (Attribute_carrying_visitor.h) would leave every corner value behind.
  template <class Profile>
  std::optional<Point> seam_placement(const Profile& profile, const Point& proposed) const {
    require_started();
    const Halfedge edge = profile.v0_v1();
    const auto closes_chart = [&] {
      for (Halfedge h : {edge, m_mesh->opposite(edge)})
        if (!m_mesh->is_border(h) && is_seam_edge(m_mesh->next(h)) && is_seam_edge(m_mesh->prev(h)))
          return true;
      return false;
    };
    switch (internal::seam_collapse_rule(
        seam_edges_for_rules(profile.v0()), seam_edges_for_rules(profile.v1()),
        [&] { return is_seam_edge(edge); }, closes_chart,
        [&] {
          return CGAL::squared_distance(proposed, profile.p0()) <
                 CGAL::squared_distance(proposed, profile.p1());
        })) {
      case internal::Seam_placement::anywhere:
        return proposed;
      case internal::Seam_placement::at_first:
        return profile.p0();
      case internal::Seam_placement::at_second:
        return profile.p1();
      case internal::Seam_placement::nowhere:
        break;
    }
    return std::nullopt;
  }

  // Whether the collapse of `edge` (its source into its target) may put the kept vertex at x: where
  // the seam rules put it, turning no texture triangle over.
  bool allows(Halfedge edge, const Point& x) const {
    const Edge_view view{m_mesh, edge};
    const std::optional<Point> allowed = seam_placement(view, x);
    return allowed && *allowed == x && keeps_uv_orientation(view, x);
  }

  // The filter accepted the collapse of the profile's edge at x: its values are interpolated there.
  template <class Profile>
  void accepted(const Profile& profile, const Point& x) const {
    m_accepted = Accepted_collapse{profile.v0_v1(), x};
  }

  // False when the collapse to `placement` turns a texture triangle over or makes it flat.
  template <class Profile>
  bool keeps_uv_orientation(const Profile& profile, const Point& placement) const {
    if (!m_attributes.uvs) return true;
    const auto& uvs = *m_attributes.uvs;
    for (const Corner_value& value : corner_values_of(profile, placement)) {
      const Halfedge h = value.corner;
      const Uv& b = uvs[m_mesh->next(h)];
      const Uv& c = uvs[m_mesh->prev(h)];
      const double before = Attributes::uv_area(uvs[h], b, c),
                   after = Attributes::uv_area(value.values.uv, b, c);
      if (std::isfinite(before) && before != 0 && !(before * after > 0)) return false;
    }
    return true;
  }

  // Before the collapse: the values the corners around the kept vertex will take, and those of
  // the other corners of their faces (the collapse may hand a face the halfedge of a face it
  // removes, so every corner of the star is written again afterwards).
  template <class Profile>
  void collapsing(const Profile& profile, const Point& placement) {
    if (m_solver.before_collapse) m_solver.before_collapse(profile.v0_v1());
    m_unmoved.clear();  // the zero-length collapses are over
    m_pending.clear();
    const Point x =
        m_accepted && m_accepted->edge == profile.v0_v1() ? m_accepted->point : placement;
    m_accepted.reset();
    for (const Corner_value& value : corner_values_of(profile, x)) {
      const Halfedge h = value.corner, b = m_mesh->next(h), c = m_mesh->prev(h);
      Pending_face pending{value.face,
                           {value, stored_value(b), stored_value(c)},
                           {m_mesh->target(b), m_mesh->target(c)}};
      m_pending.push_back(pending);
    }
  }

  // Before edge_collapse starts. CGAL first collapses every edge of zero length, with no placement,
  // filter or OnCollapsing (Edge_collapse.h, collect()). Such a collapse moves no point, so every
  // face around it keeps its values: they are recorded here and put back by collapsed(). It merges
  // the edges of its two faces, which may leave a seam corner nearby with two seam edges or none;
  // the points of those corners are recorded too, and the seam rules keep them.
  void started() {
    m_started = true;
    m_checked.reset();
    m_unmoved.clear();
    m_corners_near_zero_length_edges.clear();
    for (auto e : m_mesh->edges()) {
      const Halfedge h = m_mesh->halfedge(e);
      if (m_mesh->point(m_mesh->source(h)) != m_mesh->point(m_mesh->target(h))) continue;
      for (Vertex v : {m_mesh->source(h), m_mesh->target(h)}) {
        record_if_seam_corner(v);
        for (Halfedge around : CGAL::halfedges_around_target(v, *m_mesh)) {
          record_if_seam_corner(m_mesh->source(around));
          if (!m_mesh->is_border(around)) record_unmoved(m_mesh->face(around));
        }
      }
    }
  }

  // After the collapse: the corners of the faces around the kept vertex take their values.
  void collapsed(Vertex kept) {
    m_checked.reset();
    forget_seam_edges_around(kept);
    if (m_pending.empty()) {  // a zero-length collapse (started())
      restore_unmoved(kept);
      return;
    }
    for (const Pending_face& pending : m_pending) {
      if (m_mesh->is_removed(pending.face)) continue;
      for (Halfedge h : CGAL::halfedges_around_face(m_mesh->halfedge(pending.face), *m_mesh)) {
        const Vertex v = m_mesh->target(h);
        const Corner_value& value = v == kept                ? pending.corners[0]
                                    : v == pending.others[0] ? pending.corners[1]
                                                             : pending.corners[2];
        m_attributes.set_values(h, value.values);
      }
    }
    m_pending.clear();
  }

  bool is_seam_edge(Halfedge h) const { return m_attributes.is_seam_edge(*m_mesh, h); }

  // The values at the point of `faces` closest to x: a corner's own values when that point is the
  // corner, else the blend at its barycentric weights.
  static Values values_nearest(const Mesh& mesh, const Attributes& attributes,
                               const std::vector<Face>& faces, const Point& x) {
    const auto eigen = [](const Point& q) { return Eigen::Vector3d(q.x(), q.y(), q.z()); };
    const auto corners = [&](std::size_t k) {
      const Halfedge h = mesh.halfedge(faces[k]);
      return std::array<Halfedge, 3>{h, mesh.next(h), mesh.prev(h)};
    };
    const internal::Nearest_triangle_point nearest = internal::nearest_triangle_point(
        eigen(x), faces.size(), [](std::size_t) { return true; },
        [&](std::size_t k) {
          const std::array<Halfedge, 3> c = corners(k);
          return std::array<Eigen::Vector3d, 3>{eigen(mesh.point(mesh.target(c[0]))),
                                                eigen(mesh.point(mesh.target(c[1]))),
                                                eigen(mesh.point(mesh.target(c[2])))};
        });
    const std::array<Halfedge, 3> c = corners(nearest.triangle);
    return internal::values_at_weights<Attributes>(
        std::array<Values, 3>{attributes.values(c[0]), attributes.values(c[1]),
                              attributes.values(c[2])},
        nearest.weights);
  }

  // Remembered per vertex (every collapse asks twice or more), and forgotten around each collapse
  // (collapsed()): only the edges at the kept vertex change.
  std::size_t seam_edges_at(Vertex v) const {
    if (m_seam_counts.size() < m_mesh->num_vertices())
      m_seam_counts.resize(m_mesh->num_vertices(), kUnknown);
    std::size_t& count = m_seam_counts[std::size_t(v)];
    if (count != kUnknown) return count;
    count = 0;
    for (Halfedge h : CGAL::halfedges_around_target(v, *m_mesh)) count += is_seam_edge(h) ? 1 : 0;
    return count;
  }

 private:
  void require_started() const {
    if (!m_started)
      throw std::logic_error(
          "Corner_attribute_carrier: edge_collapse runs without Attribute_carrying_visitor, so "
          "the corner values would not follow the collapses");
  }

  // What a profile of CGAL's gives the rules, for an edge alone.
  struct Edge_view {
    const Mesh* mesh;
    Halfedge edge;
    Halfedge v0_v1() const { return edge; }
    Vertex v0() const { return mesh->source(edge); }
    Vertex v1() const { return mesh->target(edge); }
    const Point& p0() const { return mesh->point(v0()); }
    const Point& p1() const { return mesh->point(v1()); }
  };

  struct Accepted_collapse {
    Halfedge edge;
    Point point;
  };

  struct Corner_value {
    Face face;
    Halfedge corner;  // before the collapse
    Values values;
  };
  struct Pending_face {
    Face face;
    std::array<Corner_value, 3> corners;  // at the kept vertex first
    std::array<Vertex, 2> others;         // the vertices of the other two corners
  };

  Corner_value stored_value(Halfedge h) const {
    return {m_mesh->face(h), h, m_attributes.values(h)};
  }

  static constexpr std::size_t kUnknown = std::numeric_limits<std::size_t>::max();

  void record_if_seam_corner(Vertex v) {
    if (internal::is_seam_corner(seam_edges_at(v)))
      m_corners_near_zero_length_edges.insert(m_mesh->point(v));
  }

  // seam_edges_at(v), but a seam corner near an edge of zero length (started()) stays one.
  std::size_t seam_edges_for_rules(Vertex v) const {
    const std::size_t count = seam_edges_at(v);
    if (internal::is_seam_corner(count) ||
        m_corners_near_zero_length_edges.count(m_mesh->point(v)) == 0)
      return count;
    return 1;  // a seam's end: a corner
  }

  // A face's corners as they were: the vertex of each, and its values.
  struct Face_values {
    std::array<Vertex, 3> vertices;
    std::array<Corner_value, 3> values;
  };

  void record_unmoved(Face f) {
    Face_values recorded;
    std::size_t k = 0;
    for (Halfedge h : CGAL::halfedges_around_face(m_mesh->halfedge(f), *m_mesh)) {
      recorded.vertices[k] = m_mesh->target(h);
      recorded.values[k++] = stored_value(h);
    }
    m_unmoved[f] = recorded;
  }

  // Each face around `kept` takes back the values it had at each of its vertices; its corner at
  // `kept` takes those of the vertex it had there before.
  void restore_unmoved(Vertex kept) {
    for (Halfedge around : CGAL::halfedges_around_target(kept, *m_mesh)) {
      if (m_mesh->is_border(around)) continue;
      const Face f = m_mesh->face(around);
      const auto found = m_unmoved.find(f);
      if (found == m_unmoved.end()) continue;
      const Face_values& recorded = found->second;
      std::array<Vertex, 3> now;
      std::size_t k = 0;
      for (Halfedge h : CGAL::halfedges_around_face(m_mesh->halfedge(f), *m_mesh))
        now[k++] = m_mesh->target(h);
      for (Halfedge h : CGAL::halfedges_around_face(m_mesh->halfedge(f), *m_mesh)) {
        const Vertex v = m_mesh->target(h);
        const auto recorded_index = [&](auto&& is_it) {
          std::size_t i = 0;
          while (i < 3 && !is_it(recorded.vertices[i])) ++i;
          return i;
        };
        std::size_t was = recorded_index([&](Vertex r) { return r == v; });
        if (was == 3)  // at `kept`: the recorded vertex that is no longer a vertex of f
          was = recorded_index(
              [&](Vertex r) { return std::find(now.begin(), now.end(), r) == now.end(); });
        if (was == 3) continue;
        m_attributes.set_values(h, recorded.values[was].values);
      }
      record_unmoved(f);
    }
  }

  void forget_seam_edges_around(Vertex kept) {
    if (m_seam_counts.empty()) return;
    m_seam_counts[std::size_t(kept)] = kUnknown;
    for (Halfedge h : CGAL::halfedges_around_target(kept, *m_mesh))
      m_seam_counts[std::size_t(m_mesh->source(h))] = kUnknown;
  }

  // The filter and then OnCollapsing ask for the values of the same collapse, with no change to the
  // mesh in between: the last answer is kept until the next collapse.
  struct Checked_collapse {
    Halfedge edge;
    Point placement;
    std::vector<Corner_value> values;
  };

  template <class Profile>
  const std::vector<Corner_value>& corner_values_of(const Profile& profile, const Point& x) const {
    if (!m_checked || m_checked->edge != profile.v0_v1() || !(m_checked->placement == x))
      m_checked = Checked_collapse{profile.v0_v1(), x, new_corner_values(profile, x)};
    return m_checked->values;
  }

  template <class Profile>
  std::vector<Corner_value> new_corner_values(const Profile& profile, const Point& x) const {
    const Mesh& mesh = *m_mesh;
    const Vertex v0 = profile.v0(), v1 = profile.v1();
    const auto at_edge_end = [&](Vertex v) { return v == v0 || v == v1; };
    std::vector<Face> star;
    for (Vertex v : {v0, v1})
      for (Halfedge h : CGAL::halfedges_around_target(v, mesh))
        if (!mesh.is_border(h) && std::find(star.begin(), star.end(), mesh.face(h)) == star.end())
          star.push_back(mesh.face(h));
    const auto index_of = [&](Face f) {
      return std::size_t(std::find(star.begin(), star.end(), f) - star.begin());
    };
    // The sides: faces joined across the edges at v0 or v1 that are not seams.
    std::vector<std::size_t> side(star.size());
    std::iota(side.begin(), side.end(), std::size_t(0));
    const auto root = [&](std::size_t i) {
      while (side[i] != i) i = side[i] = side[side[i]];
      return i;
    };
    for (std::size_t i = 0; i < star.size(); ++i)
      for (Halfedge h : CGAL::halfedges_around_face(mesh.halfedge(star[i]), mesh)) {
        const Halfedge o = mesh.opposite(h);
        if (mesh.is_border(o) || is_seam_edge(h)) continue;
        if (!at_edge_end(mesh.source(h)) && !at_edge_end(mesh.target(h))) continue;
        const std::size_t j = index_of(mesh.face(o));
        if (j < star.size()) side[root(i)] = root(j);
      }
    const bool solved =
        m_solver.free_collapse_values && seam_edges_at(v0) == 0 && seam_edges_at(v1) == 0;
    // What the solver does not give stays NaN, and is interpolated below.
    Corner_value solved_value{mesh.face(profile.v0_v1()), profile.v0_v1(), Attributes::no_values()};
    if (solved) m_solver.free_collapse_values(profile.v0_v1(), x, solved_value.values);
    std::vector<Corner_value> values;
    for (std::size_t i = 0; i < star.size(); ++i) {
      Halfedge corner;
      std::size_t ends = 0;
      for (Halfedge h : CGAL::halfedges_around_face(mesh.halfedge(star[i]), mesh))
        if (at_edge_end(mesh.target(h))) {
          corner = h;
          ++ends;
        }
      if (ends != 1) continue;  // a face on the edge: the collapse removes it
      if (!solved) {
        values.push_back(interpolated(star, root(i), x, star[i], corner, root));
        continue;
      }
      // An attribute the solver leaves undefined (NaN) is interpolated.
      Corner_value value = solved_value;
      value.face = star[i];
      value.corner = corner;
      Values& v = value.values;
      const auto finite = [](const auto& numbers) {
        return std::all_of(numbers.begin(), numbers.end(),
                           [](double c) { return std::isfinite(c); });
      };
      const bool uv_missing = m_attributes.uvs && !finite(v.uv);
      const bool normal_missing = m_attributes.normals && !std::isfinite(v.normal.squared_length());
      const bool color_missing = m_attributes.colors && !finite(v.color);
      const bool second_uv_missing = m_attributes.second_uvs && !finite(v.second_uv);
      const bool skin_missing = m_attributes.skins && !finite(v.skin.weights);
      if (uv_missing || normal_missing || color_missing || second_uv_missing || skin_missing) {
        const Values other = interpolated(star, root(i), x, star[i], corner, root).values;
        if (uv_missing) v.uv = other.uv;
        if (normal_missing) v.normal = other.normal;
        if (color_missing) v.color = other.color;
        if (second_uv_missing) v.second_uv = other.second_uv;
        if (skin_missing) v.skin = other.skin;
      }
      values.push_back(value);
    }
    return values;
  }

  // The corner values at the point of the side's faces closest to x.
  template <class Root>
  Corner_value interpolated(const std::vector<Face>& star, std::size_t wanted, const Point& x,
                            Face face, Halfedge corner, const Root& root) const {
    std::vector<Face> side;
    for (std::size_t i = 0; i < star.size(); ++i)
      if (root(i) == wanted) side.push_back(star[i]);
    return {face, corner, values_nearest(*m_mesh, m_attributes, side, x)};
  }

  Mesh* m_mesh;
  Attributes m_attributes;
  Solver m_solver;
  bool m_started = false;  // started() was called: a visitor feeds the carrier
  std::vector<Pending_face> m_pending;
  std::map<Face, Face_values> m_unmoved;  // faces around edges of zero length, until the loop
  std::set<Point> m_corners_near_zero_length_edges;  // their points
  mutable std::vector<std::size_t> m_seam_counts;    // kUnknown until asked
  mutable std::optional<Checked_collapse> m_checked;
  mutable std::optional<Accepted_collapse> m_accepted;  // until the collapse it names, or another
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CORNER_ATTRIBUTE_CARRIER_H
