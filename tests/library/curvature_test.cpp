// Curvature_weighted_quadric_policies (docs/curvature.md) on tiny meshes with exact expectations;
// the registry's property tests run it on real meshes.
#include "test_meshes.h"

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>
#include <cgal_policies/internal/approximate_curvature.h>
#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace {

using namespace test_meshes;
using Policies = cgal_policies::Curvature_weighted_quadric_policies<Mesh, test_meshes::Kernel>;
namespace SMS = CGAL::Surface_mesh_simplification;

constexpr double kEps = 1e-3;  // the default floor

cgal_policies::Curvature_weighted_options literal_options() {
  cgal_policies::Curvature_weighted_options options;
  options.literal = true;
  return options;
}

// The grid of flat_grid(nx x ny) lifted to z = height(i, j), all scaled by `scale`.
Mesh height_grid(int nx, int ny, const std::function<double(int, int)>& height,
                 double scale = 1.0) {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) points.emplace_back(scale * i, scale * j, scale * height(i, j));
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return from_triangles(points, triangles);
}

// Ridges at odd x, valleys at even x. Each vertex with a full ring has three faces on each slope,
// so every such vertex normal is (0, 0, 1): K = 1 although the surface is anything but flat.
Mesh sawtooth() {
  return height_grid(8, 4, [](int i, int) { return i % 2 == 1 ? 1.0 : 0.0; });
}

Mesh::Vertex_index vertex_at(const Mesh& mesh, const Point& p) {
  for (auto v : vertices(mesh))
    if (mesh.point(v) == p) return v;
  ADD_FAILURE() << "no vertex at " << p;
  return Mesh::null_vertex();
}

template <typename P>
double edge_cost(const P& policies, Mesh& mesh, Mesh::Halfedge_index h) {
  const Profile profile = edge_profile(mesh, h);
  const auto cost = policies.get_cost()(profile, policies.get_placement()(profile));
  EXPECT_TRUE(cost);
  return cost ? *cost : -1.0;
}

TEST(CurvatureWeightedQuadricPolicies, AFlatPatchHasCurvatureOneAndFactorEps) {
  Mesh mesh = flat_grid(4);
  const Policies policies(mesh);
  const Policies literal(mesh, literal_options());
  policies.initialize(mesh, mesh.points(), test_meshes::Kernel());
  literal.initialize(mesh, mesh.points(), test_meshes::Kernel());
  for (auto v : vertices(mesh)) EXPECT_EQ(policies.approximate_curvature(v), 1.0);
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    EXPECT_EQ(policies.curvature_factor(source(h, mesh), target(h, mesh)), kEps);
    EXPECT_EQ(literal.curvature_factor(source(h, mesh), target(h, mesh)), 0.0);
  }
}

TEST(CurvatureWeightedQuadricPolicies, ACubeCornerHasTheCurvatureDerivedByHand) {
  // Three unit squares of a cube meeting at O, each split by its diagonal through O, normals
  // pointing away from the cube. The corner's six faces give n_O = -(1, 1, 1)/sqrt 3.
  // X = (1,0,0) lies on one face of the z = 0 and one of the y = 0 square: n_X = -(0, 1, 1)/sqrt 2,
  // cos(n_O, n_X) = 2/sqrt 6. XY = (1,1,0) lies on two faces of z = 0: n_XY = -(0, 0, 1),
  // cos(n_O, n_XY) = 1/sqrt 3. By symmetry, K_O = (3 * 2/sqrt 6 + 3 * 1/sqrt 3) / 6
  // = (sqrt 6 + sqrt 3) / 6 ~ 0.69692.
  // X's neighbours are O, XY and XZ (n_XZ = -(0, 1, 0)): K_X = (2/sqrt 6 + 2 * 1/sqrt 2) / 3.
  const Point o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), xy(1, 1, 0), xz(1, 0, 1), yz(0, 1, 1);
  Mesh mesh = from_triangles({o, x, y, z, xy, xz, yz}, {{0, 2, 4},
                                                        {0, 4, 1},  // z = 0
                                                        {0, 1, 5},
                                                        {0, 5, 3},  // y = 0
                                                        {0, 3, 6},
                                                        {0, 6, 2}});  // x = 0
  const Policies policies(mesh);
  policies.initialize(mesh, mesh.points(), test_meshes::Kernel());
  const double k_o = (std::sqrt(6.0) + std::sqrt(3.0)) / 6;
  const double k_x = (2 / std::sqrt(6.0) + 2 / std::sqrt(2.0)) / 3;
  EXPECT_NEAR(policies.approximate_curvature(vertex_at(mesh, o)), k_o, 1e-15);
  EXPECT_NEAR(policies.approximate_curvature(vertex_at(mesh, x)), k_x, 1e-15);
  EXPECT_NEAR(policies.curvature_factor(vertex_at(mesh, o), vertex_at(mesh, x)),
              kEps + 1 - (k_o + k_x) / 2, 1e-15);
}

TEST(CurvatureWeightedQuadricPolicies,
     ASymmetricSawtoothCostsEpsTimesQemByDefaultAndNothingLiterally) {
  Mesh mesh = sawtooth();
  const Policies policies(mesh);
  const Policies literal(mesh, literal_options());
  const cgal_policies::Classic_quadric_policies<Mesh, test_meshes::Kernel> classic(mesh);
  policies.initialize(mesh, mesh.points(), test_meshes::Kernel());
  literal.initialize(mesh, mesh.points(), test_meshes::Kernel());
  classic.initialize(mesh, mesh.points(), test_meshes::Kernel());

  // From a ridge down to a valley, in the middle: both ends and all their neighbours have K = 1.
  const auto h = halfedge_between(mesh, {3, 2, 1}, {4, 2, 0});
  EXPECT_EQ(policies.curvature_factor(source(h, mesh), target(h, mesh)), kEps);
  const double qem = edge_cost(classic, mesh, h);
  const double tie_break = Policies::tie_break_weight * 2.0;  // |e|^2 = 2
  // The placement is the edge's midpoint (the planes leave y free); there it lies sqrt 2 / 2 off
  // the three faces on each of the outer slopes: 6 * 1/2.
  ASSERT_NEAR(qem, 3.0, 1e-12);
  EXPECT_NEAR(edge_cost(policies, mesh, h), kEps * qem + tie_break, 1e-15);
  EXPECT_EQ(edge_cost(literal, mesh, h), tie_break);  // nothing but the tie-break
}

TEST(CurvatureWeightedQuadricPolicies, TheTieBreakTakesTheShorterEdgeFirstOnAPlane) {
  Mesh mesh = flat_grid(4);
  const Policies policies(mesh);
  policies.initialize(mesh, mesh.points(), test_meshes::Kernel());
  const double side = edge_cost(policies, mesh, halfedge_between(mesh, {1, 1, 0}, {2, 1, 0}));
  const double diagonal = edge_cost(policies, mesh, halfedge_between(mesh, {1, 1, 0}, {2, 2, 0}));
  EXPECT_EQ(side, Policies::tie_break_weight);
  EXPECT_EQ(diagonal, 2 * Policies::tie_break_weight);
}

TEST(CurvatureWeightedQuadricPolicies, CostsScaleWithTheSquaredSizeOfTheMesh) {
  // Unit face weights: every term is a squared length, so the order of collapses is scale-free.
  // Scaling by a power of two is exact in floating point, and so is every cost.
  auto bumps = [](double scale) {
    return height_grid(
        6, 6, [](int i, int j) { return 0.3 * std::sin(i + 2.0 * j); }, scale);
  };
  Mesh small = bumps(1.0), large = bumps(8.0);
  const Policies small_policies(small), large_policies(large);
  small_policies.initialize(small, small.points(), test_meshes::Kernel());
  large_policies.initialize(large, large.points(), test_meshes::Kernel());
  for (auto h : halfedges(small)) {
    if (is_border(h, small)) continue;
    EXPECT_DOUBLE_EQ(edge_cost(large_policies, large, h), 64 * edge_cost(small_policies, small, h));
  }
}

// Records the vertex kept by each collapse.
struct Kept_vertex_visitor : SMS::Edge_collapse_visitor_base<Mesh> {
  Mesh::Vertex_index* kept;
  explicit Kept_vertex_visitor(Mesh::Vertex_index* k) : kept(k) {}
  template <typename Profile_type>
  void OnCollapsed(const Profile_type&, Mesh::Vertex_index v) {
    *kept = v;
  }
};

TEST(CurvatureWeightedQuadricPolicies, ACollapseRefreshesTheCurvatureAroundTheKeptVertex) {
  Mesh mesh = icosahedron();
  const Policies policies(mesh);
  Mesh::Vertex_index kept;
  // Stops after one collapse, which removes three edges.
  SMS::edge_collapse(
      mesh, cgal_policies::internal::Edge_count_stop_predicate<Mesh>(mesh.number_of_edges() - 2),
      CGAL::parameters::get_cost(policies.get_cost())
          .get_placement(policies.get_placement())
          .visitor(Kept_vertex_visitor(&kept)));
  ASSERT_EQ(mesh.number_of_faces(), 18u);

  auto normals = mesh.add_property_map<Mesh::Vertex_index, cgal_policies::internal::Stored_normal>(
                         "v:test_normal")
                     .first;
  auto curvatures = mesh.add_property_map<Mesh::Vertex_index, double>("v:test_k").first;
  cgal_policies::internal::compute_approximate_curvatures(mesh, mesh.points(), normals, curvatures);
  const double before = (std::sqrt(5.0) / 5);  // every icosahedron vertex: cos of its 5 neighbours
  EXPECT_NE(std::abs(curvatures[kept] - before), 0.0);
  EXPECT_NEAR(policies.approximate_curvature(kept), curvatures[kept], 1e-15);
  for (auto h : CGAL::halfedges_around_target(halfedge(kept, mesh), mesh))
    EXPECT_NEAR(policies.approximate_curvature(source(h, mesh)), curvatures[source(h, mesh)],
                1e-15);
}

TEST(CurvatureWeightedQuadricPolicies, TheFlatPartLosesItsFacesFirst) {
  // x in [0, 8] is the plane z = 0; beyond, a bowl-like z = 0.1 (x - 8)^2 (1 + (y - 4)^2 / 10),
  // curved both ways (a trough along y would be ruled, and its edges along y would cost nothing).
  Mesh mesh = height_grid(16, 8, [](int i, int j) {
    return i > 8 ? 0.1 * (i - 8) * (i - 8) * (1 + (j - 4) * (j - 4) / 10.0) : 0.0;
  });
  // Collapses at the seam (x = 8, 9) may move a vertex; beyond it the curved part must stay whole.
  std::vector<Point> curved;
  std::size_t flat_vertices = 0;
  for (auto v : vertices(mesh)) {
    if (mesh.point(v).x() >= 10) curved.push_back(mesh.point(v));
    flat_vertices += mesh.point(v).x() < 8;
  }
  const Policies policies(mesh);
  // The flat half holds 128 of the 256 faces; remove 96, that is 48 vertices.
  SMS::edge_collapse(
      mesh,
      [&mesh](const auto&, const auto&, std::size_t, std::size_t) {
        return mesh.number_of_faces() <= 160;
      },
      CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  mesh.collect_garbage();
  ASSERT_LE(mesh.number_of_faces(), 160u);
  for (const Point& p : curved) {
    const auto v = std::find_if(vertices(mesh).begin(), vertices(mesh).end(),
                                [&](Mesh::Vertex_index w) { return mesh.point(w) == p; });
    EXPECT_NE(v, vertices(mesh).end()) << "curved vertex " << p << " was collapsed";
  }
  std::size_t flat_left = 0;
  for (auto v : vertices(mesh)) flat_left += mesh.point(v).x() < 8;
  EXPECT_LE(flat_left + 40, flat_vertices);
}

}  // namespace
