// A part of a partitioned run kept as arrays for the flat-array engines (fast, flat_lt) on a mesh
// without corner values (docs/scale.md, "Parts as arrays"): the vertices and triangles that
// Flat_mesh_copy reads from mesh_part's mesh, made straight from the cut, handed from one engine
// to the next and stitched from the arrays, so that no part is built as a CGAL::Surface_mesh and
// rebuilt after each engine. The engines see the same arrays in the same order, so the result is
// the same, byte for byte.
#ifndef CGAL_POLICIES_INTERNAL_FLAT_PART_H
#define CGAL_POLICIES_INTERNAL_FLAT_PART_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Fast_threshold_engine.h>
#include <cgal_policies/internal/Lindstrom_turk_engine.h>
#include <cgal_policies/internal/Mesh_parts.h>
#include <cgal_policies/internal/clean_triangle_mesh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/plane_quadrics.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace cgal_policies {
namespace internal {

struct Flat_part {
  std::vector<Eigen::Vector3d> points;
  std::vector<char> border;           // on the part's border: the input's, or a cut
  std::vector<char> locked;           // on a cut
  std::vector<std::uint32_t> origin;  // the whole mesh's vertex each stands for
  // Each face's vertices from its halfedge's source, as Flat_mesh_copy reads a face.
  std::vector<std::array<int, 3>> triangles;
  // Until an engine has run, each triangle's sides on the part's border: bit j for the side from
  // v[j] to v[j + 1] (the first engine's border planes).
  std::vector<std::uint8_t> border_sides;

  double diagonal() const {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : points) box.extend(p);
    return points.empty() ? 0.0 : box.diagonal().norm();
  }
};

// The part of cell `c` of `mesh` (manifold, no garbage, no corner values), `cell` giving each
// face's cell: Flat_mesh_copy of mesh_part(mesh, cell, c), without that mesh.
template <class Point>
Flat_part flat_part(const CGAL::Surface_mesh<Point>& mesh, const std::vector<std::uint32_t>& cell,
                    std::uint32_t c) {
  Cell_soup<Point> soup = cell_soup(mesh, cell, c);
  Flat_part part;
  part.points.reserve(soup.fan_starts.size());
  part.origin.reserve(soup.fan_starts.size());
  for (const auto start : soup.fan_starts) {
    const auto v = mesh.target(start);
    part.points.push_back(to_eigen(mesh.point(v)));
    part.origin.push_back(std::uint32_t(v));
  }
  part.locked = std::move(soup.locked);
  part.border.assign(part.points.size(), false);
  // The part's halfedge of a face runs from its third corner to its first (clean_triangle_mesh.h),
  // so the face (t0, t1, t2) reads (t2, t0, t1); side j is then the corner halfedge j of `mesh`.
  part.triangles.reserve(soup.corners.size());
  part.border_sides.reserve(soup.corners.size());
  for (std::size_t f = 0; f < soup.corners.size(); ++f) {
    const std::size_t* t = &soup.triangles[3 * f];
    part.triangles.push_back({int(t[2]), int(t[0]), int(t[1])});
    std::uint8_t sides = 0;
    for (int j = 0; j < 3; ++j) {
      const auto across = mesh.opposite(soup.corners[f][std::size_t(j)]);
      if (!mesh.is_border(across) && cell[std::size_t(mesh.face(across))] == c) continue;
      sides |= std::uint8_t(1u << j);
      part.border[std::size_t(part.triangles.back()[std::size_t(j)])] = true;
      part.border[std::size_t(part.triangles.back()[std::size_t((j + 1) % 3)])] = true;
    }
    part.border_sides.push_back(sides);
  }
  return part;
}

// The vertices of the fast engine for `part`, before any engine ran on it: each vertex's face
// planes and border planes summed as accumulate_vertex_quadrics sums them over mesh_part's mesh.
inline std::vector<Fast_threshold_vertex> fast_threshold_vertices(const Flat_part& part,
                                                                  Face_weighting weighting,
                                                                  double border_weight) {
  std::vector<Fast_threshold_vertex> vertices(part.points.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = {part.points[i], Quadric(), bool(part.border[i]), bool(part.locked[i])};
  for (std::size_t f = 0; f < part.triangles.size(); ++f) {
    const std::array<int, 3>& t = part.triangles[f];
    const auto at = [&](int j) -> const Eigen::Vector3d& {
      return part.points[std::size_t(t[std::size_t(j % 3)])];
    };
    const Eigen::Vector3d normal = triangle_area_normal(at(0), at(1), at(2));
    const Quadric face = triangle_plane_quadric(normal, at(1), weighting);
    for (int j = 0; j < 3; ++j) {
      Quadric& head = vertices[std::size_t(t[std::size_t((j + 1) % 3)])].quadric;
      head += face;
      if ((part.border_sides[f] >> j & 1u) == 0) continue;
      const Quadric side = border_side_quadric(at(j), at(j + 1), normal, border_weight, weighting);
      vertices[std::size_t(t[std::size_t(j)])].quadric += side;
      head += side;
    }
  }
  return vertices;
}

// The vertices of the Lindström–Turk engine for `part`.
inline std::vector<Lindstrom_turk_vertex> lindstrom_turk_vertices(const Flat_part& part) {
  std::vector<Lindstrom_turk_vertex> vertices;
  vertices.reserve(part.points.size());
  for (std::size_t i = 0; i < part.points.size(); ++i)
    vertices.push_back({part.points[i], bool(part.border[i]), bool(part.locked[i])});
  return vertices;
}

// `part` becomes what an engine made of it (`flat`, its Flat_collapse_mesh): the vertices kept,
// in their order, and the faces as Flat_mesh_copy would read them from the rebuilt mesh, whose
// face halfedge runs from a triangle's third vertex to its first (Euler::add_face).
template <class Flat_mesh>
void take_engine_result(Flat_mesh& flat, Flat_part& part) {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> kept;
  flat.extract(points, triangles, nullptr, nullptr, &kept);
  std::vector<char> border(kept.size()), locked(kept.size());
  std::vector<std::uint32_t> origin(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    border[i] = flat.vertex(kept[i]).border;
    locked[i] = flat.vertex(kept[i]).locked;
    origin[i] = part.origin[std::size_t(kept[i])];
  }
  for (std::array<int, 3>& t : triangles) t = {t[2], t[0], t[1]};
  part.points = std::move(points);
  part.triangles = std::move(triangles);
  part.border = std::move(border);
  part.locked = std::move(locked);
  part.origin = std::move(origin);
  part.border_sides.clear();
}

// The parts put back together as stitch_parts puts the meshes they stand for: the vertices of
// every part (their origin shared where they are locked) and their faces, part after part.
template <class Point>
CGAL::Surface_mesh<Point> stitch_flat_parts(const std::vector<Flat_part>& parts,
                                            std::size_t whole_vertices) {
  std::vector<std::size_t> shared(whole_vertices, kNotStitched);
  std::vector<Point> points;
  std::vector<std::size_t> triangles;
  for (const Flat_part& part : parts) {
    std::vector<std::size_t> index(part.points.size());
    for (std::size_t v = 0; v < part.points.size(); ++v)
      index[v] = stitched_point(part.origin[v], bool(part.locked[v]),
                                to_point<Point>(part.points[v]), shared, points);
    // A face read from its halfedge's target: (v1, v2, v0).
    for (const std::array<int, 3>& t : part.triangles)
      for (const int j : {1, 2, 0}) triangles.push_back(index[std::size_t(t[std::size_t(j)])]);
  }
  CGAL::Surface_mesh<Point> whole;
  std::size_t unused_points = 0;
  if (!build_clean_triangle_mesh(points, triangles, whole, unused_points))
    throw std::logic_error("stitch_flat_parts: the parts do not meet as a manifold mesh");
  return whole;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FLAT_PART_H
