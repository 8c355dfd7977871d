// Fast_threshold_simplifier (docs/fast.md) and Border_pair_contraction (docs/quadric_core.md):
// exact results on tiny meshes (its real-mesh tests are in property_test.cpp).
#include "test_meshes.h"

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Fast_threshold_simplifier.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using cgal_policies::Border_pair_contraction;
using cgal_policies::Fast_threshold_simplifier;
using test_meshes::Mesh;
using test_meshes::Point;

std::vector<Point> sorted_points(const Mesh& mesh) {
  std::vector<Point> points;
  for (auto v : mesh.vertices()) points.push_back(mesh.point(v));
  std::sort(points.begin(), points.end());
  return points;
}

cgal_policies::Fast_threshold_options lossless() {
  cgal_policies::Fast_threshold_options options;
  options.lossless = true;
  return options;
}

cgal_policies::Fast_threshold_options any_normal_turn() {
  cgal_policies::Fast_threshold_options options;
  options.max_normal_angle_deg = 180;
  return options;
}

const std::vector<Point> kGridCorners = {Point(0, 0, 0), Point(0, 8, 0), Point(8, 0, 0),
                                         Point(8, 8, 0)};

TEST(FastThresholdSimplifier, LosslessFlatGridCollapsesToItsCornerTriangles) {
  Mesh mesh = test_meshes::flat_grid(8);
  const auto report = Fast_threshold_simplifier(lossless())(mesh, 1);
  EXPECT_FALSE(report.target_reached);  // a single triangle would cost area
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(sorted_points(mesh), kGridCorners);
}

TEST(FastThresholdSimplifier, FlatGridReachesTwoFacesOnItsCorners) {
  Mesh mesh = test_meshes::flat_grid(8);
  const auto report = Fast_threshold_simplifier()(mesh, 2);
  EXPECT_TRUE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(sorted_points(mesh), kGridCorners);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

TEST(FastThresholdSimplifier, TetrahedronStaysATetrahedron) {
  Mesh mesh = test_meshes::tetrahedron();
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Fast_threshold_simplifier(any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(sorted_points(mesh), before);
}

TEST(FastThresholdSimplifier, IcosahedronCollapsedFullyEndsAsATetrahedron) {
  Mesh mesh = test_meshes::icosahedron();
  const auto report = Fast_threshold_simplifier(any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
}

TEST(FastThresholdSimplifier, LosslessModeKeepsACurvedSurface) {
  Mesh mesh = test_meshes::icosahedron();
  const std::vector<Point> before = sorted_points(mesh);
  static_cast<void>(Fast_threshold_simplifier(lossless())(mesh, 1));
  EXPECT_EQ(mesh.number_of_faces(), 20u);
  EXPECT_EQ(sorted_points(mesh), before);
}

// Twice the area over the squared longest edge of the thinnest face (sqrt(3)/2 when equilateral).
double thinnest_face_shape(const Mesh& mesh) {
  double thinnest = 1;
  for (auto f : mesh.faces()) {
    std::vector<Point> p;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    const double longest =
        (std::max)({CGAL::squared_distance(p[0], p[1]), CGAL::squared_distance(p[1], p[2]),
                    CGAL::squared_distance(p[2], p[0])});
    const double twice_area =
        std::sqrt(CGAL::cross_product(p[1] - p[0], p[2] - p[0]).squared_length());
    thinnest = (std::min)(thinnest, twice_area / longest);
  }
  return thinnest;
}

// A flat hexagon fan whose centre was split into three coincident vertices a, b, c: four of its
// ten faces have zero area, as the reader's repairs leave them on dragon.ply. Every edge between
// a, b and c costs nothing; the old flip test refused to move a vertex of a face that was already
// degenerate, so the faces stayed. Two collapses give back the clean six-face fan.
TEST(FastThresholdSimplifier, RemovesTheDegenerateFacesOfTheInput) {
  std::vector<Point> points;
  for (int i = 0; i < 6; ++i)
    points.emplace_back(2 * std::cos(i * CGAL_PI / 3), 2 * std::sin(i * CGAL_PI / 3), 0);
  points.insert(points.end(), 3, Point(0, 0, 0));
  const int a = 6, b = 7, c = 8;
  Mesh mesh = test_meshes::from_triangles(points, {{a, b, c},
                                                   {a, 0, 1},
                                                   {a, 1, b},
                                                   {b, 1, 2},
                                                   {b, 2, 3},
                                                   {b, 3, c},
                                                   {c, 3, 4},
                                                   {c, 4, 5},
                                                   {c, 5, a},
                                                   {a, 5, 0}});
  ASSERT_EQ(test_meshes::degenerate_face_count(mesh), 4u);
  const auto report = Fast_threshold_simplifier()(mesh, 6);
  EXPECT_TRUE(report.target_reached);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 6u);
  EXPECT_EQ(test_meshes::degenerate_face_count(mesh), 0u);
  std::vector<Point> expected(points.begin(), points.begin() + 7);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(sorted_points(mesh), expected);
}

// A flat fan around v = (1, 0.5): all four collapses of v onto a border vertex cost nothing. The
// first one tried (face (b, x, v) is read from v, so edge (v, b) comes first), onto b = (0, 0),
// would turn face (v, x, y) into the sliver (b, x, y) of shape 5e-7 without turning its normal;
// it is refused, and v goes to x instead.
TEST(FastThresholdSimplifier, RefusesACollapseThatMakesASliver) {
  Mesh mesh = test_meshes::from_triangles(
      {Point(1, 0.5, 0), Point(0, 0, 0), Point(1, -1e-6, 0), Point(2, 0, 0), Point(1, 2, 0)},
      {{1, 2, 0}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
  const auto report = Fast_threshold_simplifier()(mesh, 2);
  EXPECT_TRUE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_GT(thinnest_face_shape(mesh), 0.1);
  EXPECT_EQ(sorted_points(mesh), (std::vector<Point>{Point(0, 0, 0), Point(1, -1e-6, 0),
                                                     Point(1, 2, 0), Point(2, 0, 0)}));
}

// Scaling by a power of two is exact in floating point, so a scale-invariant schedule must give
// the same collapses, exactly scaled.
TEST(FastThresholdSimplifier, IsScaleInvariant) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  Mesh mesh = test_meshes::read_clean_mesh("bunny.obj");
  Mesh scaled = mesh;
  for (auto v : scaled.vertices()) {
    const Point& p = scaled.point(v);
    scaled.point(v) = Point(1024 * p.x(), 1024 * p.y(), 1024 * p.z());
  }
  const std::size_t target = mesh.number_of_faces() / 10;
  Fast_threshold_simplifier()(mesh, target);
  Fast_threshold_simplifier()(scaled, target);
  ASSERT_EQ(mesh.number_of_faces(), scaled.number_of_faces());
  std::vector<Point> expected;
  for (const Point& p : sorted_points(mesh))
    expected.emplace_back(1024 * p.x(), 1024 * p.y(), 1024 * p.z());
  EXPECT_EQ(sorted_points(scaled), expected);
}

// Two 2 x 4 flat grids side by side along x, the right one shifted by `gap`: a straight crack of
// 5 vertex pairs and 4 edge pairs.
Mesh cracked_grid(double gap) {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  for (int part = 0; part < 2; ++part) {
    const int first = int(points.size());
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 2; ++i) points.emplace_back(2 * part + i + part * gap, j, 0);
    auto id = [first](int i, int j) { return first + j * 3 + i; };
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 2; ++i) {
        triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  return test_meshes::from_triangles(points, triangles);
}

TEST(BorderPairContraction, ClosesACrackNarrowerThanTheDistance) {
  Mesh mesh = cracked_grid(0.01);  // D is about 5.66: the gap is 0.0018 D
  const auto report = Border_pair_contraction(0.01)(mesh);
  EXPECT_EQ(report.merged_pairs, 5u);
  EXPECT_EQ(report.stitched_edges, 4u);
  EXPECT_EQ(report.refused_pairs, 0u);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_EQ(mesh.number_of_vertices(), 25u);
  EXPECT_EQ(mesh.number_of_faces(), 32u);
  EXPECT_EQ(test_meshes::border_edge_count(mesh), 16u);
  EXPECT_EQ(test_meshes::non_manifold_vertex_count(mesh), 0u);
}

TEST(BorderPairContraction, LeavesACrackWiderThanTheDistanceAlone) {
  Mesh mesh = cracked_grid(0.01);
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Border_pair_contraction(0.001)(mesh);
  EXPECT_EQ(report.merged_pairs, 0u);
  EXPECT_EQ(report.refused_pairs, 0u);
  EXPECT_EQ(mesh.number_of_vertices(), 30u);
  EXPECT_EQ(sorted_points(mesh), before);
}

TEST(BorderPairContraction, IsOffByDefault) {
  Mesh mesh = cracked_grid(0);
  const auto report = Border_pair_contraction()(mesh);
  EXPECT_EQ(report.merged_pairs, 0u);
  EXPECT_EQ(mesh.number_of_vertices(), 30u);
}

// Two squares touching corner to corner: merging the corners would pinch the surface at one
// vertex, so the pair is refused and the mesh is left as it was.
TEST(BorderPairContraction, RefusesAMergeThatWouldBeNonManifold) {
  const double g = 0.001;
  Mesh mesh = test_meshes::from_triangles(
      {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(1 + g, 1 + g, 0),
       Point(2, 1 + g, 0), Point(2, 2, 0), Point(1 + g, 2, 0)},
      {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Border_pair_contraction(0.01)(mesh);
  EXPECT_EQ(report.merged_pairs, 0u);
  EXPECT_EQ(report.refused_pairs, 1u);
  EXPECT_EQ(report.refused_by_reason.at("pinch"), 1u);
  EXPECT_EQ(sorted_points(mesh), before);
  EXPECT_EQ(test_meshes::non_manifold_vertex_count(mesh), 0u);
}

// A thin square ring: each corner of the inner border lies close to the matching corner of the
// outer border, but the two are joined by an edge, so merging them would fold that edge away and
// leave the merged vertex with two edges to one neighbour. No pair is merged.
TEST(BorderPairContraction, RefusesAMergeThatWouldDoubleAnEdge) {
  const double g = 0.001;
  std::vector<Point> points = {Point(0, 0, 0),         Point(1, 0, 0),    Point(1, 1, 0),
                               Point(0, 1, 0),         Point(g, g, 0),    Point(1 - g, g, 0),
                               Point(1 - g, 1 - g, 0), Point(g, 1 - g, 0)};
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    triangles.push_back({i, j, 4 + j});
    triangles.push_back({i, 4 + j, 4 + i});
  }
  Mesh mesh = test_meshes::from_triangles(points, triangles);
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Border_pair_contraction(0.01)(mesh);
  EXPECT_EQ(report.merged_pairs, 0u);
  EXPECT_EQ(report.refused_pairs, 4u);
  // Once three are refused, the last one has no stitched edge left and would only pinch.
  EXPECT_EQ(report.refused_by_reason.at("duplicate_edge"), 3u);
  EXPECT_EQ(report.refused_by_reason.at("pinch"), 1u);
  EXPECT_EQ(sorted_points(mesh), before);
}

}  // namespace
