// The state behind the Hausdorff-bounded policies (policies.md §3): the reference surface, the
// input pieces that follow the faces of the current mesh, and the conservative two-sided test of a
// patch whose vertices move (an edge collapse, or one vertex during smoothing).
//
// Global reference: the input triangles sit in an AABB tree (new patch -> input), and every part of
// the input is a piece attached to one current face that covers it within the tolerance (input ->
// new patch). When a patch changes, the pieces of its faces are attached again to the new faces, or
// the change is refused; the pieces elsewhere keep their faces, which did not change. So the whole
// output stays within the tolerance of the whole input, in both directions.
//
// Local reference (the paper's literal rule): the patch before the change is the reference.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_TRACKER_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_TRACKER_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Flat_frame.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/patch_distance.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// Candidates are ranked on the corners of this many pieces at most: a lower bound all the same.
constexpr std::size_t kRankingPieces = 32;
// A patch that needs more reference samples than this to be certified is refused.
constexpr std::size_t kSampleBudget = 600;
// Only the best few candidates are put to the full test: the others rarely pass when they fail.
constexpr std::size_t kMaxCertified = 3;
// A walk on the input toward a point stops after this many steps (see reference_sample).
constexpr std::size_t kWalkSteps = 64;
// The flatness argument gives up after this many input triangles.
constexpr std::size_t kFlatSearchLimit = 2000;
constexpr std::uint32_t kNoNeighbour = 0xffffffffu;

template <typename TriangleMesh>
class Hausdorff_tracker {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;

  using Search_kernel = CGAL::Simple_cartesian<double>;
  using Search_triangles = std::vector<Search_kernel::Triangle_3>;
  using Search_tree = CGAL::AABB_tree<CGAL::AABB_traits<
      Search_kernel,
      CGAL::AABB_triangle_primitive<Search_kernel, typename Search_triangles::const_iterator>>>;

  using Piece_list_property = CGAL::dynamic_face_property_t<std::vector<std::uint32_t>>;
  using Piece_list_map = typename boost::property_map<TriangleMesh, Piece_list_property>::type;
  using Frozen_property = CGAL::dynamic_face_property_t<bool>;
  using Frozen_map = typename boost::property_map<TriangleMesh, Frozen_property>::type;
  using Distance_property = CGAL::dynamic_vertex_property_t<Reference_sample>;
  using Distance_map = typename boost::property_map<TriangleMesh, Distance_property>::type;
  using Order_property = CGAL::dynamic_edge_property_t<double>;
  using Order_map = typename boost::property_map<TriangleMesh, Order_property>::type;

  // The faces around the moving vertices: those that survive with a moved corner, and those that
  // vanish (the two faces of a collapsed edge).
  struct Patch {
    std::vector<face_descriptor> faces, removed;
    std::vector<Triangle_corners> before, removed_before;
    std::vector<std::array<bool, 3>> moving;  // which corners of `before` move
    std::vector<std::array<Reference_sample, 3>> corner_distances;
    std::vector<Triangle_corners> reference;  // local reference: the patch before the change
    std::vector<Triangle_corners> pieces;
    std::vector<std::uint32_t> piece_sources;
  };

  struct Pending {
    bool active = false;
    Eigen::Vector3d point;
    Reference_sample distance;
    vertex_descriptor v0, v1;
    std::vector<face_descriptor> faces, removed;
    std::vector<Piece_cover> covers;
  };

 public:
  // `input` is the reference surface; `tracked` is the mesh that will change (it may be the same).
  template <typename InputMesh>
  Hausdorff_tracker(const InputMesh& input, TriangleMesh& tracked, double tolerance_fraction,
                    const Hausdorff_bounded_options& options)
      : m_options(options),
        m_face_pieces(get(Piece_list_property(), tracked)),
        m_frozen(get(Frozen_property(), tracked)),
        m_distance(get(Distance_property(), tracked)),
        m_order(get(Order_property(), tracked)) {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
    m_diagonal =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
    m_tolerance = tolerance_fraction * m_diagonal;
    if (m_options.reference == Hausdorff_reference::local) return;
    const auto vpm = get(CGAL::vertex_point, input);
    using Input_face = typename boost::graph_traits<InputMesh>::face_descriptor;
    std::vector<std::pair<Input_face, std::uint32_t>> index;
    for (auto f : faces(input)) {
      const Triangle_corners t = corners(f, input, vpm);
      m_input.emplace_back(search_point(t[0]), search_point(t[1]), search_point(t[2]));
      m_input_corners.push_back(t);
      index.emplace_back(f, std::uint32_t(index.size()));
    }
    std::sort(index.begin(), index.end());
    m_input_neighbours.resize(m_input_corners.size());
    // Across edge k of input triangle i (corners k, k + 1) lies m_input_neighbours[i][k].
    for (const auto& [f, i] : index) {
      std::array<std::uint32_t, 3> across;
      int k = 0;
      for (auto h : CGAL::halfedges_around_face(halfedge(f, input), input)) {
        const Input_face g = face(opposite(h, input), input);
        const auto it = std::lower_bound(index.begin(), index.end(), std::make_pair(g, 0u));
        across[k++] =
            g == boost::graph_traits<InputMesh>::null_face() || it == index.end() || it->first != g
                ? kNoNeighbour
                : it->second;
      }
      m_input_neighbours[i] = across;
    }
    m_flat_state.assign(m_input_corners.size(), {0, 0});
    m_tree.rebuild(m_input.begin(), m_input.end());
    m_tree.accelerate_distance_queries();
  }

  Hausdorff_tracker(const Hausdorff_tracker&) = delete;
  Hausdorff_tracker& operator=(const Hausdorff_tracker&) = delete;

  double tolerance() const { return m_tolerance; }
  double diagonal() const { return m_diagonal; }

  // Every face of `tm`, which is the input itself, becomes its own piece; the storage order of the
  // edges is recorded for the single-pass order.
  template <typename VertexPointMap>
  void attach_to_itself(const TriangleMesh& tm, const VertexPointMap& vpm) {
    m_pending.active = false;
    m_pieces.clear();
    std::size_t index = 0;
    for (auto f : faces(tm)) {
      for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
        put(m_distance, v, Reference_sample{0.0, index});
      ++index;
      put(m_frozen, f, false);
      std::vector<std::uint32_t> list;
      if (m_options.reference == Hausdorff_reference::global) {
        list.push_back(std::uint32_t(m_pieces.size()));
        m_pieces.push_back(corners(f, tm, vpm));
      }
      put(m_face_pieces, f, std::move(list));
    }
    double order = 0;
    for (auto e : edges(tm)) put(m_order, e, order++);
  }

  // Attaches every input face to faces of `tm`, an approximation of the input made elsewhere: each
  // piece goes to a face around the face nearest to its centroid that covers it. A piece that none
  // covers freezes that face (its vertices will not move), since the bound is broken there already.
  template <typename VertexPointMap>
  void attach_to_approximation(const TriangleMesh& tm, const VertexPointMap& vpm) {
    m_pending.active = false;
    m_pieces.clear();
    Search_triangles current;
    std::vector<face_descriptor> current_faces;
    for (auto f : faces(tm)) {
      const Triangle_corners t = corners(f, tm, vpm);
      current.emplace_back(search_point(t[0]), search_point(t[1]), search_point(t[2]));
      current_faces.push_back(f);
      put(m_face_pieces, f, std::vector<std::uint32_t>());
      put(m_frozen, f, false);
    }
    for (auto v : vertices(tm)) put(m_distance, v, reference_sample(to_eigen(get(vpm, v))));
    if (current.empty()) return;
    Search_tree tree(current.begin(), current.end());
    tree.accelerate_distance_queries();
    for (const auto& t : m_input) {
      const Triangle_corners piece = {to_eigen(t[0]), to_eigen(t[1]), to_eigen(t[2])};
      const Eigen::Vector3d centroid = (piece[0] + piece[1] + piece[2]) / 3;
      const auto nearest = tree.closest_point_and_primitive(search_point(centroid)).second;
      const face_descriptor f = current_faces[std::size_t(nearest - current.cbegin())];
      std::vector<face_descriptor> around;
      for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
        for (auto g : CGAL::faces_around_target(h, tm))
          if (g != Graph_traits::null_face() &&
              std::find(around.begin(), around.end(), g) == around.end())
            around.push_back(g);
      std::vector<Triangle_corners> patch;
      for (auto g : around) patch.push_back(corners(g, tm, vpm));
      std::vector<Piece_cover> covers;
      std::size_t hint = 0;
      if (cover_piece(piece, kNewPiece, patch, m_tolerance, m_options.max_refinement, hint,
                      covers)) {
        for (const Piece_cover& c : covers) attach(c.piece, around[c.triangle]);
      } else {
        attach(piece, f);
        put(m_frozen, f, true);
      }
    }
  }

  // The edge's place in the single pass, or nothing once it was tried.
  template <typename Profile>
  Optional<double> storage_order(const Profile& profile) const {
    const double order = get(m_order, edge(profile.v0_v1(), profile.surface_mesh()));
    if (order < 0) return {};
    return order;
  }
  template <typename Profile>
  void mark_tried(const Profile& profile) const {
    put(m_order, edge(profile.v0_v1(), profile.surface_mesh()), -1.0);
  }

  // The best of `candidates` (the smallest lower bound of its two-sided distance first) that is
  // certified within the tolerance, or nothing. `acceptable(point)` filters candidates first (flip
  // check). The choice is remembered until commit().
  template <typename Profile, typename Acceptable>
  Optional<Eigen::Vector3d> choose(const Profile& profile,
                                   const std::vector<Eigen::Vector3d>& candidates,
                                   const Acceptable& acceptable) {
    // A choice still pending was not collapsed, unless nothing calls commit() (defer_commits).
    if (m_deferred_commits)
      commit_pending();
    else
      m_pending.active = false;
    const Patch patch =
        make_patch(profile.surface_mesh(), profile.vertex_point_map(), profile.v0(), profile.v1());
    if (frozen(patch)) return {};
    struct Ranked {
      double bound;
      Reference_sample distance;
      std::size_t index;
    };
    std::vector<Ranked> ranked;
    const Eigen::Vector3d p0 = to_eigen(profile.p0()), p1 = to_eigen(profile.p1());
    const std::size_t hint0 = get(m_distance, profile.v0()).triangle,
                      hint1 = get(m_distance, profile.v1()).triangle;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const Eigen::Vector3d& p = candidates[i];
      // The cheapest refusals first: the pieces' corners, the flip check, then p's distance.
      const double stop = (std::min)(best, m_tolerance);
      const double pieces_bound =
          corner_distance_lower_bound(patch.pieces, moved(patch, p), stop, kRankingPieces);
      if (pieces_bound > m_tolerance || !acceptable(p)) continue;
      const bool nearer_v0 = (p - p0).squaredNorm() <= (p - p1).squaredNorm();
      const Reference_sample d = patch_reference_sample(patch, p, nearer_v0 ? hint0 : hint1);
      const double bound = (std::max)(d.distance, pieces_bound);
      if (bound > m_tolerance) continue;
      best = (std::min)(best, bound);
      ranked.push_back({bound, d, i});
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const Ranked& a, const Ranked& b) { return a.bound < b.bound; });
    if (ranked.size() > kMaxCertified) ranked.resize(kMaxCertified);
    for (const Ranked& r : ranked) {
      std::vector<Piece_cover> covers;
      if (!certify(patch, candidates[r.index], r.distance, covers)) continue;
      m_pending.active = true;
      m_pending.point = candidates[r.index];
      m_pending.distance = r.distance;
      m_pending.v0 = profile.v0();
      m_pending.v1 = profile.v1();
      m_pending.faces = patch.faces;
      m_pending.removed = patch.removed;
      m_pending.covers = std::move(covers);
      return candidates[r.index];
    }
    return {};
  }

  // For a filter used alone, whose collapses nobody reports: what choose() accepted is taken as
  // collapsed when the next choice is asked for.
  void defer_commits() { m_deferred_commits = true; }

  // After the collapse chose(): moves the kept vertex to the chosen point when asked, and attaches
  // the pieces of the old patch to the new faces.
  template <typename VertexPointMap>
  void commit(const VertexPointMap& vpm, vertex_descriptor kept, bool move_vertex) {
    if (!m_pending.active) return;
    if (move_vertex)
      put(vpm, kept,
          to_point<typename boost::property_traits<VertexPointMap>::value_type>(m_pending.point));
    commit_pending();
  }

  // Applies whatever choose() left pending (when the collapse used the placement it was given).
  void commit_pending() {
    if (!m_pending.active) return;
    m_pending.active = false;
    put(m_distance, m_pending.v0, m_pending.distance);
    put(m_distance, m_pending.v1, m_pending.distance);
    if (m_options.reference == Hausdorff_reference::local) return;  // no pieces to follow
    for (auto f : m_pending.removed) put(m_face_pieces, f, std::vector<std::uint32_t>());
    for (auto f : m_pending.faces) put(m_face_pieces, f, std::vector<std::uint32_t>());
    for (const Piece_cover& c : m_pending.covers) {
      const face_descriptor f = m_pending.faces[c.triangle];
      if (c.source == kNewPiece) {
        attach(c.piece, f);
      } else {
        std::vector<std::uint32_t> list = get(m_face_pieces, f);
        list.push_back(c.source);
        put(m_face_pieces, f, std::move(list));
      }
    }
  }

  // True, and the pieces attached again, when moving v to p keeps the bound; the caller moves v.
  template <typename VertexPointMap>
  bool try_move(const TriangleMesh& tm, const VertexPointMap& vpm, vertex_descriptor v,
                const Eigen::Vector3d& p) {
    commit_pending();
    const Patch patch = make_patch(tm, vpm, v, v);
    if (frozen(patch)) return false;
    const Reference_sample d = patch_reference_sample(patch, p, get(m_distance, v).triangle);
    std::vector<Piece_cover> covers;
    if (d.distance > m_tolerance || !certify(patch, p, d, covers)) return false;
    m_pending.active = true;
    m_pending.point = p;
    m_pending.distance = d;
    m_pending.v0 = m_pending.v1 = v;
    m_pending.faces = patch.faces;
    m_pending.removed.clear();
    m_pending.covers = std::move(covers);
    commit_pending();
    return true;
  }

 private:
  static Search_kernel::Point_3 search_point(const Eigen::Vector3d& p) {
    return {p.x(), p.y(), p.z()};
  }
  static Eigen::Vector3d to_eigen(const Search_kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }
  template <typename Point>
  static Eigen::Vector3d to_eigen(const Point& p) {
    return internal::to_eigen(p);
  }

  template <typename Mesh, typename VertexPointMap>
  static Triangle_corners corners(typename boost::graph_traits<Mesh>::face_descriptor f,
                                  const Mesh& tm, const VertexPointMap& vpm) {
    const auto h = halfedge(f, tm);
    return {internal::to_eigen(get(vpm, source(h, tm))),
            internal::to_eigen(get(vpm, target(h, tm))),
            internal::to_eigen(get(vpm, target(next(h, tm), tm)))};
  }

  void attach(const Triangle_corners& piece, face_descriptor f) {
    std::vector<std::uint32_t> list = get(m_face_pieces, f);
    list.push_back(std::uint32_t(m_pieces.size()));
    m_pieces.push_back(piece);
    put(m_face_pieces, f, std::move(list));
  }

  // The distance from p to an input triangle near it, an upper bound of its distance to the input:
  // a walk across the input's edges from the triangle `hint` while the distance drops, which is
  // exact on most of a smooth surface; an upper bound is all the tests need. When it ends farther
  // than the tolerance, the input point nearest to p, from the AABB tree seeded with the walk's end
  // (or the previous answer).
  Reference_sample reference_sample(const Eigen::Vector3d& p,
                                    std::size_t hint = Reference_sample::kNoTriangle) const {
    const auto query = search_point(p);
    if (hint != Reference_sample::kNoTriangle) {
      std::uint32_t at = std::uint32_t(hint);
      double d2 = squared_distance_to_triangle(p, m_input_corners[at]);
      for (std::size_t step = 0; step < kWalkSteps; ++step) {
        const std::uint32_t from = at;
        for (const std::uint32_t j : m_input_neighbours[from]) {
          if (j == kNoNeighbour) continue;
          const double e2 = squared_distance_to_triangle(p, m_input_corners[j]);
          if (e2 < d2) {
            d2 = e2;
            at = j;
          }
        }
        if (at == from) break;
      }
      if (d2 <= m_tolerance * m_tolerance) return {std::sqrt(d2), at};
      const auto primitive = m_input.cbegin() + at;
      m_hint = {Search_kernel().construct_projected_point_3_object()(*primitive, query), primitive};
      m_has_hint = true;
    }
    const auto nearest = m_has_hint ? m_tree.closest_point_and_primitive(query, m_hint)
                                    : m_tree.closest_point_and_primitive(query);
    m_hint = nearest;
    m_has_hint = true;
    return {std::sqrt(CGAL::squared_distance(query, nearest.first)),
            std::size_t(nearest.second - m_input.cbegin())};
  }

  // Whether t is within the tolerance of a flat part of the input (Flat_frame). K grows from
  // input triangles near t's corners across the input's edges, through the triangles that
  // hold the flatness argument and whose projection may meet t's; an edge of K to a triangle that
  // does not hold it, or to none, must not cross t. An edge to a triangle whose projection misses
  // t's cannot.
  bool flat_covers(const Sampled_triangle& t) const {
    const Flat_frame frame(t.corners, m_tolerance);
    if (!frame.valid()) return false;
    enum : std::uint8_t { outside, kept, rejected };
    if (++m_flat_stamp == 0) {  // wrapped: stale stamps would pass for current ones
      std::fill(m_flat_state.begin(), m_flat_state.end(), std::make_pair(0u, std::uint8_t(0)));
      m_flat_stamp = 1;
    }
    m_flat_stack.clear();
    const auto visit = [&](std::uint32_t j) {
      auto& [stamp, state] = m_flat_state[j];
      if (stamp != m_flat_stamp) {
        stamp = m_flat_stamp;
        const Triangle_corners& q = m_input_corners[j];
        state = !frame.may_meet(q) ? outside : frame.holds(q) ? kept : rejected;
        if (state == kept) m_flat_stack.push_back(j);
      }
      return state;
    };
    // Seeds: the triangles nearest to t's corners, or, when one does not hold the argument (a
    // corner on a crease may be nearest to the far side), the two rings of triangles around it.
    for (const Reference_sample& s : t.samples) {
      if (s.triangle == Reference_sample::kNoTriangle || visit(std::uint32_t(s.triangle)) == kept)
        continue;
      for (const std::uint32_t j : m_input_neighbours[s.triangle])
        if (j != kNoNeighbour && visit(j) != kept)
          for (const std::uint32_t k : m_input_neighbours[j])
            if (k != kNoNeighbour) visit(k);
    }
    bool centroid = false;
    for (std::size_t expanded = 0; !m_flat_stack.empty(); ++expanded) {
      if (expanded == kFlatSearchLimit) return false;
      const std::uint32_t i = m_flat_stack.back();
      m_flat_stack.pop_back();
      const Triangle_corners& q = m_input_corners[i];
      centroid = centroid || frame.holds_centroid(q);
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t j = m_input_neighbours[i][k];
        if ((j == kNoNeighbour || visit(j) == rejected) && frame.crosses(q[k], q[(k + 1) % 3]))
          return false;
      }
    }
    return centroid;
  }

  // The nearest point of the reference of this patch: the input, or the patch before the change.
  // `hint` is an input triangle near p (global reference).
  Reference_sample patch_reference_sample(const Patch& patch, const Eigen::Vector3d& p,
                                          std::size_t hint) const {
    if (m_options.reference == Hausdorff_reference::global) return reference_sample(p, hint);
    Reference_sample nearest{std::numeric_limits<double>::infinity(), 0};
    for (std::size_t t = 0; t < patch.reference.size(); ++t) {
      const double d2 = squared_distance_to_triangle(p, patch.reference[t]);
      if (d2 < nearest.distance) nearest = {d2, t};
    }
    nearest.distance = std::sqrt(nearest.distance);
    return nearest;
  }

  template <typename VertexPointMap>
  Patch make_patch(const TriangleMesh& tm, const VertexPointMap& vpm, vertex_descriptor v0,
                   vertex_descriptor v1) const {
    Patch patch;
    const bool global = m_options.reference == Hausdorff_reference::global;
    for (int pass = 0; pass < (v0 == v1 ? 1 : 2); ++pass) {
      const vertex_descriptor v = pass == 0 ? v0 : v1;
      for (auto f : CGAL::faces_around_target(halfedge(v, tm), tm)) {
        if (f == Graph_traits::null_face()) continue;
        std::array<vertex_descriptor, 3> vs;
        int i = 0;
        for (auto w : CGAL::vertices_around_face(halfedge(f, tm), tm)) vs[i++] = w;
        const bool has0 = std::find(vs.begin(), vs.end(), v0) != vs.end();
        const bool has1 = std::find(vs.begin(), vs.end(), v1) != vs.end();
        if (pass == 1 && has0) continue;  // seen around v0
        Triangle_corners t;
        for (int k = 0; k < 3; ++k) t[k] = internal::to_eigen(get(vpm, vs[k]));
        if (has0 && has1 && v0 != v1) {
          patch.removed.push_back(f);
          patch.removed_before.push_back(t);
          continue;
        }
        patch.faces.push_back(f);
        patch.before.push_back(t);
        std::array<bool, 3> moving;
        std::array<Reference_sample, 3> distances;
        for (int k = 0; k < 3; ++k) {
          moving[k] = vs[k] == v0 || vs[k] == v1;
          distances[k] =
              global ? get(m_distance, vs[k]) : Reference_sample{0.0, patch.before.size() - 1};
        }
        patch.moving.push_back(moving);
        patch.corner_distances.push_back(distances);
      }
    }
    if (global) {
      for (const auto* list : {&patch.faces, &patch.removed})
        for (auto f : *list)
          for (std::uint32_t i : get(m_face_pieces, f)) {
            patch.pieces.push_back(m_pieces[i]);
            patch.piece_sources.push_back(i);
          }
    } else {
      patch.reference = patch.before;
      patch.reference.insert(patch.reference.end(), patch.removed_before.begin(),
                             patch.removed_before.end());
      patch.pieces = patch.reference;
      patch.piece_sources.assign(patch.pieces.size(), kNewPiece);
    }
    return patch;
  }

  bool frozen(const Patch& patch) const {
    for (const auto* list : {&patch.faces, &patch.removed})
      for (auto f : *list)
        if (get(m_frozen, f)) return true;
    return false;
  }

  static std::vector<Triangle_corners> moved(const Patch& patch, const Eigen::Vector3d& p) {
    std::vector<Triangle_corners> after = patch.before;
    for (std::size_t j = 0; j < after.size(); ++j)
      for (int k = 0; k < 3; ++k)
        if (patch.moving[j][k]) after[j][k] = p;
    return after;
  }

  // The conservative two-sided test of the patch with its moving vertices at p (at distance d_p
  // from the reference): new patch -> reference on refined grids, reference pieces -> new patch.
  bool certify(const Patch& patch, const Eigen::Vector3d& p, const Reference_sample& d_p,
               std::vector<Piece_cover>& covers) const {
    const std::vector<Triangle_corners> after = moved(patch, p);
    const bool global = m_options.reference == Hausdorff_reference::global;
    const auto sample = [&](const Eigen::Vector3d& x, std::size_t hint) {
      return patch_reference_sample(patch, x, hint);
    };
    const auto reference = [&](std::size_t t) -> const Triangle_corners& {
      return global ? m_input_corners[t] : patch.reference[t];
    };
    std::vector<Sampled_triangle> triangles;
    for (std::size_t j = 0; j < after.size(); ++j) {
      std::array<Reference_sample, 3> d = patch.corner_distances[j];
      for (int k = 0; k < 3; ++k)
        if (patch.moving[j][k]) d[k] = d_p;
      triangles.push_back({after[j], d});
    }
    const auto flat = [&](const Sampled_triangle& t) { return global && flat_covers(t); };
    if (!triangles_within(std::move(triangles), m_tolerance, m_options.max_refinement,
                          kSampleBudget, sample, reference, flat))
      return false;
    std::size_t hint = 0;
    for (std::size_t i = 0; i < patch.pieces.size(); ++i) {
      const std::size_t before = covers.size();
      if (cover_piece(patch.pieces[i], patch.piece_sources[i], after, m_tolerance,
                      m_options.max_refinement, hint, covers))
        continue;
      covers.resize(before);
      if (!cover_piece_along_fan(patch.pieces[i], after, p, m_tolerance, covers)) return false;
    }
    return true;
  }

  Hausdorff_bounded_options m_options;
  double m_diagonal = 0;
  double m_tolerance = 0;
  Search_triangles m_input;
  std::vector<Triangle_corners> m_input_corners;
  std::vector<std::array<std::uint32_t, 3>> m_input_neighbours;
  mutable std::vector<std::pair<std::uint32_t, std::uint8_t>> m_flat_state;  // stamp, state
  mutable std::uint32_t m_flat_stamp = 0;
  mutable std::vector<std::uint32_t> m_flat_stack;
  Search_tree m_tree;
  mutable typename Search_tree::Point_and_primitive_id m_hint;
  mutable bool m_has_hint = false;
  std::vector<Triangle_corners> m_pieces;
  Piece_list_map m_face_pieces;
  Frozen_map m_frozen;
  Distance_map m_distance;
  Order_map m_order;
  Pending m_pending;
  bool m_deferred_commits = false;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_TRACKER_H
