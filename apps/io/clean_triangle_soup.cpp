#include "clean_triangle_soup.h"

#include <limits>
#include <utility>

namespace cgal_policies {
namespace io {
namespace {

using Halfedge = Mesh::Halfedge_index;
using Vertex = Mesh::Vertex_index;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// The corners of the soup's triangles, face after face, when every polygon is a triangle of three
// distinct points; empty otherwise. Side s runs along face s / 3 from corner s to the face's next
// corner.
std::vector<std::size_t> triangle_corners(const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::size_t> corners;
  corners.reserve(3 * polygons.size());
  for (const auto& p : polygons) {
    if (p.size() != 3 || p[0] == p[1] || p[1] == p[2] || p[2] == p[0]) return {};
    corners.insert(corners.end(), p.begin(), p.end());
  }
  return corners;
}

std::size_t next_corner(std::size_t s) { return s % 3 == 2 ? s - 2 : s + 1; }

// The sides leaving each point, grouped by point, with their heads: those of point p are
// leaving[first[p]] .. leaving[first[p + 1] - 1].
struct Sides_by_tail {
  struct Side {
    std::size_t head, side;
  };
  std::vector<std::size_t> first;
  std::vector<Side> leaving;
};

Sides_by_tail sides_by_tail(std::size_t point_count, const std::vector<std::size_t>& corners) {
  Sides_by_tail out;
  out.first.assign(point_count + 1, 0);
  for (std::size_t corner : corners) ++out.first[corner + 1];
  for (std::size_t p = 0; p < point_count; ++p) out.first[p + 1] += out.first[p];
  out.leaving.resize(corners.size());
  std::vector<std::size_t> cursor(out.first.begin(), out.first.end() - 1);
  for (std::size_t s = 0; s < corners.size(); ++s)
    out.leaving[cursor[corners[s]]++] = {corners[next_corner(s)], s};
  return out;
}

// The side running the other way along each side's edge, or kNone on a border; false when an
// oriented edge is used twice (which is also how an edge of three or more faces shows).
bool find_twins(const std::vector<std::size_t>& corners, const Sides_by_tail& by_tail,
                std::vector<std::size_t>& twin) {
  twin.assign(corners.size(), kNone);
  for (std::size_t a = 0; a + 1 < by_tail.first.size(); ++a) {
    const std::size_t begin = by_tail.first[a], end = by_tail.first[a + 1];
    for (std::size_t i = begin; i < end; ++i) {
      const auto [b, s] = by_tail.leaving[i];
      for (std::size_t j = i + 1; j < end; ++j)
        if (by_tail.leaving[j].head == b) return false;
      for (std::size_t j = by_tail.first[b]; j < by_tail.first[b + 1]; ++j)
        if (by_tail.leaving[j].head == a) twin[s] = by_tail.leaving[j].side;
    }
  }
  return true;
}

// Whether the halfedges into v, turning around v from halfedge(v), are all `expected` of them:
// a point where two fans meet shows fewer.
bool is_one_fan(const Mesh& mesh, Vertex v, std::size_t expected) {
  const Halfedge start = mesh.halfedge(v);
  Halfedge h = start;
  for (std::size_t seen = 1; seen <= expected; ++seen) {
    h = mesh.opposite(mesh.next(h));
    if (h == start) return seen == expected;
  }
  return false;
}

}  // namespace

bool build_mesh_from_clean_triangles(const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons,
                                     Mesh& mesh, std::size_t& unused_points,
                                     std::vector<Mesh::Vertex_index>* vertex_of_point) {
  mesh.clear();
  const std::vector<std::size_t> corners = triangle_corners(polygons);
  if (corners.empty()) return false;
  const Sides_by_tail by_tail = sides_by_tail(points.size(), corners);
  std::vector<std::size_t> twin;
  if (!find_twins(corners, by_tail, twin)) return false;

  std::size_t edge_count = 0;
  for (std::size_t s = 0; s < twin.size(); ++s) edge_count += twin[s] == kNone || twin[s] > s;
  std::vector<Vertex> vertex_of(points.size());
  unused_points = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
    unused_points += by_tail.first[p] == by_tail.first[p + 1];
  mesh.reserve(Mesh::size_type(points.size() - unused_points), Mesh::size_type(edge_count),
               Mesh::size_type(polygons.size()));
  for (std::size_t p = 0; p < points.size(); ++p)
    if (by_tail.first[p] != by_tail.first[p + 1]) vertex_of[p] = mesh.add_vertex(points[p]);

  // Edges are numbered as Euler::add_face numbers them, face by face, so that a run on a clean
  // file meets its edges in the same order whichever path read it.
  std::vector<Halfedge> halfedge_of(twin.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto face = mesh.add_face();
    for (std::size_t s = 3 * f; s < 3 * f + 3; ++s) {
      const Halfedge h =
          twin[s] != kNone && twin[s] < s
              ? mesh.opposite(halfedge_of[twin[s]])
              : mesh.add_edge(vertex_of[corners[s]], vertex_of[corners[next_corner(s)]]);
      mesh.set_face(h, face);
      halfedge_of[s] = h;
    }
    for (std::size_t i = 0; i < 3; ++i)
      mesh.set_next(halfedge_of[3 * f + i], halfedge_of[3 * f + (i + 1) % 3]);
    mesh.set_halfedge(face, halfedge_of[3 * f + 2]);
    for (std::size_t s = 3 * f; s < 3 * f + 3; ++s)
      mesh.set_halfedge(vertex_of[corners[next_corner(s)]], halfedge_of[s]);
  }

  // A side without twin has a border halfedge opposite; it leaves the side's head. A point with
  // two border halfedges leaving it is where two fans touch.
  std::vector<Halfedge> border_leaving(points.size());
  for (std::size_t s = 0; s < twin.size(); ++s) {
    if (twin[s] != kNone) continue;
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
  for (std::size_t s = 0; s < twin.size(); ++s) {
    if (twin[s] != kNone) continue;
    const Halfedge border = mesh.opposite(halfedge_of[s]);
    const std::size_t border_head = corners[s];
    mesh.set_next(border, border_leaving[border_head]);
    mesh.set_halfedge(vertex_of[border_head], border);
  }
  for (std::size_t p = 0; p < points.size(); ++p) {
    const std::size_t faces_around = by_tail.first[p + 1] - by_tail.first[p];
    if (faces_around == 0) continue;
    const bool on_border = border_leaving[p] != Mesh::null_halfedge();
    if (!is_one_fan(mesh, vertex_of[p], faces_around + on_border)) {
      mesh.clear();
      return false;
    }
  }
  if (vertex_of_point) *vertex_of_point = std::move(vertex_of);
  return true;
}

}  // namespace io
}  // namespace cgal_policies
