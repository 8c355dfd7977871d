// The fitting pass (docs/fitting.md) on tiny meshes with exact expectations, its guard, and the
// nearest-point reading of corner values that it shares with the attributes policy and fast; and
// its bounded mode on real meshes, checked by mesh_error's measure.
#include "test_meshes.h"

#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Two_sided_fitter.h>
#include <cgal_policies/internal/Border_curve.h>
#include <cgal_policies/internal/Fit_guard.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Input_triangles.h>
#include <cgal_policies/internal/Triangle_bvh.h>
#include <cgal_policies/internal/nearest_corner_values.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using namespace test_meshes;
using cgal_policies::Two_sided_fit_options;
using cgal_policies::Two_sided_fit_report;
using cgal_policies::Two_sided_fitter;

double radius(const Point& p) {
  return std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length()));
}

// The mean of | |x| - 1 | over a grid of points on every face: the distance to the unit sphere.
double mean_distance_to_unit_sphere(const Mesh& mesh) {
  double sum = 0;
  std::size_t count = 0;
  for (auto f : faces(mesh)) {
    std::vector<Point> corners;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      corners.push_back(mesh.point(v));
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; i + j <= 4; ++j) {
        const double a = i / 4.0, b = j / 4.0, c = 1 - a - b;
        const Point p(a * corners[0].x() + b * corners[1].x() + c * corners[2].x(),
                      a * corners[0].y() + b * corners[1].y() + c * corners[2].y(),
                      a * corners[0].z() + b * corners[1].z() + c * corners[2].z());
        sum += std::abs(radius(p) - 1);
        ++count;
      }
  }
  return sum / double(count);
}

Mesh scaled(Mesh mesh, double factor) {
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(factor * p.x(), factor * p.y(), factor * p.z());
  }
  return mesh;
}

// Tiny meshes need far fewer input samples than the default, which suits real meshes.
Two_sided_fit_options few_samples() {
  Two_sided_fit_options options;
  options.min_input_samples = 5000;
  return options;
}

TEST(TwoSidedFitter, ACoarsePlaneOnThePlaneItApproximatesStaysExactlyAsItIs) {
  const Mesh input = flat_grid(16);
  const Mesh before = scaled(flat_grid(4), 4);  // the same square, coarser: no distance to lower
  Mesh output = before;
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, few_samples()).fit(output);
  EXPECT_EQ(report.rounds, 0);  // the first round lowered nothing and was undone
  EXPECT_EQ(report.flips, 0u);
  for (auto v : vertices(output)) EXPECT_EQ(output.point(v), before.point(v));
  for (auto f : faces(output))
    EXPECT_EQ(halfedge(f, output), halfedge(f, before)) << "connectivity changed";
}

// flat_grid(16)'s square, coarser, its inner vertices lifted to z = 0.25.
Mesh lifted_coarse_plane() {
  Mesh mesh = scaled(flat_grid(4), 4);
  for (auto v : vertices(mesh))
    if (!CGAL::is_border(v, mesh)) {
      const Point& p = mesh.point(v);
      mesh.point(v) = Point(p.x(), p.y(), 0.25);
    }
  return mesh;
}

TEST(TwoSidedFitter, ACoarsePlaneLiftedOffItsPlaneComesBackToIt) {
  const Mesh input = flat_grid(16);
  Mesh output = lifted_coarse_plane();
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, few_samples()).fit(output);
  EXPECT_GE(report.rounds, 1);
  EXPECT_TRUE(is_valid_triangle_mesh(output));
  EXPECT_EQ(output.number_of_faces(), 32u);
  for (auto v : vertices(output)) {
    const Point& p = output.point(v);
    if (CGAL::is_border(v, output)) {  // on the input's border curve, the square's sides
      EXPECT_EQ(p.z(), 0.0) << p;
      EXPECT_NEAR((std::min)({p.x(), 16 - p.x(), p.y(), 16 - p.y()}), 0.0, 1e-12) << p;
    } else {
      EXPECT_LT(std::abs(p.z()), 0.125) << p;  // at least half way back
    }
  }
}

TEST(TwoSidedFitter, ABorderVertexOffTheInputsBorderNeverMovesFartherFromIt) {
  const Mesh input = flat_grid(16);
  Mesh output = lifted_coarse_plane();
  Mesh::Vertex_index off;  // the middle of the square's side y = 0, pushed out of the square
  for (auto v : vertices(output))
    if (output.point(v) == Point(8, 0, 0)) off = v;
  ASSERT_TRUE(off.is_valid());
  output.point(off) = Point(8, -0.5, 0);
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, few_samples()).fit(output);
  EXPECT_GE(report.rounds, 1);
  for (auto v : vertices(output)) {
    const Point& p = output.point(v);
    if (v == off) {  // its distance to the side y = 0, which stays the nearest part of the border
      EXPECT_TRUE(p.x() > 0 && p.x() < 16 && p.y() <= 0) << p;
      EXPECT_LE(std::hypot(p.y(), p.z()), 0.5) << p;
    } else if (CGAL::is_border(v, output)) {  // on the input's border curve, the square's sides
      EXPECT_EQ(p.z(), 0.0) << p;
      EXPECT_NEAR((std::min)({p.x(), 16 - p.x(), p.y(), 16 - p.y()}), 0.0, 1e-12) << p;
    }
  }
}

TEST(TwoSidedFitter, ACoarseSphereInsideAFineOneMovesEveryVertexTowardIt) {
  const Mesh input = loop_sphere(3);
  const Mesh before = scaled(loop_sphere(1), 0.9);
  Mesh output = before;
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, few_samples()).fit(output);
  EXPECT_EQ(report.refused_moves, 0u);
  for (auto v : vertices(output))
    EXPECT_LT(std::abs(radius(output.point(v)) - 1), std::abs(radius(before.point(v)) - 1));
  EXPECT_LT(mean_distance_to_unit_sphere(output), 0.5 * mean_distance_to_unit_sphere(before));
  EXPECT_TRUE(is_valid_triangle_mesh(output));
}

// --max-normal-angle takes 0 (found by fuzz_policies: the fitter's contract started above 0).
TEST(TwoSidedFitter, AtAZeroAngleNoFaceNormalTurns) {
  const Mesh input = flat_grid(16);
  Mesh output = lifted_coarse_plane();
  const Mesh before = output;
  Two_sided_fit_options options = few_samples();
  options.max_normal_angle_deg = 0;
  Two_sided_fitter<Mesh>(input, options).fit(output);
  for (auto f : faces(output)) {
    const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(f, output);
    const auto m = CGAL::Polygon_mesh_processing::compute_face_normal(f, before);
    EXPECT_EQ(n, m) << f;
  }
}

TEST(TwoSidedFitter, TwoFitsOfTheSameMeshesGiveTheSamePoints) {
  const Mesh input = loop_sphere(3);
  Mesh first = scaled(loop_sphere(1), 0.9), second = first;
  Two_sided_fitter<Mesh>(input, few_samples()).fit(first);
  Two_sided_fitter<Mesh>(input, few_samples()).fit(second);
  for (auto v : vertices(first)) EXPECT_EQ(first.point(v), second.point(v));
}

// Enough samples and faces for several tasks of each kind of match (kFitSamplesPerTask,
// kFitFacesPerTask).
TEST(TwoSidedFitter, MatchesOnTwoCoresAsOnOne) {
  const Mesh input = loop_sphere(3);
  const Mesh before = scaled(loop_sphere(2), 0.9);
  Two_sided_fit_options options = few_samples();
  options.min_input_samples = 20000;
  Mesh first = before, second = before;
  const Two_sided_fit_report one = Two_sided_fitter<Mesh>(input, options).fit(first);
  options.threads = 2;
  const Two_sided_fit_report two = Two_sided_fitter<Mesh>(input, options).fit(second);
  EXPECT_EQ(one.rounds, two.rounds);
  EXPECT_EQ(one.moves, two.moves);
  EXPECT_EQ(one.flips, two.flips);
  EXPECT_GT(one.moves, 0u);
  for (auto v : vertices(first)) EXPECT_EQ(first.point(v), second.point(v));
  for (auto h : halfedges(first)) EXPECT_EQ(target(h, first), target(h, second));
}

// A 4 x 4 grid of points in z = 0 but for (1, 1), raised; `diagonal` splits the middle square
// from (1, 1) to (2, 2) when true (as every other square), from (2, 1) to (1, 2) when false.
Mesh raised_grid(bool diagonal) {
  std::vector<Point> points;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) points.emplace_back(i, j, i == 1 && j == 1 ? 1 : 0);
  const auto id = [](int i, int j) { return j * 4 + i; };
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1 && !diagonal) {
        triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        continue;
      }
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return from_triangles(points, triangles);
}

TEST(TwoSidedFitter, FlipsTheEdgeThatMakesTheOutputTheInput) {
  const Mesh input = raised_grid(true);
  Mesh output = raised_grid(false);
  Two_sided_fit_options options;
  options.rounds = 1;
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, options).fit(output);
  EXPECT_GE(report.flips, 1u);  // others may follow the moves made before the flips
  const auto v = [](int i, int j) { return Mesh::Vertex_index(std::uint32_t(j * 4 + i)); };
  EXPECT_TRUE(halfedge(v(1, 1), v(2, 2), output).second);
  EXPECT_FALSE(halfedge(v(2, 1), v(1, 2), output).second);
  EXPECT_TRUE(is_valid_triangle_mesh(output));
}

TEST(TwoSidedFitter, WithoutFlipsTheConnectivityStays) {
  const Mesh input = raised_grid(true);
  Mesh output = raised_grid(false);
  Two_sided_fit_options options;
  options.flips = false;
  const Two_sided_fit_report report = Two_sided_fitter<Mesh>(input, options).fit(output);
  EXPECT_EQ(report.flips, 0u);
  const auto v = [](int i, int j) { return Mesh::Vertex_index(std::uint32_t(j * 4 + i)); };
  EXPECT_TRUE(halfedge(v(2, 1), v(1, 2), output).second);
}

using cgal_policies::internal::Fit_guard;
using cgal_policies::internal::Indexed_triangle;

Indexed_triangle indexed(std::array<std::uint32_t, 3> ids, std::array<Eigen::Vector3d, 3> points) {
  return {ids, points};
}

// Faces (a, b, c) and (b, a, d) of the quad a d b c; a flip makes (a, d, c) and (d, b, c).
struct Quad {
  Eigen::Vector3d a, b, c, d;
  std::vector<Indexed_triangle> faces() const {
    return {indexed({0, 1, 2}, {a, b, c}), indexed({1, 0, 3}, {b, a, d})};
  }
  std::vector<Indexed_triangle> flipped() const {
    return {indexed({0, 3, 2}, {a, d, c}), indexed({3, 1, 2}, {d, b, c})};
  }
};

TEST(FitGuard, RefusesAFlipThatFoldsAndAllowsOneThatDoesNot) {
  const Eigen::Vector3d up(0, 0, 1);
  // b lies inside the triangle a d c: the flipped faces would overlap, one of them upside down.
  const Quad folding{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {2, -1, 0}};
  for (const double angle : {90.0, 180.0}) {  // at 180 degrees the overlap alone refuses it
    Fit_guard guard(folding.faces(), angle, 1.0);
    EXPECT_FALSE(guard.allows({0, 1}, folding.flipped(), {up, up})) << angle;
  }
  const Quad convex{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -1, 0}};
  Fit_guard guard(convex.faces(), 90, 1.0);
  EXPECT_TRUE(guard.allows({0, 1}, convex.flipped(), {up, up}));
}

TEST(FitGuard, RefusesAMoveThroughAnotherFace) {
  const Indexed_triangle low = indexed({0, 1, 2}, {{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}});
  const Indexed_triangle high = indexed({3, 4, 5}, {{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}}});
  Fit_guard guard({low, high}, 180, 1.0);
  Indexed_triangle through = high;
  through.points[0] = {1, 1, -1};  // its corner dives below the low face
  EXPECT_FALSE(guard.allows({1}, {through}, {guard.reference(1)}));
  Indexed_triangle above = high;
  above.points[0] = {1, 1, 0.5};
  EXPECT_TRUE(guard.allows({1}, {above}, {guard.reference(1)}));
}

// Faces whose boxes only touch go to the exact predicates; faces whose boxes are apart, by however
// little, do not meet.
TEST(FacesIntersect, TouchingAtTheBoxesSideMeetsAndJustApartDoesNot) {
  const Indexed_triangle s = indexed({0, 1, 2}, {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  const Indexed_triangle touching = indexed({3, 4, 5}, {{{1, 0, 0}, {2, 0, 1}, {2, 1, 0}}});
  EXPECT_TRUE(faces_intersect(s, touching));
  EXPECT_TRUE(faces_intersect(touching, s));
  Indexed_triangle apart = touching;
  apart.points[0].x() = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(faces_intersect(s, apart));
  EXPECT_FALSE(faces_intersect(apart, s));
  // Boxes that overlap while the faces miss each other: the predicates decide.
  const Indexed_triangle beside = indexed({3, 4, 5}, {{{0.9, 0.9, -1}, {0.9, 0.9, 1}, {1, 1, 0}}});
  EXPECT_FALSE(faces_intersect(s, beside));
  // A common corner: a bow tie meets nowhere else; an edge facing it through the other face does.
  const Indexed_triangle bow_tie = indexed({0, 7, 8}, {{{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}}});
  EXPECT_FALSE(faces_intersect(s, bow_tie));
  const Indexed_triangle piercing =
      indexed({0, 7, 8}, {{{0, 0, 0}, {0.2, 0.2, -1}, {0.2, 0.2, 1}}});
  EXPECT_TRUE(faces_intersect(s, piercing));
  EXPECT_TRUE(faces_intersect(piercing, s));
}

// Two unit squares 0.1 apart, side by side in z = 0: four border edges each.
Mesh two_squares() {
  return from_triangles({{0, 0, 0},
                         {1, 0, 0},
                         {1, 1, 0},
                         {0, 1, 0},
                         {1.1, 0, 0},
                         {2.1, 0, 0},
                         {2.1, 1, 0},
                         {1.1, 1, 0}},
                        {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}});
}

// The curve of a mesh's border edges and that of its triangles (a fit by cells) alike.
TEST(BorderCurve, APointSlidesAlongItsOwnBorderAndNeverJumpsToTheNextOne) {
  namespace internal = cgal_policies::internal;
  const Mesh mesh = two_squares();
  const auto vpm = get(CGAL::vertex_point, mesh);
  for (const internal::Border_curve& curve :
       {internal::Border_curve(mesh, vpm),
        internal::Border_curve(internal::input_triangles(mesh, vpm))}) {
    // The other square's side is nearer the target; the point stays on its own side.
    EXPECT_EQ(curve.nearest_along({1, 0.5, 0}, {1.09, 0.5, 0}, 0.3), Eigen::Vector3d(1, 0.5, 0));
    EXPECT_NEAR(curve.distance({1.09, 0.5, 0}), 0.01, 1e-12);
    // Within reach only its own edge: the corner of it; with more, along the next edge.
    EXPECT_EQ(curve.nearest_along({0.5, 0, 0}, {0, 0.5, 0}, 0.3), Eigen::Vector3d(0, 0, 0));
    EXPECT_EQ(curve.nearest_along({0.5, 0, 0}, {0, 0.5, 0}, 1.0), Eigen::Vector3d(0, 0.5, 0));
  }
}

// Triangles of a cell may touch at a point only, two fans of a vertex: each keeps its own border,
// as the cell's part, which splits the vertex, does.
TEST(BorderCurve, TwoFansTouchingAtAPointKeepTheirOwnBorders) {
  namespace internal = cgal_policies::internal;
  internal::Input_triangles fans;
  fans.corners = {
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0)},
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)},
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-1, -1, 0)}};
  const std::uint32_t none = internal::kNoNeighbour;
  fans.neighbours = {{none, none, 1}, {0, none, none}, {none, none, none}};
  const internal::Border_curve curve(fans);
  // From the middle of the first fan's edge (0, 0)-(1, 0), the target near the other fan: along
  // its own border the nearest point is the shared corner, with any reach.
  EXPECT_EQ(curve.nearest_along({0.5, 0, 0}, {-0.5, -0.25, 0}, 100), Eigen::Vector3d(0, 0, 0));
  // From the second fan's edge, its own edge (-1, -1)-(0, 0) holds the nearest point.
  EXPECT_EQ(curve.nearest_along({-0.5, 0, 0}, {-0.25, -0.5, 0}, 100),
            Eigen::Vector3d(-0.375, -0.375, 0));
}

// Two unit right triangles in the plane z = 0, the second two units along x.
std::array<Eigen::Vector3d, 3> plane_triangle(std::size_t k) {
  const Eigen::Vector3d shift(2.0 * double(k), 0, 0);
  return {Eigen::Vector3d(0, 0, 0) + shift, Eigen::Vector3d(1, 0, 0) + shift,
          Eigen::Vector3d(0, 1, 0) + shift};
}

TEST(NearestTrianglePoint, TakesTheNearestOfTheTrianglesItIsAllowed) {
  using cgal_policies::internal::nearest_triangle_point;
  const Eigen::Vector3d p(2.25, 0.25, 1);  // above the inside of the second triangle
  const auto all = nearest_triangle_point(
      p, 2, [](std::size_t) { return true; }, plane_triangle);
  EXPECT_EQ(all.triangle, 1u);
  EXPECT_EQ(all.weights, (std::array<double, 3>{0.5, 0.25, 0.25}));
  // Without the second, the first one's nearest point is its corner (1, 0, 0).
  const auto first = nearest_triangle_point(
      p, 2, [](std::size_t k) { return k == 0; }, plane_triangle);
  EXPECT_EQ(first.triangle, 0u);
  EXPECT_EQ(first.weights, (std::array<double, 3>{0, 1, 0}));
}

using cgal_policies::internal::Triangle_bvh;
using cgal_policies::internal::Triangle_corners;

// Eight of plane_triangle's triangles along x: two leaves of four.
std::vector<Triangle_corners> plane_row() {
  std::vector<Triangle_corners> row;
  for (std::size_t k = 0; k < 8; ++k) row.push_back(plane_triangle(k));
  return row;
}

TEST(TriangleBvh, GivesTheNearestTriangleAndItsSquaredDistance) {
  const Triangle_bvh bvh(plane_row());
  const Triangle_bvh::Hit above = bvh.nearest({2.25, 0.25, 1});  // above triangle 1's inside
  EXPECT_EQ(above.triangle, 1u);
  EXPECT_EQ(above.squared_distance, 1.0);
  // Corner (7, 0, 0) of triangle 3 and corner (8, 0, 0) of triangle 4, in the other leaf, are as
  // near: the lower index wins, even when the search starts from the other one.
  const Eigen::Vector3d between(7.5, 0, 0);
  for (const Triangle_bvh::Hit start : {Triangle_bvh::Hit{}, Triangle_bvh::Hit{4, 0.25}}) {
    const Triangle_bvh::Hit hit = bvh.nearest(between, start);
    EXPECT_EQ(hit.triangle, 3u);
    EXPECT_EQ(hit.squared_distance, 0.25);
  }
  // A start nearer than every triangle is the answer; with no triangles, so is any start.
  const Triangle_bvh::Hit nearer{Triangle_bvh::kNone, 0.5};
  EXPECT_EQ(bvh.nearest({2.25, 0.25, 1}, nearer).triangle, Triangle_bvh::kNone);
  EXPECT_EQ(Triangle_bvh().nearest({0, 0, 0}).triangle, Triangle_bvh::kNone);
}

// A sphere of 81,920 triangles, enough for its halves to be built at once: two cores keep the
// triangles in the same order and give the same answers as one.
TEST(TriangleBvh, TwoCoresBuildTheTreeOfOne) {
  const Mesh sphere = loop_sphere(6);
  const std::vector<Triangle_corners> triangles =
      cgal_policies::internal::input_triangles(sphere, get(CGAL::vertex_point, sphere)).corners;
  const Triangle_bvh one(triangles), two(triangles, 2);
  ASSERT_EQ(one.size(), triangles.size());
  ASSERT_EQ(two.size(), triangles.size());
  for (std::uint32_t k = 0; k < one.size(); ++k) ASSERT_EQ(one.index(k), two.index(k)) << k;
  std::mt19937 random(11);
  const auto coordinate = [&] { return 3 * double(random()) / 4294967296.0 - 1.5; };
  for (int q = 0; q < 1000; ++q) {
    const Eigen::Vector3d p(coordinate(), coordinate(), coordinate());
    const Triangle_bvh::Hit a = one.nearest(p), b = two.nearest(p);
    EXPECT_EQ(a.triangle, b.triangle) << q;
    EXPECT_EQ(a.squared_distance, b.squared_distance) << q;
  }
}

// On the bunny, points on its triangles (a corner is the tie of all the triangles around it),
// near them, inside its box and far away: the hierarchy's answer is the minimum of
// squared_distance_to_triangle over every triangle, exactly, and the lowest index attaining it.
// The input surface of the fitting pass gives the same distance whatever triangle it starts from.
TEST(TriangleBvh, GivesTheBruteForceMinimumOnTheBunny) {
  SKIP_IF_REAL_MESHES_ARE_OFF();  // 4,000 brute-force scans of its 70k triangles
  using cgal_policies::internal::squared_distance_to_triangle;
  const Mesh bunny = apps::read_triangle_mesh(test_meshes::data_file("bunny.obj"));
  const auto vpm = get(CGAL::vertex_point, bunny);
  const std::vector<Triangle_corners> triangles =
      cgal_policies::internal::input_triangles(bunny, vpm).corners;
  const Triangle_bvh bvh(triangles);
  const cgal_policies::internal::Hausdorff_input_surface surface(bunny, vpm, 0.0, true);
  ASSERT_EQ(surface.size(), triangles.size());
  Eigen::Vector3d lo = triangles[0][0], hi = lo;
  for (const Triangle_corners& t : triangles)
    for (const Eigen::Vector3d& c : t) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
  const double diagonal = (hi - lo).norm();
  std::mt19937 random(7);  // its raw numbers are the same everywhere, unlike the distributions'
  const auto unit = [&] { return double(random()) / 4294967296.0; };
  const auto direction = [&] {
    return Eigen::Vector3d(unit() - 0.5, unit() - 0.5, unit() - 0.5).normalized();
  };
  std::size_t zero = 0;
  for (std::size_t q = 0; q < 4000; ++q) {
    const Triangle_corners& t = triangles[random() % triangles.size()];
    double a = unit(), b = unit();
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Eigen::Vector3d on = (1 - a - b) * t[0] + a * t[1] + b * t[2];
    Eigen::Vector3d p;
    switch (q % 5) {
      case 0:
        p = t[q / 5 % 3];
        break;
      case 1:
        p = on;
        break;
      case 2:
        p = on + 0.01 * diagonal * unit() * direction();
        break;
      case 3:
        p = lo + Eigen::Vector3d(unit(), unit(), unit()).cwiseProduct(hi - lo);
        break;
      default:
        p = 0.5 * (lo + hi) + 20 * diagonal * direction();
        break;
    }
    Triangle_bvh::Hit brute;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const double d2 = squared_distance_to_triangle(p, triangles[i]);
      if (d2 < brute.squared_distance) brute = {std::uint32_t(i), d2};
    }
    zero += brute.squared_distance == 0;
    const Triangle_bvh::Hit hit = bvh.nearest(p);
    ASSERT_EQ(hit.squared_distance, brute.squared_distance) << "query " << q;
    ASSERT_EQ(hit.triangle, brute.triangle) << "query " << q;
    // A walk that reaches a distance of 0 stops there, at a triangle that need not be the first.
    const auto near = surface.nearest(p, random() % triangles.size());
    ASSERT_EQ(near.distance, std::sqrt(brute.squared_distance)) << "query " << q;
    if (brute.squared_distance > 0) {
      ASSERT_EQ(near.triangle, brute.triangle) << "query " << q;
    }
  }
  EXPECT_GE(zero, 800u);  // at least the corners
}

// Blends like a texture coordinate, and marks every blend with a tenth more, so that a test can
// tell a blend from a corner's own value.
struct Marked_blend {
  static double blend(const std::array<double, 3>& corner, const std::array<double, 3>& w) {
    return w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2] + 0.1;
  }
};

TEST(ValuesAtWeights, ACornerKeepsItsOwnValueAndAnywhereElseBlends) {
  using cgal_policies::internal::values_at_weights;
  const std::array<double, 3> corner{1, 2, 4};
  EXPECT_EQ(values_at_weights<Marked_blend>(corner, {0, 1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(values_at_weights<Marked_blend>(corner, {0.5, 0.25, 0.25}), 2.1);
  EXPECT_DOUBLE_EQ(values_at_weights<Marked_blend>(corner, {0, 0.5, 0.5}), 3.1);
}

// The fitting pass in bounded mode (docs/fitting.md): the bound the simplification kept holds after
// the pass too, by the evaluator, and the mean error drops.
TEST(TwoSidedFitter, BoundedModeKeepsTheBoundOfTheRun) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name : {"bunny.obj", "fandisk.obj", "teapot.obj", "cow.obj"}) {
    const Mesh original = apps::read_triangle_mesh(test_meshes::data_file(name));
    const double tolerance = 0.005;
    cgal_policies::Hausdorff_bounded_options options;
    options.beta = tolerance;
    Mesh mesh = original;
    {
      const cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> policies(mesh, options);
      SMS::edge_collapse(
          mesh,
          cgal_policies::Face_count_stop_predicate<Mesh>(mesh, original.number_of_faces() / 100),
          CGAL::parameters::get_cost(policies.get_cost())
              .get_placement(policies.get_placement())
              .filter(policies.get_filter()));
    }
    mesh.collect_garbage();
    const apps::Mesh_error before = apps::measure_mesh_error(original, mesh);
    cgal_policies::Two_sided_fit_options fit_options;
    fit_options.tolerance = tolerance;
    const cgal_policies::Two_sided_fit_report fit =
        cgal_policies::Two_sided_fitter<Mesh>(original, fit_options).fit(mesh);
    EXPECT_GT(fit.moves, 0u) << name;
    const apps::Mesh_error after = apps::measure_mesh_error(original, mesh);
    EXPECT_LE(after.hausdorff, tolerance * after.bbox_diagonal)
        << name << ": Hausdorff " << after.hausdorff / after.bbox_diagonal;
    EXPECT_LT(after.mean(), before.mean()) << name;
    EXPECT_TRUE(apps::check_mesh_validity(mesh).valid) << name;
  }
}

}  // namespace
