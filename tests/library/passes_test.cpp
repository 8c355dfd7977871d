// The passes around a policy in Simplification_pipeline, each with the library alone on tiny
// meshes: Border_pair_contraction (docs/quadric_core.md, the QEM tutorial's pair contraction),
// the small components dropped before and after the run (small_components.h), Laplacian_smoother
// ([Liu17] §2.4) and, bounded, Hausdorff_move_guard (docs/hausdorff.md).
#include "test_meshes.h"

#include "evaluation/surface_error.h"

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Hausdorff_move_guard.h>
#include <cgal_policies/Laplacian_smoother.h>
#include <cgal_policies/small_components.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using cgal_policies::Border_pair_contraction;
using test_meshes::Kernel;
using test_meshes::Mesh;
using test_meshes::Point;
using test_meshes::sorted_points;

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

// Three components: a tetrahedron (4 faces), an icosahedron (20), a 3 x 3 grid (18) and a lone
// triangle (1), 43 faces.
test_meshes::Mesh dirty_scan() {
  test_meshes::Mesh mesh = test_meshes::tetrahedron();
  CGAL::copy_face_graph(test_meshes::icosahedron(), mesh);
  CGAL::copy_face_graph(test_meshes::flat_grid(3), mesh);
  CGAL::copy_face_graph(test_meshes::from_triangles({{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}, {{0, 1, 2}}),
                        mesh);
  return mesh;
}

TEST(SmallComponents, DroppedBelowASizeButTheLargest) {
  test_meshes::Mesh mesh = dirty_scan();
  ASSERT_EQ(mesh.number_of_faces(), 43u);
  const cgal_policies::Dropped_components specks =
      cgal_policies::drop_components_smaller_than(mesh, 5);
  EXPECT_EQ(specks.components, 2u);
  EXPECT_EQ(specks.faces, 5u);
  EXPECT_EQ(mesh.number_of_faces(), 38u);
  EXPECT_FALSE(mesh.has_garbage());
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  const cgal_policies::Dropped_components all =
      cgal_policies::drop_components_smaller_than(mesh, 1000);
  EXPECT_EQ(all.components, 1u);
  EXPECT_EQ(all.faces, 18u);
  EXPECT_EQ(mesh.number_of_faces(), 20u);  // the icosahedron, the largest, stays
  EXPECT_EQ(cgal_policies::drop_components_smaller_than(mesh, 0).components, 0u);
}

TEST(SmallComponents, DroppedSmallestFirstUntilTheTarget) {
  test_meshes::Mesh mesh = dirty_scan();
  const cgal_policies::Dropped_components none =
      cgal_policies::drop_smallest_components_until(mesh, 43);
  EXPECT_EQ(none.components, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 43u);
  const cgal_policies::Dropped_components some =
      cgal_policies::drop_smallest_components_until(mesh, 40);
  EXPECT_EQ(some.components, 2u);  // the triangle, then the tetrahedron
  EXPECT_EQ(some.faces, 5u);
  EXPECT_EQ(mesh.number_of_faces(), 38u);
  const cgal_policies::Dropped_components rest =
      cgal_policies::drop_smallest_components_until(mesh, 0);
  EXPECT_EQ(rest.components, 1u);
  EXPECT_EQ(mesh.number_of_faces(), 20u);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

// Laplacian_smoother ([Liu17] §2.4). A square fan around the centre 0 at (0.2, 0, 0), its ring
// 1 2 3 4 at distance 1 from the origin:
//        2
//      / | `
//    3 - 0 - 1
//      ` | /
//        4
Mesh fan() {
  return test_meshes::from_triangles(
      {Point(0.2, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(0, -1, 0)},
      {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
}

using cgal_policies::Laplacian_smoother;
using cgal_policies::Smoothing_method;
using cgal_policies::Smoothing_weights;

TEST(LaplacianSmoother, MovesTheCentreTowardsTheUniformMean) {
  Mesh mesh = fan();
  Laplacian_smoother<Mesh>(0.5).smooth(mesh, 1);
  // Mean of the ring: the origin; P + 0.5 (U - P) = (0.1, 0, 0).
  EXPECT_DOUBLE_EQ(mesh.point(Mesh::Vertex_index(0)).x(), 0.1);
  EXPECT_DOUBLE_EQ(mesh.point(Mesh::Vertex_index(0)).y(), 0.0);
}

TEST(LaplacianSmoother, InverseDistanceWeightsFavourNearNeighbours) {
  Mesh mesh = fan();
  Laplacian_smoother<Mesh>(1.0, Smoothing_weights::inverse_distance).smooth(mesh, 1);
  // Eq. 8: U = sum(w_i p_i) / sum(w_i), w_i = 1 / |P - p_i|.
  const double w1 = 1 / 0.8, w3 = 1 / 1.2, w24 = 1 / std::sqrt(0.04 + 1);
  const double expected_x = (w1 * 1 - w3 * 1) / (w1 + w3 + 2 * w24);
  EXPECT_NEAR(mesh.point(Mesh::Vertex_index(0)).x(), expected_x, 1e-12);
  EXPECT_GT(expected_x, 0.0);  // pulled towards the near neighbour 1
}

TEST(LaplacianSmoother, BorderVerticesDoNotMove) {
  for (const Smoothing_method method : {Smoothing_method::laplacian, Smoothing_method::taubin}) {
    Mesh mesh = test_meshes::flat_grid(4);
    for (auto v : vertices(mesh))
      if (!CGAL::is_border(v, mesh))
        mesh.point(v) = Point(mesh.point(v).x(), mesh.point(v).y(), 0.3);
    const Mesh before = mesh;
    Laplacian_smoother<Mesh>(0.5, Smoothing_weights::uniform, method).smooth(mesh, 20);
    int moved_interior = 0;
    for (auto v : vertices(mesh)) {
      if (CGAL::is_border(v, mesh))
        EXPECT_EQ(mesh.point(v), before.point(v));
      else
        moved_interior += mesh.point(v) != before.point(v);
    }
    EXPECT_EQ(moved_interior, 9);
  }
}

TEST(LaplacianSmoother, TaubinShrinksAClosedSphereLessThanLaplacian) {
  const Mesh original = test_meshes::loop_sphere(3);
  const double volume = CGAL::Polygon_mesh_processing::volume(original);
  Mesh laplacian = original, taubin = original;
  Laplacian_smoother<Mesh>(0.5).smooth(laplacian, 50);
  Laplacian_smoother<Mesh>(0.5, Smoothing_weights::uniform, Smoothing_method::taubin)
      .smooth(taubin, 50);
  const double laplacian_loss = 1 - CGAL::Polygon_mesh_processing::volume(laplacian) / volume;
  const double taubin_loss = 1 - CGAL::Polygon_mesh_processing::volume(taubin) / volume;
  EXPECT_GT(laplacian_loss, 0.0);
  EXPECT_GT(laplacian_loss, std::abs(taubin_loss));
}

TEST(HausdorffMoveGuard, BoundedSmoothingKeepsTheBound) {
  const Mesh original = test_meshes::loop_sphere(3);
  const double tolerance = 0.002;
  Mesh free = original, bounded = original;
  const cgal_policies::Laplacian_smoother<Mesh> smoother(0.5);
  smoother.smooth(free, 30);
  const cgal_policies::Hausdorff_move_guard<Mesh> guard(original, bounded, tolerance);
  const std::size_t refused = smoother.smooth(bounded, 30, guard);
  const apps::Mesh_error free_error = apps::measure_mesh_error(original, free, 50000);
  const apps::Mesh_error bounded_error = apps::measure_mesh_error(original, bounded, 50000);
  EXPECT_GT(free_error.hausdorff, tolerance * free_error.bbox_diagonal);  // the test has teeth
  EXPECT_LE(bounded_error.hausdorff, tolerance * bounded_error.bbox_diagonal);
  EXPECT_GT(refused, 0u);
}

}  // namespace
