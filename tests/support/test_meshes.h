// Tiny meshes built by hand for exact tests, and access to the real meshes of data/. It needs the
// library and CGAL only, so that the library's own tests link nothing of the apps.
#ifndef CGAL_POLICIES_TESTS_TEST_MESHES_H
#define CGAL_POLICIES_TESTS_TEST_MESHES_H

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_profile.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace test_meshes {

// The types of the apps (apps/io/Mesh_types.h), so that both kinds of tests share meshes.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// A mesh from points and triangles given as index triples.
inline Mesh from_triangles(const std::vector<Point>& points,
                           const std::vector<std::array<int, 3>>& triangles) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for (const Point& p : points) v.push_back(mesh.add_vertex(p));
  for (const auto& t : triangles) mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return mesh;
}

// An n x n grid of squares in the plane z = 0 over [0, n]^2, each square split along its diagonal
// (2 n^2 triangles, an open disk).
inline Mesh flat_grid(int n) {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) points.emplace_back(i, j, 0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return from_triangles(points, triangles);
}

// flat_grid(n) bent along x = n / 2, whose vertices are raised by `height`: two planes meeting
// along a ridge, flat again beyond x = n / 2 -+ 1.
inline Mesh bent_grid(int n, double height) {
  Mesh mesh = flat_grid(n);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    if (p.x() == n / 2) mesh.point(v) = Point(p.x(), p.y(), height);
  }
  return mesh;
}

inline Mesh icosahedron() {
  Mesh mesh;
  CGAL::make_icosahedron<Mesh, Point>(mesh, Point(0, 0, 0), 1.0);
  return mesh;
}

inline Mesh tetrahedron() {
  Mesh mesh;
  CGAL::make_tetrahedron(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1),
                         mesh);
  return mesh;
}

// An icosahedron Loop-subdivided `levels` times, its vertices pushed onto the unit sphere.
inline Mesh loop_sphere(int levels) {
  Mesh mesh = icosahedron();
  CGAL::Subdivision_method_3::Loop_subdivision(mesh,
                                               CGAL::parameters::number_of_iterations(levels));
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
    mesh.point(v) = Point(p.x() / r, p.y() / r, p.z() / r);
  }
  return mesh;
}

// A cube of side 4 with an n x n grid on each of its six sides (12 n^2 triangles, closed; n 1, 2
// or 4: 192 triangles by default), side k made of the points on_side(k, s, t) below, facing out.
inline Mesh six_sided_cube(int n = 4) {
  const int step = 4 / n;
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  std::map<std::array<int, 3>, int> index;
  const auto point_index = [&](int x, int y, int z) {
    const auto [it, added] = index.emplace(std::array<int, 3>{x, y, z}, int(points.size()));
    if (added) points.emplace_back(x, y, z);
    return it->second;
  };
  // Side k: the point at (s, t) of the side, outward orientation.
  const auto on_side = [](int k, int s, int t) -> std::array<int, 3> {
    switch (k) {
      case 0:
        return {t, s, 0};
      case 1:
        return {s, t, 4};
      case 2:
        return {s, 0, t};
      case 3:
        return {t, 4, s};
      case 4:
        return {0, t, s};
      default:
        return {4, s, t};
    }
  };
  for (int k = 0; k < 6; ++k)
    for (int s = 0; s < 4; s += step)
      for (int t = 0; t < 4; t += step) {
        const auto corner = [&](int ds, int dt) {
          const auto q = on_side(k, s + ds * step, t + dt * step);
          return point_index(q[0], q[1], q[2]);
        };
        triangles.push_back({corner(0, 0), corner(1, 0), corner(1, 1)});
        triangles.push_back({corner(0, 0), corner(1, 1), corner(0, 1)});
      }
  return from_triangles(points, triangles);
}

// The side of six_sided_cube() a face lies on, from its normal: 0 bottom (z = 0), 1 top, 2 front
// (y = 0), 3 back, 4 left (x = 0), 5 right.
inline int cube_side(const Mesh& mesh, Mesh::Face_index f) {
  const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh);
  if (n.z() < -0.5) return 0;
  if (n.z() > 0.5) return 1;
  if (n.y() < -0.5) return 2;
  if (n.y() > 0.5) return 3;
  return n.x() < -0.5 ? 4 : 5;
}

// The texture chart of side k of six_sided_cube(): [k, k + 1] x [0, 1], each side turning
// counterclockwise in it, so that every cube edge is a seam.
inline std::array<double, 2> cube_chart(int k, const Point& p) {
  const std::array<double, 6> s{p.y(), p.x(), p.x(), p.z(), p.z(), p.y()};
  const std::array<double, 6> t{p.x(), p.y(), p.z(), p.x(), p.y(), p.z()};
  return {k + s[k] / 4, t[k] / 4};
}

// Adds the maps `kinds` names and sets each corner's value in `map` (one of them) from its face and
// the point of its vertex.
template <class Map, class Value_of>
void paint_corner_map(Mesh& mesh, const cgal_policies::Corner_attributes<Point>::Kinds& kinds,
                      std::optional<Map> cgal_policies::Corner_attributes<Point>::*map,
                      const Value_of& value_of) {
  const auto attributes = cgal_policies::Corner_attributes<Point>::add(mesh, kinds);
  for (auto h : halfedges(mesh))
    if (!mesh.is_border(h))
      (*(attributes.*map))[h] = value_of(face(h, mesh), mesh.point(target(h, mesh)));
}

// Sets every corner's texture coordinate from its face and the point of its vertex (and its
// normal to +z, when asked).
template <class Uv_of>
void paint_corners(Mesh& mesh, const Uv_of& uv_of, bool with_normals) {
  using Attributes = cgal_policies::Corner_attributes<Point>;
  paint_corner_map(mesh, {true, false, false, false, false, false}, &Attributes::uvs, uv_of);
  if (with_normals)
    paint_corner_map(mesh, {false, true, false, false, false, false}, &Attributes::normals,
                     [](Mesh::Face_index, const Point&) { return Kernel::Vector_3(0, 0, 1); });
}

// Sets every corner's colour from its face and the point of its vertex.
template <class Color_of>
void paint_colors(Mesh& mesh, const Color_of& color_of) {
  paint_corner_map(mesh, {false, false, true, false, false, false},
                   &cgal_policies::Corner_attributes<Point>::colors, color_of);
}

// Sets every corner's second texture coordinate (glTF's TEXCOORD_1) from its face and the point
// of its vertex.
template <class Uv_of>
void paint_second_uvs(Mesh& mesh, const Uv_of& uv_of) {
  paint_corner_map(mesh, {false, false, false, false, true, false},
                   &cgal_policies::Corner_attributes<Point>::second_uvs, uv_of);
}

// Sets every corner's skin influences (glTF's JOINTS_0 and WEIGHTS_0) from its face and the point
// of its vertex.
template <class Skin_of>
void paint_skins(Mesh& mesh, const Skin_of& skin_of) {
  paint_corner_map(mesh, {false, false, false, false, false, true},
                   &cgal_policies::Corner_attributes<Point>::skins, skin_of);
}

// Twice the signed area of a face's texture triangle.
inline double uv_area(const Mesh& mesh, Mesh::Face_index f) {
  return cgal_policies::Corner_attributes<Point>(mesh).face_uv_area(mesh, f);
}

// flat_grid(n) with texture coordinates (x, y) / n, whose extent is sqrt(2); normals +z when
// asked.
inline Mesh textured_grid(int n, bool with_normals) {
  Mesh mesh = flat_grid(n);
  paint_corners(
      mesh,
      [n](Mesh::Face_index, const Point& p) {
        return std::array<double, 2>{p.x() / n, p.y() / n};
      },
      with_normals);
  return mesh;
}

// textured_grid(4, with_normals).
inline Mesh textured_plane(bool with_normals) { return textured_grid(4, with_normals); }

using Profile = CGAL::Surface_mesh_simplification::Edge_profile<
    Mesh, Mesh::Property_map<Mesh::Vertex_index, Point>, Kernel>;

// The profile edge_collapse would hand to the policies for the collapse of h (source into target).
inline Profile edge_profile(Mesh& mesh, Mesh::Halfedge_index h) {
  static const Kernel kernel;
  return Profile(h, mesh, kernel, 0, mesh.points(), 0, true);
}

// The halfedge from the vertex at a to the vertex at b; a test failure when there is none.
inline Mesh::Halfedge_index halfedge_between(const Mesh& mesh, const Point& a, const Point& b) {
  for (auto h : halfedges(mesh))
    if (mesh.point(source(h, mesh)) == a && mesh.point(target(h, mesh)) == b) return h;
  ADD_FAILURE() << "no edge " << a << " -> " << b;
  return Mesh::null_halfedge();
}

// A mesh of the project's data/ folder.
inline std::string data_file(const std::string& name) {
  return std::string(CGAL_POLICIES_DATA_DIR) + "/" + name;
}

// A clean mesh of data/ read as it is, with CGAL's reader (no repairs); a test failure otherwise.
inline Mesh read_clean_mesh(const std::string& name) {
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(data_file(name), mesh) || !CGAL::is_triangle_mesh(mesh))
    ADD_FAILURE() << name << " is not a clean triangle mesh";
  return mesh;
}

// A valid halfedge structure made of triangles only.
// The mesh's points in lexicographic order, to compare meshes whose vertices were renumbered.
inline std::vector<Point> sorted_points(const Mesh& mesh) {
  std::vector<Point> points;
  for (auto v : mesh.vertices()) points.push_back(mesh.point(v));
  std::sort(points.begin(), points.end());
  return points;
}

inline bool is_valid_triangle_mesh(const Mesh& mesh) {
  return CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh);
}

// The diagonal of the mesh's bounding box, the length Hausdorff tolerances are fractions of (the
// apps' bbox_diagonal, with CGAL's bbox).
inline double bbox_diagonal(const Mesh& mesh) {
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

inline std::size_t border_edge_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (auto e : edges(mesh)) count += CGAL::is_border(e, mesh) ? 1 : 0;
  return count;
}

inline std::size_t non_manifold_vertex_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (auto v : vertices(mesh))
    count += CGAL::Polygon_mesh_processing::is_non_manifold_vertex(v, mesh) ? 1 : 0;
  return count;
}

inline std::size_t degenerate_face_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (auto f : faces(mesh))
    count += CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, mesh) ? 1 : 0;
  return count;
}

// The same mesh halfedge by halfedge: the same target point, face and next (a Surface_mesh's
// opposite is fixed).
inline void expect_same_connectivity(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_halfedges(), b.number_of_halfedges());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  std::size_t differences = 0;
  for (auto h : a.halfedges())
    differences += a.point(a.target(h)) != b.point(b.target(h)) || a.face(h) != b.face(h) ||
                   a.next(h) != b.next(h);
  EXPECT_EQ(differences, 0u);
}

// CI's sanitizer pass sets CGAL_POLICIES_SKIP_REAL_MESHES: real meshes, and the few tiny-mesh
// tests that certify many runs, are many times slower in an instrumented Debug build (minutes
// each), and the Release pass runs them all.
inline bool real_meshes_skipped() {
  return std::getenv("CGAL_POLICIES_SKIP_REAL_MESHES") != nullptr;
}

}  // namespace test_meshes

// Skips the current test, with a message, in CI's sanitized pass (CGAL_POLICIES_SKIP_REAL_MESHES).
#define SKIP_IF_REAL_MESHES_ARE_OFF()                                                           \
  do {                                                                                          \
    if (test_meshes::real_meshes_skipped())                                                     \
      GTEST_SKIP() << "CGAL_POLICIES_SKIP_REAL_MESHES is set: real meshes run in Release only"; \
  } while (0)

// Skips a test on tiny meshes that takes minutes in CI's sanitized pass; the Release pass runs it.
#define SKIP_IF_TOO_SLOW_WHEN_SANITIZED()                                                 \
  do {                                                                                    \
    if (test_meshes::real_meshes_skipped())                                               \
      GTEST_SKIP() << "CGAL_POLICIES_SKIP_REAL_MESHES is set: too slow in the sanitized " \
                      "Debug build, it runs in Release";                                  \
  } while (0)

#endif  // CGAL_POLICIES_TESTS_TEST_MESHES_H
