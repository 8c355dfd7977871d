// A CGAL::Surface_mesh cut into the parts of a partitioned run and put back together. Each face
// goes to the cell of its centroid (Spatial_cells.h); a part is a mesh of its cell's faces with
// their corner attributes and materials, each vertex knowing the whole mesh's vertex it stands for
// (kOriginVertexMap). A vertex whose faces lie in more than one cell is on a cut: it
// is locked in every part (the vertex property map kLockedVertexMap), so that no collapse and no
// fitting move touches it and the parts still meet exactly along the cuts when they are stitched.
// A vertex whose faces in one cell form several fans (they are separated by faces of other cells)
// is one part vertex per fan, each locked; stitching makes them one vertex again.
#ifndef CGAL_POLICIES_INTERNAL_MESH_PARTS_H
#define CGAL_POLICIES_INTERNAL_MESH_PARTS_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/Spatial_cells.h>
#include <cgal_policies/internal/clean_triangle_mesh.h>
#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// Faces to a task where the centroids and cells of every face are computed in parallel.
constexpr std::size_t kFacesPerTask = std::size_t(1) << 16;

// The face centroids of `mesh` (which holds no garbage), to build the cells on and to cut by; on
// up to `threads` cores (0: all).
template <class Point>
std::vector<Eigen::Vector3d> face_centroids(const CGAL::Surface_mesh<Point>& mesh,
                                            std::size_t threads) {
  std::vector<Eigen::Vector3d> centroids(mesh.number_of_faces());
  for_each_in_blocks(centroids.size(), kFacesPerTask, threads, [&](std::size_t i) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    const typename CGAL::Surface_mesh<Point>::Face_index f(static_cast<std::uint32_t>(i));
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      sum += to_eigen(mesh.point(v));
    centroids[i] = sum / 3;
  });
  return centroids;
}

// The cell of every face, by its centroid.
inline std::vector<std::uint32_t> face_cells(const std::vector<Eigen::Vector3d>& centroids,
                                             const Spatial_cells& cells, std::size_t threads) {
  std::vector<std::uint32_t> cell(centroids.size());
  for_each_in_blocks(cell.size(), kFacesPerTask, threads,
                     [&](std::size_t f) { cell[f] = std::uint32_t(cells.cell_of(centroids[f])); });
  return cell;
}

template <class Point>
std::vector<std::uint32_t> face_cells(const CGAL::Surface_mesh<Point>& mesh,
                                      const Spatial_cells& cells, std::size_t threads) {
  return face_cells(face_centroids(mesh, threads), cells, threads);
}

// The corner values and materials of face i of `to` from the corners `corners[i]` of the mesh
// `from[i]`: `to` was built from the triangles `triangles` (three point indices each) of points
// that are all used, so that point j is vertex j of `to` and triangle i, its corners in the order
// of corners[i], is face i.
template <class Point>
void copy_corner_values(const std::vector<const CGAL::Surface_mesh<Point>*>& from,
                        const std::vector<std::array<CGAL::SM_Halfedge_index, 3>>& corners,
                        const std::vector<std::size_t>& triangles, CGAL::Surface_mesh<Point>& to) {
  using Attributes = Corner_attributes<Point>;
  if (from.empty() || !Attributes(*from.front()).any()) return;
  const Attributes target = Attributes::add(to, Attributes(*from.front()).kinds());
  std::size_t i = 0;
  const CGAL::Surface_mesh<Point>* read = nullptr;  // the mesh `source` reads, while it stays
  std::optional<Attributes> source;
  for (const auto f : to.faces()) {
    if (from[i] != read) source.emplace(*(read = from[i]));
    if (target.materials) (*target.materials)[f] = (*source->materials)[read->face(corners[i][0])];
    const auto triangle = triangles.begin() + std::ptrdiff_t(3 * i);
    for (const auto h : CGAL::halfedges_around_face(to.halfedge(f), to)) {
      const auto k = std::find(triangle, triangle + 3, std::size_t(to.target(h))) - triangle;
      target.set_values(h, source->values(corners[i][std::size_t(k)]));
    }
    ++i;
  }
}

// The faces of cell `c` of `mesh` (manifold, no garbage) as a part's soup, `cell` giving each
// face's cell: one point per fan of a vertex's faces in the cell, numbered in the order of the
// fans' first corners; per face, in the order of faces(mesh), its corners around
// mesh.halfedge(f) as halfedges of `mesh` and as point numbers.
template <class Point>
struct Cell_soup {
  using Halfedge = typename CGAL::Surface_mesh<Point>::Halfedge_index;
  std::vector<std::array<Halfedge, 3>> corners;
  std::vector<std::size_t> triangles;  // three point numbers a face
  std::vector<Halfedge> fan_starts;    // of each point, the first corner of its fan
  std::vector<char> locked;            // of each point: its vertex has faces in other cells
};

// A vertex whose faces in the cell make several fans is a point per fan, which a part's link
// condition takes for distinct vertices: a collapse could join a neighbour of one fan to another
// fan, and the stitching, making the fans one vertex again, would then give their edge three
// faces or more. Every point of those fans' faces is locked too, so that no collapse in the part
// gives a fan point a new neighbour.
template <class Point>
void lock_fans_of_split_vertices(const CGAL::Surface_mesh<Point>& mesh, Cell_soup<Point>& soup) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> locked_points;  // (vertex, point)
  for (std::size_t p = 0; p < soup.fan_starts.size(); ++p)
    if (soup.locked[p])
      locked_points.emplace_back(std::uint32_t(mesh.target(soup.fan_starts[p])), std::uint32_t(p));
  std::sort(locked_points.begin(), locked_points.end());
  std::vector<char> split(soup.fan_starts.size(), false);
  bool any = false;
  for (std::size_t i = 1; i < locked_points.size(); ++i) {
    if (locked_points[i].first != locked_points[i - 1].first) continue;
    split[locked_points[i].second] = split[locked_points[i - 1].second] = true;
    any = true;
  }
  if (!any) return;
  for (std::size_t s = 0; s < soup.triangles.size(); s += 3) {
    const std::size_t* t = &soup.triangles[s];
    if (split[t[0]] || split[t[1]] || split[t[2]])
      soup.locked[t[0]] = soup.locked[t[1]] = soup.locked[t[2]] = true;
  }
}

template <class Point>
Cell_soup<Point> cell_soup(const CGAL::Surface_mesh<Point>& mesh,
                           const std::vector<std::uint32_t>& cell, std::uint32_t c) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Halfedge = typename Mesh::Halfedge_index;
  const auto in_cell = [&](Halfedge h) {
    return !mesh.is_border(h) && cell[std::size_t(mesh.face(h))] == c;
  };
  // The corner h (target v) belongs to the fan of v's faces in the cell that starts at the
  // returned corner: the first one going clockwise, or halfedge(v) when the fan is v's whole star.
  // Most vertices lie inside a cell: whether v's whole star is in it is found once per vertex.
  enum : std::uint8_t { unknown, whole_star, cut_star };
  std::vector<std::uint8_t> star(mesh.num_vertices(), unknown);
  const auto fan_start = [&](Halfedge h) {
    std::uint8_t& state = star[std::size_t(mesh.target(h))];
    if (state == unknown) {
      state = whole_star;
      for (const Halfedge g : CGAL::halfedges_around_target(h, mesh))
        if (!in_cell(g)) {
          state = cut_star;
          break;
        }
    }
    if (state == whole_star) return mesh.halfedge(mesh.target(h));
    for (Halfedge g = h;;) {
      const Halfedge before = mesh.prev(mesh.opposite(g));
      if (!in_cell(before)) return g;
      g = before;
    }
  };
  // Asked of each point's vertex after the cut, when its star's state is known.
  const auto locked = [&](typename Mesh::Vertex_index v) {
    if (star[std::size_t(v)] == whole_star) return false;
    for (const Halfedge h : CGAL::halfedges_around_target(v, mesh))
      if (!mesh.is_border(h) && cell[std::size_t(mesh.face(h))] != c) return true;
    return false;
  };
  // Points by their fan's first corner, in the order of those corners' indices: a bit per
  // halfedge of `mesh` marks the first corners, and a point's number is the count of marks
  // before its corner's.
  Cell_soup<Point> soup;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint64_t> is_start((mesh.num_halfedges() + 63) / 64, 0);
  for (const auto f : mesh.faces()) {
    if (cell[std::size_t(f)] != c) continue;
    std::array<Halfedge, 3> face_corners;
    std::array<std::uint32_t, 3> t;
    int k = 0;
    for (const Halfedge h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      face_corners[k] = h;
      t[k] = std::uint32_t(std::size_t(fan_start(h)));
      is_start[t[k] / 64] |= std::uint64_t(1) << (t[k] % 64);
      ++k;
    }
    soup.corners.push_back(face_corners);
    triangles.push_back(t);
  }
  std::vector<std::uint32_t> starts_before(is_start.size());
  for (std::size_t w = 0; w < is_start.size(); ++w) {
    starts_before[w] = std::uint32_t(soup.fan_starts.size());
    for (std::uint64_t bits = is_start[w]; bits != 0; bits &= bits - 1)
      soup.fan_starts.push_back(
          Halfedge(std::uint32_t(64 * w + std::bitset<64>(~bits & (bits - 1)).count())));
  }
  soup.triangles.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (const std::uint32_t start : t) {
      const std::uint64_t below = (std::uint64_t(1) << (start % 64)) - 1;
      soup.triangles.push_back(starts_before[start / 64] +
                               std::bitset<64>(is_start[start / 64] & below).count());
    }
  soup.locked.reserve(soup.fan_starts.size());
  for (const Halfedge start : soup.fan_starts) soup.locked.push_back(locked(mesh.target(start)));
  lock_fans_of_split_vertices(mesh, soup);
  return soup;
}

// The part of cell `c` of `mesh` (manifold, no garbage), `cell` giving each face's cell.
// Without corner values when `with_values` is false (the input of a partitioned fit).
template <class Point>
CGAL::Surface_mesh<Point> mesh_part(const CGAL::Surface_mesh<Point>& mesh,
                                    const std::vector<std::uint32_t>& cell, std::uint32_t c,
                                    bool with_values = true) {
  using Mesh = CGAL::Surface_mesh<Point>;
  const Cell_soup<Point> soup = cell_soup(mesh, cell, c);
  std::vector<Point> points;
  points.reserve(soup.fan_starts.size());
  for (const auto start : soup.fan_starts) points.push_back(mesh.point(mesh.target(start)));
  Mesh part;
  std::size_t unused_points = 0;
  // Each fan is a vertex of its own, so the part is a clean mesh whenever `mesh` is one.
  if (!build_clean_triangle_mesh(points, soup.triangles, part, unused_points))
    throw std::logic_error("mesh_part: the cell's faces are not a manifold mesh");
  add_part_vertex_maps(
      part, [&](auto v) { return mesh.target(soup.fan_starts[std::size_t(v)]); },
      [&](auto v) { return bool(soup.locked[std::size_t(v)]); });
  if (with_values)
    copy_corner_values(std::vector<const Mesh*>(soup.corners.size(), &mesh), soup.corners,
                       soup.triangles, part);
  return part;
}

// Not yet among the stitched points (stitched_point).
constexpr std::size_t kNotStitched = std::size_t(-1);

// The index among the stitched `points` of a part vertex at `point` that stands for the whole's
// vertex `origin`: a locked vertex's point is added once for every part that has it (`shared`
// keeps it by origin, kNotStitched until then), any other vertex's anew.
template <class Point>
std::size_t stitched_point(std::size_t origin, bool locked, const Point& point,
                           std::vector<std::size_t>& shared, std::vector<Point>& points) {
  std::size_t& slot = shared[origin];
  if (locked && slot != kNotStitched) return slot;
  if (locked) slot = points.size();
  points.push_back(point);
  return points.size() - 1;
}

// The parts put back together: the vertices of every part (their origin shared where they are
// locked) and their faces, part after part, with their corner values.
template <class Point>
CGAL::Surface_mesh<Point> stitch_parts(const std::vector<CGAL::Surface_mesh<Point>>& parts,
                                       std::size_t whole_vertices) {
  using Mesh = CGAL::Surface_mesh<Point>;
  std::vector<std::size_t> shared(whole_vertices, kNotStitched);
  std::vector<Point> points;
  std::vector<std::size_t> triangles;
  std::vector<std::array<CGAL::SM_Halfedge_index, 3>> corners;
  std::vector<const Mesh*> owner;
  for (const Mesh& m : parts) {
    const auto lock = find_vertex_map<bool>(m, kLockedVertexMap);
    const auto origin = find_vertex_map<CGAL::SM_Vertex_index>(m, kOriginVertexMap);
    std::vector<std::size_t> index(m.num_vertices(), kNotStitched);
    for (const auto v : m.vertices())
      index[std::size_t(v)] =
          stitched_point(std::size_t((*origin)[v]), (*lock)[v], m.point(v), shared, points);
    for (const auto f : m.faces()) {
      std::array<CGAL::SM_Halfedge_index, 3> c;
      int k = 0;
      for (const auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        triangles.push_back(index[std::size_t(m.target(h))]);
        c[k++] = h;
      }
      corners.push_back(c);
      owner.push_back(&m);
    }
  }
  Mesh whole;
  std::size_t unused_points = 0;
  if (build_clean_triangle_mesh(points, triangles, whole, unused_points)) {
    copy_corner_values(owner, corners, triangles, whole);
    return whole;
  }
  // The parts of a streamed run were never one mesh: where the input's surface is not manifold,
  // they meet again in a vertex or an edge that is not, split here as in the parts. Such parts
  // carry no corner values.
  std::vector<std::vector<std::size_t>> polygons;
  for (std::size_t s = 0; s < triangles.size(); s += 3)
    polygons.push_back({triangles[s], triangles[s + 1], triangles[s + 2]});
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, whole);
  return whole;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_MESH_PARTS_H
