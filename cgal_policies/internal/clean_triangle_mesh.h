// A Surface_mesh built straight from the indices of a clean triangle soup. CGAL's general path
// (polygon_soup_to_polygon_mesh: a std::set of every edge to check the soup, then Euler::add_face
// per face) took most of the time of reading a file and of cutting a mesh into parts and stitching
// them; most soups are already an oriented manifold triangle mesh, and for those this is the same
// mesh, halfedge for halfedge, in a fraction of the time.
#ifndef CGAL_POLICIES_INTERNAL_CLEAN_TRIANGLE_MESH_H
#define CGAL_POLICIES_INTERNAL_CLEAN_TRIANGLE_MESH_H

#include <cgal_policies/internal/for_each_in_parallel.h>

#include <CGAL/Surface_mesh.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace cgal_policies {
namespace internal {
namespace clean_triangles {

// The index of a side or a point: 32 bits when the soup's sides and points number fewer than 2^32,
// which halves the memory of these tables (fresh memory is costly to fault in: docs/scale.md).
template <class Index>
constexpr Index kNone = (std::numeric_limits<Index>::max)();

// Side s runs along triangle s / 3 from its corner s to the triangle's next corner.
template <class Index>
Index next_corner(Index s) {
  return s % 3 == 2 ? s - 2 : s + 1;
}

// The sides leaving each point, grouped by point, with their heads: those of point p are
// leaving[first[p]] .. leaving[first[p + 1] - 1].
template <class Index>
struct Sides_by_tail {
  struct Side {
    Index head, side;
  };
  std::vector<Index> first;
  std::vector<Side> leaving;
};

template <class Index>
Sides_by_tail<Index> sides_by_tail(std::size_t point_count,
                                   const std::vector<std::size_t>& corners) {
  Sides_by_tail<Index> out;
  out.first.assign(point_count + 1, 0);
  for (std::size_t corner : corners) ++out.first[corner + 1];
  for (std::size_t p = 0; p < point_count; ++p) out.first[p + 1] += out.first[p];
  out.leaving.resize(corners.size());
  std::vector<Index> cursor(out.first.begin(), out.first.end() - 1);
  for (Index s = 0; s < corners.size(); ++s)
    out.leaving[cursor[corners[s]]++] = {Index(corners[next_corner(s)]), s};
  return out;
}

// The points of a soup go to the cores in blocks of this many: a point's work is a few loads.
constexpr std::size_t kPointsPerTask = std::size_t(1) << 14;

// The side running the other way along each side's edge, or kNone on a border; false when an
// oriented edge is used twice (which is also how an edge of three or more faces shows). Each point
// sets the twins of the sides leaving it, on up to `threads` cores.
template <class Index>
bool find_twins(const std::vector<std::size_t>& corners, const Sides_by_tail<Index>& by_tail,
                std::size_t threads, std::vector<Index>& twin) {
  twin.assign(corners.size(), kNone<Index>);
  std::atomic<bool> used_twice{false};
  for_each_in_blocks(by_tail.first.size() - 1, kPointsPerTask, threads, [&](std::size_t a) {
    const Index begin = by_tail.first[a], end = by_tail.first[a + 1];
    for (Index i = begin; i < end; ++i) {
      const auto [b, s] = by_tail.leaving[i];
      for (Index j = i + 1; j < end; ++j)
        if (by_tail.leaving[j].head == b) used_twice.store(true, std::memory_order_relaxed);
      for (Index j = by_tail.first[b]; j < by_tail.first[b + 1]; ++j)
        if (by_tail.leaving[j].head == a) twin[s] = by_tail.leaving[j].side;
    }
  });
  return !used_twice;
}

// Whether the halfedges into v, turning around v from halfedge(v), are all `expected` of them:
// a point where two fans meet shows fewer.
template <class Point>
bool is_one_fan(const CGAL::Surface_mesh<Point>& mesh, CGAL::SM_Vertex_index v,
                std::size_t expected) {
  const auto start = mesh.halfedge(v);
  auto h = start;
  for (std::size_t seen = 1; seen <= expected; ++seen) {
    h = mesh.opposite(mesh.next(h));
    if (h == start) return seen == expected;
  }
  return false;
}

// The body of build_clean_triangle_mesh below, its tables indexed by Index.
template <class Index, class Point>
bool build_with_indices(const std::vector<Point>& points, const std::vector<std::size_t>& corners,
                        CGAL::Surface_mesh<Point>& mesh, std::size_t& unused_points,
                        std::vector<CGAL::SM_Vertex_index>* vertex_of_point, std::size_t threads) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Halfedge = typename Mesh::Halfedge_index;
  using Vertex = typename Mesh::Vertex_index;
  mesh.clear();
  for (std::size_t s = 0; s < corners.size(); s += 3)
    if (corners[s] == corners[s + 1] || corners[s + 1] == corners[s + 2] ||
        corners[s + 2] == corners[s])
      return false;
  const Sides_by_tail<Index> by_tail = sides_by_tail<Index>(points.size(), corners);
  std::vector<Index> twin;
  if (!find_twins(corners, by_tail, threads, twin)) return false;

  std::size_t edge_count = 0;
  for (Index s = 0; s < twin.size(); ++s) edge_count += twin[s] == kNone<Index> || twin[s] > s;
  std::vector<Vertex> vertex_of(points.size());
  unused_points = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
    unused_points += by_tail.first[p] == by_tail.first[p + 1];
  const std::size_t face_count = corners.size() / 3;
  mesh.reserve(typename Mesh::size_type(points.size() - unused_points),
               typename Mesh::size_type(edge_count), typename Mesh::size_type(face_count));
  for (std::size_t p = 0; p < points.size(); ++p)
    if (by_tail.first[p] != by_tail.first[p + 1]) vertex_of[p] = mesh.add_vertex(points[p]);

  std::vector<Halfedge> halfedge_of(twin.size());
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto face = mesh.add_face();
    for (Index s = Index(3 * f); s < 3 * f + 3; ++s) {
      const Halfedge h =
          twin[s] != kNone<Index> && twin[s] < s
              ? mesh.opposite(halfedge_of[twin[s]])
              : mesh.add_edge(vertex_of[corners[s]], vertex_of[corners[next_corner(s)]]);
      mesh.set_face(h, face);
      halfedge_of[s] = h;
    }
    for (std::size_t i = 0; i < 3; ++i)
      mesh.set_next(halfedge_of[3 * f + i], halfedge_of[3 * f + (i + 1) % 3]);
    mesh.set_halfedge(face, halfedge_of[3 * f + 2]);
    for (Index s = Index(3 * f); s < 3 * f + 3; ++s)
      mesh.set_halfedge(vertex_of[corners[next_corner(s)]], halfedge_of[s]);
  }

  // A side without twin has a border halfedge opposite; it leaves the side's head. A point with
  // two border halfedges leaving it is where two fans touch.
  std::vector<Halfedge> border_leaving(points.size());
  for (Index s = 0; s < twin.size(); ++s) {
    if (twin[s] != kNone<Index>) continue;
    const Halfedge border = mesh.opposite(halfedge_of[s]);
    mesh.set_face(border, Mesh::null_face());
    Halfedge& leaving = border_leaving[corners[next_corner(s)]];
    if (leaving != Mesh::null_halfedge()) {
      mesh.clear();
      return false;
    }
    leaving = border;
  }
  // Each point has as many border halfedges in as out, so every border halfedge has a next; the
  // halfedge of a border vertex is its border halfedge in, as CGAL's border tests expect.
  for (Index s = 0; s < twin.size(); ++s) {
    if (twin[s] != kNone<Index>) continue;
    const Halfedge border = mesh.opposite(halfedge_of[s]);
    const std::size_t border_head = corners[s];
    mesh.set_next(border, border_leaving[border_head]);
    mesh.set_halfedge(vertex_of[border_head], border);
  }
  std::atomic<bool> two_fans{false};
  for_each_in_blocks(points.size(), kPointsPerTask, threads, [&](std::size_t p) {
    const std::size_t faces_around = by_tail.first[p + 1] - by_tail.first[p];
    if (faces_around == 0) return;
    const bool on_border = border_leaving[p] != Mesh::null_halfedge();
    if (!is_one_fan(mesh, vertex_of[p], faces_around + on_border))
      two_fans.store(true, std::memory_order_relaxed);
  });
  if (two_fans) {
    mesh.clear();
    return false;
  }
  if (vertex_of_point) *vertex_of_point = std::move(vertex_of);
  return true;
}

}  // namespace clean_triangles

// Builds `mesh` from the triangles `corners` (three point indices each, all below points.size())
// when each has three distinct points, no oriented edge is used twice, no edge has more than two
// faces, and the faces around each point form one fan: the mesh polygon_soup_to_polygon_mesh
// builds, its edges numbered as Euler::add_face numbers them, face by face. Points no face uses
// are left out and counted in `unused_points`; faces, and the used points, keep the soup's order.
// Returns false and leaves `mesh` empty when the soup is not such a mesh. `vertex_of_point`, when
// given, gets each point's vertex (a null index for an unused point). The checks around each
// point run on up to `threads` cores (0: all of them); the mesh is the same.
template <class Point>
bool build_clean_triangle_mesh(const std::vector<Point>& points,
                               const std::vector<std::size_t>& corners,
                               CGAL::Surface_mesh<Point>& mesh, std::size_t& unused_points,
                               std::vector<CGAL::SM_Vertex_index>* vertex_of_point = nullptr,
                               std::size_t threads = 1) {
  constexpr std::size_t kNarrow = clean_triangles::kNone<std::uint32_t>;
  if (points.size() < kNarrow && corners.size() < kNarrow)
    return clean_triangles::build_with_indices<std::uint32_t>(points, corners, mesh, unused_points,
                                                              vertex_of_point, threads);
  return clean_triangles::build_with_indices<std::size_t>(points, corners, mesh, unused_points,
                                                          vertex_of_point, threads);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_CLEAN_TRIANGLE_MESH_H
