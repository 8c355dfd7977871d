// Laplacian_smoother and Hausdorff_move_guard ([Liu17] §2.4; docs/hausdorff.md).
#include "common/mesh_measures.h"
#include "test_meshes.h"

#include <cgal_policies/Hausdorff_move_guard.h>
#include <cgal_policies/Laplacian_smoother.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using apps::Mesh;
using apps::Point;
using cgal_policies::Laplacian_smoother;
using cgal_policies::Smoothing_method;
using cgal_policies::Smoothing_weights;

// An icosahedron subdivided `levels` times, its vertices pushed onto the unit sphere.
Mesh sphere(int levels) {
  Mesh mesh = test_meshes::icosahedron();
  CGAL::Subdivision_method_3::Loop_subdivision(mesh,
                                               CGAL::parameters::number_of_iterations(levels));
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
    mesh.point(v) = Point(p.x() / r, p.y() / r, p.z() / r);
  }
  return mesh;
}

// A square fan around the centre 0 at (0.2, 0, 0), its ring 1 2 3 4 at distance 1 from the origin:
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
  const Mesh original = sphere(3);
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
  const Mesh original = sphere(3);
  const double tolerance = 0.002;
  Mesh free = original, bounded = original;
  const Laplacian_smoother<Mesh> smoother(0.5);
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
