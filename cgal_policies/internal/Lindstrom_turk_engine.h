// The flat-array engine of Flat_lindstrom_turk_simplifier (docs/flat_lt.md): Lindstrom and Turk's
// memoryless cost and placement [LT98], computed on the current star of each edge as CGAL's
// LindstromTurk policies do, over Flat_collapse_mesh instead of a halfedge structure: the volume
// terms summed per vertex (around its own point, for their precision) and kept up to date, the
// cheapest edge first from a heap whose stale entries are skipped.
#ifndef CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_ENGINE_H
#define CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_ENGINE_H

#include <cgal_policies/Flat_lindstrom_turk_options.h>
#include <cgal_policies/internal/Flat_collapse_mesh.h>
#include <cgal_policies/internal/Lindstrom_turk_constraints.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <boost/heap/d_ary_heap.hpp>

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

struct Lindstrom_turk_vertex {
  Eigen::Vector3d point;
  bool border = false;
  bool locked = false;  // never moved nor removed (the cut vertices of a partitioned run)
};

// Corners as Flat_collapse_mesh takes them; with values (mesh().set_corner_values), the
// collapses keep the seam rules of Corner_attribute_carrier (docs/attributes.md).
template <class Corners = No_corner_values>
class Lindstrom_turk_engine {
 public:
  struct Triangle {
    std::array<int, 3> v;
    bool deleted;
  };
  using Mesh = Flat_collapse_mesh<Corners, Lindstrom_turk_vertex, Triangle>;

  // The arrays, for the corner values before simplify() and the result after it.
  Mesh& mesh() { return m_mesh; }

  // Collapses between two polls of `interrupted`.
  static constexpr std::size_t kPollPeriod = 4096;

  // Precondition: every triangle has three distinct vertex indices in range.
  Lindstrom_turk_engine(std::vector<Lindstrom_turk_vertex> vertices,
                        const std::vector<std::array<int, 3>>& triangles)
      : m_mesh(std::move(vertices), triangles_of(triangles)) {
    m_sums.resize(m_mesh.vertex_count());
    for (std::size_t v = 0; v < m_mesh.vertex_count(); ++v) sum_volume_terms(int(v));
    m_changed.assign(m_mesh.vertex_count(), 0);
  }

  struct Outcome {
    std::size_t collapses = 0;
    bool target_reached = false;
    bool interrupted = false;
  };

  // Collapses the cheapest allowed edge until the target is reached, no allowed collapse is
  // left, or `interrupted` says so. on_progress gets the face count now and then.
  Outcome simplify(std::size_t target_faces, const Flat_lindstrom_turk_options& options,
                   const std::function<void(std::size_t)>& on_progress = {},
                   const std::function<bool()>& interrupted = {}) {
    m_options = options;
    m_cos_max_angle = std::cos(options.max_normal_angle_deg * (std::acos(-1.0) / 180.0));
    Outcome outcome;
    queue_every_edge();
    const std::size_t start = m_mesh.live_triangles();
    const std::size_t progress_step =
        (std::max)(std::size_t(1), (start - (std::min)(start, target_faces)) / 100);
    std::size_t next_progress = start;
    while (m_mesh.live_triangles() > target_faces && !m_heap.empty()) {
      const Queued edge = pop();
      if (!current(edge)) continue;
      if (!try_collapse(edge)) continue;
      ++outcome.collapses;
      if (outcome.collapses % kPollPeriod == 0 && interrupted && interrupted()) {
        outcome.interrupted = true;
        break;
      }
      if (on_progress && m_mesh.live_triangles() + progress_step <= next_progress) {
        next_progress = m_mesh.live_triangles();
        on_progress(next_progress);
      }
    }
    m_heap = Heap();
    m_mesh.compact();
    outcome.target_reached = m_mesh.live_triangles() <= target_faces;
    return outcome;
  }

 private:
  using Reference = typename Mesh::Reference;

  // [LT98]'s volume terms of faces around an origin o: per face its normal n (twice its area) and
  // the determinant d = n·(p0 - o) of its corners less o, summed as n, d, n n^T, d n and d^2;
  // n·(x - o) - d is six times the volume of the tetrahedron a point x makes with the face.
  struct Volume_terms {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    double determinant = 0;
    Eigen::Matrix3d normal_normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d determinant_normal = Eigen::Vector3d::Zero();
    double determinant_squared = 0;

    void add(const Eigen::Vector3d& n, double d, double sign = 1) {
      normal += sign * n;
      determinant += sign * d;
      normal_normal += sign * (n * n.transpose());
      determinant_normal += sign * d * n;
      determinant_squared += sign * d * d;
    }
    // The same faces around o - shift.
    Volume_terms shifted(const Eigen::Vector3d& shift) const {
      Volume_terms moved = *this;
      const Eigen::Vector3d nn_shift = normal_normal * shift;
      moved.determinant += normal.dot(shift);
      moved.determinant_normal += nn_shift;
      moved.determinant_squared += 2 * shift.dot(determinant_normal) + shift.dot(nn_shift);
      return moved;
    }
    void operator+=(const Volume_terms& other) {
      normal += other.normal;
      determinant += other.determinant;
      normal_normal += other.normal_normal;
      determinant_normal += other.determinant_normal;
      determinant_squared += other.determinant_squared;
    }
  };

  // An edge in the heap, and the collapse count when its cost was computed: it is stale when
  // either end changed since.
  struct Queued {
    double cost;
    double squared_length;
    int a, b;
    std::uint32_t time;
  };
  // The cheapest first; equal costs (the flat stars' 0) the shortest first, so that no vertex
  // takes in its flat surroundings one after the other; then by their ends, so that the order
  // never depends on the heap.
  struct After {
    bool operator()(const Queued& x, const Queued& y) const {
      if (x.cost != y.cost) return x.cost > y.cost;
      if (x.squared_length != y.squared_length) return x.squared_length > y.squared_length;
      if (x.a != y.a) return x.a > y.a;
      return x.b > y.b;
    }
  };
  // Four children a node: a pop sifts down half as many levels as in a binary heap, and a
  // node's children share cache lines. A binary heap's pops were a quarter of the time of the
  // partitioned run's last pass (docs/scale.md).
  using Heap = boost::heap::d_ary_heap<Queued, boost::heap::arity<4>, boost::heap::compare<After>>;

  // A border edge in its face's direction, s to t, around the edge's first end: its vector and
  // t × s.
  struct Border_terms {
    Eigen::Vector3d s, t, vector, moment;
  };

  // The neighbours of a vertex, each with the one or two triangles of their edge.
  struct Neighbour {
    int vertex;
    int triangles[2];
  };

  static std::vector<Triangle> triangles_of(const std::vector<std::array<int, 3>>& triangles) {
    std::vector<Triangle> result;
    result.reserve(triangles.size());
    for (const auto& t : triangles) result.push_back({t, false});
    return result;
  }

  // w's point around origin o's.
  Eigen::Vector3d local(int w, int o) const { return m_mesh.point(w) - m_mesh.point(o); }

  // Triangle t's normal and determinant around o's point.
  void add_face(Volume_terms& terms, std::size_t t, int o, double sign = 1) const {
    const Triangle& triangle = m_mesh.triangles()[t];
    const Eigen::Vector3d p0 = local(triangle.v[0], o), p1 = local(triangle.v[1], o),
                          p2 = local(triangle.v[2], o);
    const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    terms.add(n, n.dot(p0), sign);
  }

  // m_sums[v]: the volume terms of v's faces around v.
  void sum_volume_terms(int v) {
    Volume_terms terms;
    for (const Reference* r = m_mesh.references_begin(v); r != m_mesh.references_end(v); ++r)
      if (!m_mesh.triangles()[std::size_t(r->triangle)].deleted)
        add_face(terms, std::size_t(r->triangle), v);
    m_sums[std::size_t(v)] = terms;
  }

  // m_neighbours: v's neighbours, once each, with the triangles of their edge.
  void collect_neighbours(int v) {
    m_neighbours.clear();
    for (const Reference* r = m_mesh.references_begin(v); r != m_mesh.references_end(v); ++r) {
      const Triangle& t = m_mesh.triangles()[std::size_t(r->triangle)];
      if (t.deleted) continue;
      for (int w : {t.v[(r->corner + 1) % 3], t.v[(r->corner + 2) % 3]}) {
        const auto known = std::find_if(m_neighbours.begin(), m_neighbours.end(),
                                        [w](const Neighbour& n) { return n.vertex == w; });
        if (known == m_neighbours.end())
          m_neighbours.push_back({w, {r->triangle, -1}});
        else
          known->triangles[1] = r->triangle;
      }
    }
  }

  Queued pop() {
    const Queued edge = m_heap.top();
    m_heap.pop();
    return edge;
  }

  bool current(const Queued& edge) const {
    return !m_mesh.removed(edge.a) && !m_mesh.removed(edge.b) &&
           m_changed[std::size_t(edge.a)] <= edge.time &&
           m_changed[std::size_t(edge.b)] <= edge.time;
  }

  // The heap entry of the edge from a to b; none while its collapse is refused (until its star
  // changes).
  std::optional<Queued> entry(int a, const Neighbour& b) {
    Eigen::Vector3d unused;
    const double cost = edge_cost(a, b, unused);
    if (!std::isfinite(cost)) return std::nullopt;
    return Queued{cost, local(b.vertex, a).squaredNorm(), a, b.vertex, m_time};
  }

  void push(int a, const Neighbour& b) {
    if (const std::optional<Queued> queued = entry(a, b)) m_heap.push(*queued);
  }

  // Every edge once, from its smaller end.
  void queue_every_edge() {
    m_heap.clear();
    for (int u = 0; u < int(m_mesh.vertex_count()); ++u) {
      if (m_mesh.removed(u)) continue;
      collect_neighbours(u);
      for (const Neighbour& w : m_neighbours) {
        if (w.vertex < u) continue;
        push(u, w);
      }
    }
  }

  // The cost of merging a and b.vertex, and where the merged vertex goes: [LT98]'s placement,
  // moved by the seam rules when the mesh carries corner values; infinity when refused (a locked
  // end, no placement, or the seam rules).
  double edge_cost(int a, const Neighbour& b, Eigen::Vector3d& placement) {
    constexpr double kRefused = std::numeric_limits<double>::infinity();
    if (m_mesh.vertex(a).locked || m_mesh.vertex(b.vertex).locked) return kRefused;
    collect_terms(a, b);
    const double squared_length = local(b.vertex, a).squaredNorm();
    const std::optional<Eigen::Vector3d> x = lindstrom_turk_point(a, b.vertex, squared_length);
    if (!x) return kRefused;
    placement = *x + m_mesh.point(a);
    if (!m_mesh.place_by_seams(a, b.vertex, std::size_t(b.triangles[0]), placement))
      return kRefused;
    const double cost =
        lindstrom_turk_cost(a, b.vertex, placement - m_mesh.point(a), squared_length);
    return std::isfinite(cost) ? cost : kRefused;
  }

  // m_volume and m_borders of the edge of a and b, around a: the faces around either end (their
  // sums less the faces of the edge, which both hold) and the border edges at either end.
  void collect_terms(int a, const Neighbour& b) {
    m_volume = m_sums[std::size_t(a)];
    m_volume += m_sums[std::size_t(b.vertex)].shifted(local(b.vertex, a));
    for (int t : b.triangles)
      if (t >= 0) add_face(m_volume, std::size_t(t), a, -1);
    m_borders.clear();
    m_link.clear();  // collect_link() fills it when it is needed
    if (!m_mesh.vertex(a).border && !m_mesh.vertex(b.vertex).border) return;
    for (int end : {a, b.vertex})
      for (const Reference* r = m_mesh.references_begin(end); r != m_mesh.references_end(end);
           ++r) {
        const Triangle& t = m_mesh.triangles()[std::size_t(r->triangle)];
        if (t.deleted || (end == b.vertex && Mesh::contains(t, a))) continue;
        collect_border_edges(std::size_t(r->triangle), a, b.vertex);
      }
  }

  // m_link: the vertices next to a or b but a and b themselves, once each.
  void collect_link(int a, int b) {
    if (!m_link.empty()) return;
    for (int end : {a, b})
      for (const Reference* r = m_mesh.references_begin(end); r != m_mesh.references_end(end);
           ++r) {
        const Triangle& t = m_mesh.triangles()[std::size_t(r->triangle)];
        if (t.deleted) continue;
        for (int w : t.v)
          if (w != a && w != b && std::find(m_link.begin(), m_link.end(), w) == m_link.end())
            m_link.push_back(w);
      }
  }

  // t's edges at a or b that no other face has.
  void collect_border_edges(std::size_t t, int a, int b) {
    const Triangle& triangle = m_mesh.triangles()[t];
    for (int j = 0; j < 3; ++j) {
      const int s = triangle.v[j], e = triangle.v[(j + 1) % 3];
      if ((s == a || s == b || e == a || e == b) && m_mesh.is_border_edge(t, s, e)) {
        const Eigen::Vector3d ps = local(s, a), pe = local(e, a);
        m_borders.push_back({ps, pe, pe - ps, pe.cross(ps)});
      }
    }
  }

  // [LT98]'s (v×)(×v): the matrix of x -> v × (v × x), negated.
  static Eigen::Matrix3d cross_square(const Eigen::Vector3d& v) {
    return Eigen::Matrix3d::Identity() * v.squaredNorm() - v * v.transpose();
  }

  // The placement: border preservation, volume preservation, then the weighted volume and border
  // optimisation, then the shape of the link, as long as fewer than three constraints hold.
  std::optional<Eigen::Vector3d> lindstrom_turk_point(int a, int b, double squared_length) {
    Lindstrom_turk_constraints constraints;
    Eigen::Vector3d border_vector = Eigen::Vector3d::Zero(), border_moment = border_vector;
    Eigen::Matrix3d border_h = Eigen::Matrix3d::Zero();
    Eigen::Vector3d border_c = Eigen::Vector3d::Zero();
    for (const Border_terms& e : m_borders) {
      border_vector += e.vector;
      border_moment += e.moment;
      border_h += cross_square(e.vector);
      border_c += e.vector.cross(e.moment);
    }
    if (!m_borders.empty())
      constraints.add_minimum_of(cross_square(border_vector), border_vector.cross(border_moment));

    const Eigen::Matrix3d& volume_h = m_volume.normal_normal;
    const Eigen::Vector3d volume_c = -m_volume.determinant_normal;
    if (!constraints.complete()) constraints.add(m_volume.normal, m_volume.determinant);
    if (!constraints.complete()) {
      if (m_borders.empty()) {
        constraints.add_minimum_of(volume_h, volume_c);
      } else {
        const double border_scale = 9 * m_options.boundary_weight * squared_length;
        constraints.add_minimum_of(m_options.volume_weight * volume_h + border_scale * border_h,
                                   m_options.volume_weight * volume_c + border_scale * border_c);
      }
    }
    if (!constraints.complete()) {
      collect_link(a, b);
      Eigen::Vector3d link_c = Eigen::Vector3d::Zero();
      for (int w : m_link) link_c -= local(w, a);
      constraints.add_minimum_of(Eigen::Matrix3d::Identity() * double(m_link.size()), link_c);
    }
    return constraints.solve();
  }

  // The weighted sum of the volume, border and shape costs at x (around a).
  double lindstrom_turk_cost(int a, int b, const Eigen::Vector3d& x, double squared_length) {
    // The sum of (n·x - d)^2 over the faces, as the sums give it: 0 where it is within their
    // round-off, as it is exactly on a flat star, so that such collapses tie as they do when each
    // face is summed alone (in CGAL's LindstromTurk_cost), and go in the order of their ends.
    const double squared = m_volume.determinant_squared;
    const double linear = 2 * x.dot(m_volume.determinant_normal);
    const double quadratic = x.dot(m_volume.normal_normal * x);
    const double volume_sum = squared - linear + quadratic;
    const double round_off =
        kRoundOff * (std::abs(squared) + std::abs(linear) + std::abs(quadratic));
    const double volume = volume_sum > round_off ? volume_sum : 0.0;
    double border = 0;
    for (const Border_terms& e : m_borders) border += e.vector.cross(e.t - x).squaredNorm();
    double shape = 0;
    if (m_options.shape_weight != 0) {
      collect_link(a, b);
      for (int w : m_link) shape += (x - local(w, a)).squaredNorm();
    }
    return m_options.volume_weight * volume / 36 +
           m_options.boundary_weight * border / 4 * squared_length +
           m_options.shape_weight * shape * squared_length * squared_length;
  }

  // The collapse of a current edge, unless a check refuses it; then the costs around it again.
  bool try_collapse(const Queued& edge) {
    const int a = edge.a;
    collect_neighbours(a);
    const auto b = std::find_if(m_neighbours.begin(), m_neighbours.end(),
                                [&edge](const Neighbour& n) { return n.vertex == edge.b; });
    if (b == m_neighbours.end()) return false;
    Eigen::Vector3d p;
    if (!std::isfinite(edge_cost(a, *b, p))) return false;
    if (!m_mesh.satisfies_link_condition(a, edge.b) ||
        m_mesh.turns_too_far(a, edge.b, p, m_cos_max_angle) ||
        m_mesh.turns_too_far(edge.b, a, p, m_cos_max_angle))
      return false;
    if (!m_mesh.plan_corner_values(a, edge.b, p)) return false;
    m_mesh.collapse(a, edge.b, p, [](Triangle&) {});
    // The lists keep the deleted triangles until compact(); the costs walk them.
    if (m_mesh.reference_count() > 6 * m_mesh.live_triangles() + 64) m_mesh.compact();
    queue_edges_around(a);
    if (m_heap.size() > kStaleShare * (3 * m_mesh.live_triangles() / 2 + 64)) drop_stale_entries();
    return true;
  }

  // After a collapse into v: v and its neighbours have new faces, so new sums, and every edge at
  // one of them a new star, so a new cost; each is queued once.
  void queue_edges_around(int v) {
    ++m_time;
    m_ring.clear();
    m_ring.push_back(v);
    collect_neighbours(v);
    for (const Neighbour& w : m_neighbours) m_ring.push_back(w.vertex);
    m_mesh.next_stamp();
    for (int u : m_ring) {
      m_mesh.mark(u);
      m_changed[std::size_t(u)] = m_time;
      sum_volume_terms(u);
    }
    // An edge between two vertices of the ring is queued from its smaller end.
    for (int u : m_ring) {
      collect_neighbours(u);
      for (const Neighbour& w : m_neighbours)
        if (!(m_mesh.marked(w.vertex) && w.vertex < u)) push(u, w);
    }
  }

  // The heap without the entries no collapse can use any more.
  void drop_stale_entries() {
    std::vector<Queued> kept;
    for (const Queued& edge : m_heap)
      if (current(edge)) kept.push_back(edge);
    m_heap.clear();
    for (const Queued& edge : kept) m_heap.push(edge);
  }

  // Relative round-off of the volume cost summed from the sums, a few units in the last place.
  static constexpr double kRoundOff = 64 * std::numeric_limits<double>::epsilon();
  // The heap may hold this many times the live edges before its stale entries are dropped.
  static constexpr std::size_t kStaleShare = 2;

  Mesh m_mesh;
  std::vector<Volume_terms> m_sums;  // per vertex, of its faces around its point
  Heap m_heap;
  std::vector<std::uint32_t> m_changed;  // per vertex, m_time when its edges last changed
  std::uint32_t m_time = 0;              // collapses so far
  // One edge's terms, one collapse's ring and one vertex's neighbours.
  Volume_terms m_volume;
  std::vector<Border_terms> m_borders;
  std::vector<int> m_link;
  std::vector<int> m_ring;
  std::vector<Neighbour> m_neighbours;
  Flat_lindstrom_turk_options m_options;
  double m_cos_max_angle = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_LINDSTROM_TURK_ENGINE_H
