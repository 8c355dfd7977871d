// The cut of a streamed run (Simplification_pipeline::run_streamed, docs/scale.md): a mesh too
// large to hold whole, read from a source in passes, and cut into the cells of Spatial_cells
// without ever being a CGAL::Surface_mesh. A source is any object with
//   void for_each_point(F f) const     calling f(x, y, z) for each vertex, in order
//   void for_each_triangle(F f) const  calling f(a, b, c), the numbers of three vertices,
//                                      for each triangle, the same ones on every pass
// and, when its corners carry values (Streamed_corners.h),
//   Kinds corner_kinds() const         Corner_attributes<Point>::Kinds, after for_each_point
// with for_each_triangle calling f(a, b, c, corners), corners a Streamed_corners<Point>
// (apps/io/Streamed_mesh_file.h reads binary PLY and OBJ files so). Memory: the points, a cell
// per point, and one cell's part at a time per thread; the triangles and their corners' values
// wait on disk (Spill_files).
#ifndef CGAL_POLICIES_INTERNAL_STREAMED_CUT_H
#define CGAL_POLICIES_INTERNAL_STREAMED_CUT_H

#include <cgal_policies/internal/Spatial_cells.h>
#include <cgal_policies/internal/Spill_files.h>
#include <cgal_policies/internal/Streamed_corners.h>
#include <cgal_policies/internal/clean_triangle_mesh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace cgal_policies {
namespace internal {

// Faces whose centroids the cells are built on: all of them up to twice this, else every k-th.
constexpr std::size_t kCellSample = std::size_t(1) << 20;

// What the first passes over a source keep: its points, those exactly equal joined into one (so
// that no edge has zero length and a cut never runs between two copies of a point); the number of
// the joined point of each source point; a sample of the face centroids; the triangles' count;
// the kinds of values their corners carry.
template <class Point>
struct Streamed_input {
  std::vector<Point> points;
  std::vector<std::uint32_t> joined;
  std::vector<Eigen::Vector3d> sample;
  std::size_t faces = 0;
  typename Corner_attributes<Point>::Kinds kinds;

  // The source triangle (a, b, c) in joined numbers; false when two of them are one point.
  bool triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, Spill_files::Triangle& t) const {
    if (std::size_t(std::max({a, b, c})) >= joined.size())
      throw std::out_of_range("a triangle names a vertex the source does not have");
    t = {joined[a], joined[b], joined[c]};
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
  }

  Eigen::Vector3d centroid(const Spill_files::Triangle& t) const {
    return (to_eigen(points[t[0]]) + to_eigen(points[t[1]]) + to_eigen(points[t[2]])) / 3;
  }
};

// The exact bits of a point's coordinates, -0 made +0 so that equal points hash alike.
template <class Point>
std::size_t point_hash(const Point& p) {
  std::size_t hash = 0;
  for (const double c : {p.x() + 0.0, p.y() + 0.0, p.z() + 0.0}) {
    std::uint64_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    hash = (hash ^ bits) * 0x9E3779B97F4A7C15ull;
  }
  return hash ^ (hash >> 29);
}

// Two passes: the points (joined in an open-addressing table of 8 bytes a point), then the
// triangles, for their count and the centroid sample (every stride-th triangle, the stride doubled
// whenever the sample reaches 2 kCellSample).
template <class Point, class Source>
Streamed_input<Point> read_streamed_input(const Source& source) {
  Streamed_input<Point> input;
  std::vector<Point>& points = input.points;
  source.for_each_point([&](double x, double y, double z) { points.emplace_back(x, y, z); });
  if (points.size() >= std::size_t(UINT32_MAX))
    throw std::length_error("more than 2^32 - 1 vertices");
  constexpr std::uint32_t kEmpty = UINT32_MAX;
  std::size_t capacity = 1;
  while (capacity < 2 * points.size()) capacity *= 2;
  std::vector<std::uint32_t> table(capacity, kEmpty);
  input.joined.resize(points.size());
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t slot = point_hash(points[i]) & (capacity - 1);
    while (table[slot] != kEmpty && !(points[table[slot]] == points[i]))
      slot = (slot + 1) & (capacity - 1);
    if (table[slot] == kEmpty) {
      table[slot] = kept;
      points[kept++] = points[i];  // kept <= i: the table names only points already moved
    }
    input.joined[i] = table[slot];
  }
  table = {};
  points.resize(kept);
  points.shrink_to_fit();
  input.kinds = corner_kinds_of<Point>(source);

  std::size_t stride = 1;
  source.for_each_triangle([&](std::uint32_t a, std::uint32_t b, std::uint32_t c, const auto&...) {
    Spill_files::Triangle t;
    if (!input.triangle(a, b, c, t)) return;
    if (input.faces++ % stride != 0) return;
    input.sample.push_back(input.centroid(t));
    if (input.sample.size() < 2 * kCellSample) return;
    for (std::size_t k = 0; k < kCellSample; ++k) input.sample[k] = input.sample[2 * k];
    input.sample.resize(kCellSample);
    stride *= 2;
  });
  return input;
}

// The cell of a point no triangle uses, and of a point whose triangles lie in several cells.
constexpr std::uint32_t kNoCell = UINT32_MAX, kCutCell = UINT32_MAX - 1;

// A third pass: each triangle, with its corners' values, into the spill file of its centroid's
// cell (`spills` holding streamed_corner_doubles(input.kinds) a triangle). Returns each point's
// cell: the one of all its triangles, or kCutCell.
template <class Point, class Source>
std::vector<std::uint32_t> cut_into_spills(const Source& source, const Streamed_input<Point>& input,
                                           const Spatial_cells& cells, Spill_files& spills) {
  std::vector<std::uint32_t> vertex_cell(input.points.size(), kNoCell);
  std::vector<double> values(spills.doubles());
  source.for_each_triangle(
      [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, const auto&... corners) {
        Spill_files::Triangle t;
        if (!input.triangle(a, b, c, t)) return;
        const std::uint32_t cell = std::uint32_t(cells.cell_of(input.centroid(t)));
        (encode_streamed_corners<Point>(input.kinds, corners, values.data()), ...);
        spills.append(cell, t, values.data());
        for (const std::uint32_t v : t)
          vertex_cell[v] = vertex_cell[v] == kNoCell || vertex_cell[v] == cell ? cell : kCutCell;
      });
  spills.close();
  return vertex_cell;
}

// The spilled triangles of `from` again, into `to` by the cells `cells` (the fit's second cut).
template <class Point>
void spill_again(const Streamed_input<Point>& input, const Spill_files& from,
                 const Spatial_cells& cells, Spill_files& to) {
  for (std::size_t c = 0; c < from.size(); ++c) {
    const Spill_files::Cell cell = from.read(c);
    for (std::size_t i = 0; i < cell.triangles.size(); ++i)
      to.append(cells.cell_of(input.centroid(cell.triangles[i])), cell.triangles[i],
                cell.values.data() + i * from.doubles());
  }
  to.close();
}

// Records, for orient_polygon_soup, where each point it adds comes from.
struct Duplicated_point_origins : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::vector<std::uint32_t>* origin = nullptr;
  void duplicated_vertex(std::size_t from, std::size_t to) {
    if (origin->size() <= to) origin->resize(to + 1);
    (*origin)[to] = (*origin)[from];
  }
};

// Sets the corner values and materials of `part`, whose face i is the spilled triangle i of
// `cell` (turned over, maybe, by orient_polygon_soup) and whose vertex v stands for the joined
// point origin[v]: a triangle's three points differ, so each corner is found by its origin.
template <class Point>
void add_streamed_corner_values(CGAL::Surface_mesh<Point>& part,
                                const std::vector<std::uint32_t>& origin,
                                const Spill_files::Cell& cell,
                                const typename Corner_attributes<Point>::Kinds& kinds) {
  using Attributes = Corner_attributes<Point>;
  const std::size_t doubles = streamed_corner_doubles<Point>(kinds);
  if (doubles == 0) return;
  const Attributes attributes = Attributes::add(part, kinds);
  std::size_t i = 0;
  for (const auto f : part.faces()) {
    const Spill_files::Triangle& t = cell.triangles[i];
    const Streamed_corners<Point> corners =
        decode_streamed_corners<Point>(kinds, cell.values.data() + i * doubles);
    if (attributes.materials) (*attributes.materials)[f] = corners.material;
    for (const auto h : CGAL::halfedges_around_face(part.halfedge(f), part)) {
      const std::uint32_t o = origin[std::size_t(part.target(h))];
      attributes.set_values(
          h, corners.values[std::size_t(std::find(t.begin(), t.end(), o) - t.begin())]);
    }
    ++i;
  }
}

// The part of the spilled triangles of one cell, as Mesh_parts.h makes a part: each vertex's
// origin (kOriginVertexMap, the joined point it stands for) and whether it is on a cut
// (kLockedVertexMap), and, when `kinds` names any, its corners' values and its faces' materials.
// A point whose triangles in the cell make several fans, or meet along an edge of more than two of
// them, becomes one vertex per fan (orient_polygon_soup), all of one origin.
template <class Point>
CGAL::Surface_mesh<Point> streamed_part(const std::vector<Point>& points,
                                        const std::vector<std::uint32_t>& vertex_cell,
                                        const Spill_files::Cell& cell,
                                        const typename Corner_attributes<Point>::Kinds& kinds) {
  using Mesh = CGAL::Surface_mesh<Point>;
  const std::vector<Spill_files::Triangle>& triangles = cell.triangles;
  std::vector<std::uint32_t> origin;
  origin.reserve(3 * triangles.size());
  for (const Spill_files::Triangle& t : triangles) origin.insert(origin.end(), t.begin(), t.end());
  std::sort(origin.begin(), origin.end());
  origin.erase(std::unique(origin.begin(), origin.end()), origin.end());
  std::vector<Point> part_points;
  part_points.reserve(origin.size());
  for (const std::uint32_t v : origin) part_points.push_back(points[v]);
  std::vector<std::size_t> corners;
  corners.reserve(3 * triangles.size());
  for (const Spill_files::Triangle& t : triangles)
    for (int k = 0; k < 3; ++k)
      corners.push_back(
          std::size_t(std::lower_bound(origin.begin(), origin.end(), t[k]) - origin.begin()));
  Mesh part;
  std::size_t unused_points = 0;
  if (!build_clean_triangle_mesh(part_points, corners, part, unused_points)) {
    std::vector<std::array<std::size_t, 3>> polygons(triangles.size());
    for (std::size_t i = 0; i < polygons.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k) polygons[i][k] = corners[3 * i + k];
    Duplicated_point_origins visitor;
    visitor.origin = &origin;
    CGAL::Polygon_mesh_processing::orient_polygon_soup(part_points, polygons,
                                                       CGAL::parameters::visitor(visitor));
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(part_points, polygons, part);
  }
  add_part_vertex_maps(
      part, [&](auto v) { return typename Mesh::Vertex_index(origin[std::size_t(v)]); },
      [&](auto v) { return vertex_cell[origin[std::size_t(v)]] == kCutCell; });
  add_streamed_corner_values(part, origin, cell, kinds);
  return part;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_STREAMED_CUT_H
