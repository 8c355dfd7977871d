// Hausdorff_bounded_policies, its cost, placement and filter (docs/hausdorff.md): exact cases on
// tiny meshes, and the global-mode guarantee on real meshes, checked by mesh_error's measure.
#include "common/edge_collapse_runner.h"
#include "common/mesh_measures.h"
#include "test_meshes.h"

#include "common/mesh_io.h"

#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Hausdorff_move_guard.h>
#include <cgal_policies/Laplacian_smoother.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_profile.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using apps::Kernel;
using apps::Mesh;
using apps::Point;
using Policies = cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel>;
using Profile = SMS::Edge_profile<Mesh>;

cgal_policies::Hausdorff_bounded_options options_with(double beta) {
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = beta;
  return options;
}

// Asks the policy's filter, as edge_collapse would when it pops the edge of h.
bool collapse_accepted(Mesh& mesh, const Policies& policy, Mesh::Halfedge_index h) {
  const Kernel traits;
  const Profile profile(h, mesh, traits, get(CGAL::vertex_index, mesh),
                        get(CGAL::vertex_point, mesh), get(CGAL::halfedge_index, mesh), true);
  return bool(policy.get_filter()(profile, policy.get_placement()(profile)));
}

void start(Mesh& mesh, const Policies& policy) {
  policy.get_cost().initialize(mesh, get(CGAL::vertex_point, mesh), Kernel());
}

Mesh::Halfedge_index halfedge_between(const Mesh& mesh, int a, int b) {
  const auto h = CGAL::halfedge(Mesh::Vertex_index(a), Mesh::Vertex_index(b), mesh);
  EXPECT_TRUE(h.second);
  return h.first;
}

// The 4 x 4 flat grid with a ridge: the vertices of the middle column x = 2 are raised by
// `height`. Vertex (i, j) has index 5 j + i.
Mesh ridge_grid(double height) {
  Mesh mesh = test_meshes::flat_grid(4);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    if (p.x() == 2) mesh.point(v) = Point(p.x(), p.y(), height);
  }
  return mesh;
}

void expect_every_interior_collapse_accepted(double beta) {
  {
    Mesh mesh = test_meshes::flat_grid(4);
    const Policies policy(mesh, options_with(beta));
    start(mesh, policy);
    int interior = 0;
    for (auto e : edges(mesh)) {
      const auto h = halfedge(e, mesh);
      if (CGAL::is_border(source(h, mesh), mesh) || CGAL::is_border(target(h, mesh), mesh))
        continue;
      ++interior;
      EXPECT_TRUE(collapse_accepted(mesh, policy, h)) << "beta " << beta << " edge " << e;
    }
    EXPECT_EQ(interior, 16);  // the 3 x 3 interior vertices: 6 + 6 axis edges, 4 diagonals
  }
}

TEST(HausdorffBoundedPolicies, FlatGridAcceptsEveryInteriorCollapse) {
  expect_every_interior_collapse_accepted(0.5);
}

// The same policy is asked about every edge with no collapse in between: an accepted choice that
// was not collapsed must not be taken as done (two edges were refused here while it was).
TEST(HausdorffBoundedPolicies, FlatGridAcceptsEveryInteriorCollapseAtSmallTolerances) {
  for (double beta : {0.0001, 0.001, 0.01, 0.05, 0.1})
    expect_every_interior_collapse_accepted(beta);
}

// The cut along a fan, directly: a fan of four right triangles around (1, 1) tiles the square
// [0, 2]^2. A piece inside it that straddles all four is cut into parts that tile it exactly, each
// over its own triangle; halving alone cannot cover it within 1e-9. A piece that reaches out of the
// square is refused, and so is one seen from below (the fan faces away from it).
TEST(HausdorffBoundedPolicies, APieceIsCutExactlyAlongACoplanarFan) {
  using cgal_policies::internal::Piece_cover;
  using cgal_policies::internal::Triangle_corners;
  using V = Eigen::Vector3d;
  const V apex(1, 1, 0);
  const std::vector<Triangle_corners> fan = {{apex, V(0, 0, 0), V(2, 0, 0)},
                                             {apex, V(2, 0, 0), V(2, 2, 0)},
                                             {apex, V(2, 2, 0), V(0, 2, 0)},
                                             {apex, V(0, 2, 0), V(0, 0, 0)}};
  const double limit = 1e-9;
  const Triangle_corners piece = {V(0.2, 0.3, 0), V(1.7, 0.4, 0), V(0.9, 1.8, 0)};
  std::vector<Piece_cover> covers;
  std::size_t hint = 0;
  EXPECT_FALSE(cgal_policies::internal::cover_piece(piece, 0, fan, limit, 5, hint, covers));
  covers.clear();
  ASSERT_TRUE(cgal_policies::internal::cover_piece_along_fan(piece, fan, apex, limit, covers));
  double area = 0;
  std::vector<bool> used(fan.size(), false);
  for (const Piece_cover& c : covers) {
    area += 0.5 * (c.piece[1] - c.piece[0]).cross(c.piece[2] - c.piece[0]).norm();
    used[c.triangle] = true;
    for (const V& corner : c.piece)
      EXPECT_LE(cgal_policies::internal::squared_distance_to_triangle(corner, fan[c.triangle]),
                limit * limit);
  }
  EXPECT_NEAR(area, 0.5 * (piece[1] - piece[0]).cross(piece[2] - piece[0]).norm(), 1e-12);
  EXPECT_EQ(used, std::vector<bool>(fan.size(), true));

  covers.clear();
  const Triangle_corners beyond = {V(0.2, 0.3, 0), V(2.5, 0.4, 0), V(0.9, 1.8, 0)};
  EXPECT_FALSE(cgal_policies::internal::cover_piece_along_fan(beyond, fan, apex, limit, covers));
  const Triangle_corners below = {piece[0], piece[2], piece[1]};
  EXPECT_FALSE(cgal_policies::internal::cover_piece_along_fan(below, fan, apex, limit, covers));
  EXPECT_TRUE(covers.empty());
}

TEST(HausdorffBoundedPolicies, BentGridRefusesTheCollapseAcrossTheBendBelowItsHeight) {
  // The interior edge from (1, 2) up to the ridge vertex (2, 2): whichever point the merged vertex
  // takes, the bend is cut or the flat part is lifted by a good part of the height.
  const double height = 0.5;
  for (const double tolerance : {0.1 * height, 2 * height}) {
    Mesh mesh = ridge_grid(height);
    const double diagonal = apps::bbox_diagonal(mesh);
    const Policies policy(mesh, options_with(tolerance / diagonal));
    start(mesh, policy);
    const bool accepted = collapse_accepted(mesh, policy, halfedge_between(mesh, 11, 12));
    EXPECT_EQ(accepted, tolerance > height) << "tolerance " << tolerance;
  }
}

TEST(HausdorffBoundedPolicies, LockedBordersRefuseBorderEdges) {
  Mesh mesh = test_meshes::flat_grid(4);
  cgal_policies::Hausdorff_bounded_options options = options_with(0.5);
  const Policies sliding(mesh, options);
  start(mesh, sliding);
  EXPECT_TRUE(collapse_accepted(mesh, sliding, halfedge_between(mesh, 1, 2)));
  options.border = cgal_policies::Border_rule::lock;
  const Policies locked(mesh, options);
  start(mesh, locked);
  EXPECT_FALSE(collapse_accepted(mesh, locked, halfedge_between(mesh, 1, 2)));
}

// A finely sampled cylinder arc: collapses in local mode each stay within the tolerance of the
// patch they replace, but successive ones drift away from the original surface.
Mesh cylinder_band(int segments) {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i <= segments; ++i) {
    const double angle = 0.5 * M_PI * i / segments;
    points.emplace_back(std::cos(angle), std::sin(angle), 0);
    points.emplace_back(std::cos(angle), std::sin(angle), 0.05);
  }
  for (int i = 0; i < segments; ++i) {
    triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  return test_meshes::from_triangles(points, triangles);
}

apps::Mesh_error simplify_band(cgal_policies::Hausdorff_reference reference, double beta) {
  Mesh mesh = cylinder_band(64);
  const Mesh original = mesh;
  cgal_policies::Hausdorff_bounded_options options = options_with(beta);
  options.reference = reference;
  const Policies policy(mesh, options);
  apps::Simplify_settings settings;
  settings.target_faces = 2;
  apps::run_edge_collapse(mesh, settings, policy.get_cost(), policy.get_placement(),
                          policy.get_filter());
  mesh.collect_garbage();
  return apps::measure_mesh_error(original, mesh, 20000);
}

TEST(HausdorffBoundedPolicies, LocalModeAccumulatesWhileGlobalModeKeepsTheBound) {
  const double beta = 0.01;
  const apps::Mesh_error local = simplify_band(cgal_policies::Hausdorff_reference::local, beta);
  const apps::Mesh_error global = simplify_band(cgal_policies::Hausdorff_reference::global, beta);
  EXPECT_GT(local.hausdorff, beta * local.bbox_diagonal);
  EXPECT_LE(global.hausdorff, beta * global.bbox_diagonal);
}

// The guarantee: in global mode, mesh_error's two-sided Hausdorff distance never exceeds the
// tolerance, smoothing off and bounded smoothing on. (The registry's "hausdorff" entry runs the
// same classes; property_test checks it like every policy.)
TEST(HausdorffBoundedPolicies, GlobalModeKeepsTheTwoSidedBoundOnRealMeshes) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name : {"bunny.obj", "fandisk.obj", "teapot.obj", "rocker-arm.obj"}) {
    const Mesh original = apps::read_triangle_mesh(test_meshes::data_file(name));
    for (const double tolerance : {0.001, 0.005, 0.01}) {
      for (const bool smooth : {false, true}) {
        Mesh mesh = original;
        {
          const Policies policy(mesh, options_with(tolerance));
          // Down to 5% of the faces, or as far as the tolerance allows: far enough that the
          // tighter tolerances stop the run, and short enough for a test.
          apps::Simplify_settings settings;
          settings.target_faces = original.number_of_faces() / 20;
          apps::run_edge_collapse(mesh, settings, policy.get_cost(), policy.get_placement(),
                                  policy.get_filter());
        }
        mesh.collect_garbage();
        if (smooth) {
          const cgal_policies::Hausdorff_move_guard<Mesh> guard(original, mesh, tolerance);
          cgal_policies::Laplacian_smoother<Mesh>().smooth(mesh, 3, guard);
        }
        const apps::Mesh_error error = apps::measure_mesh_error(original, mesh);
        EXPECT_LE(error.hausdorff, tolerance * error.bbox_diagonal)
            << name << " tolerance " << tolerance << (smooth ? " smoothed" : "") << ": "
            << mesh.number_of_faces() << " faces, Hausdorff "
            << error.hausdorff / error.bbox_diagonal;
        EXPECT_LT(mesh.number_of_faces(), original.number_of_faces());
      }
    }
  }
}

}  // namespace
