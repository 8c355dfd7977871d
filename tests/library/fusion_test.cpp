// Unit tests of Feature_fusion_policies and its measures (docs/fusion.md): the side ratio of eq. 9,
// the normal twist, the normal factor, their refresh after collapses, and scale invariance.
#include "test_meshes.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Feature_fusion_policies.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/feature_fusion_measures.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using test_meshes::Kernel;
using test_meshes::Mesh;
using test_meshes::Point;
using Policies = cgal_policies::Feature_fusion_policies<Mesh, Kernel>;
using Vertex = Mesh::Vertex_index;

cgal_policies::Feature_fusion_options with_visual_weight(double visual_weight) {
  cgal_policies::Feature_fusion_options options;
  options.visual_weight = visual_weight;
  return options;
}

// The unit sphere as an icosahedron split `levels` times into four, new points pushed onto it.
Mesh icosphere(int levels) {
  const Mesh base = test_meshes::icosahedron();
  std::vector<Point> points;
  for (Vertex v : vertices(base)) points.push_back(base.point(v));
  std::vector<std::array<int, 3>> triangles;
  for (auto f : faces(base)) {
    std::array<int, 3> t;
    int i = 0;
    for (Vertex v : vertices_around_face(base.halfedge(f), base)) t[i++] = int(v);
    triangles.push_back(t);
  }
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      const auto m = CGAL::midpoint(points[a], points[b]) - CGAL::ORIGIN;
      points.push_back(CGAL::ORIGIN + m / std::sqrt(m.squared_length()));
      return midpoints[key] = int(points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : triangles) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = finer;
  }
  return test_meshes::from_triangles(points, triangles);
}

// A grid over [-1, 1]^2 lifted to z = height(x, y).
template <typename Height>
Mesh height_field(int n, const Height& height) {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      points.emplace_back(x, y, height(x, y));
    }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return test_meshes::from_triangles(points, triangles);
}

bool is_border_vertex(Vertex v, const Mesh& mesh) {
  return mesh.is_border(v, /*check_all_incident_halfedges=*/true);
}

// T(v) for every vertex not on a border, with the area-weighted normals the policy uses.
std::vector<double> interior_twists(const Mesh& mesh) {
  const auto vpm = get(CGAL::vertex_point, mesh);
  const auto normal = [&](Vertex v) {
    return cgal_policies::internal::vertex_normal(v, mesh, vpm,
                                                  cgal_policies::internal::Normal_weighting::area);
  };
  const auto edge_term = [&](Mesh::Halfedge_index h) {
    return cgal_policies::internal::Normal_variation_sum::of(
        cgal_policies::internal::edge_normal_variation(h, mesh, vpm, normal, true));
  };
  std::vector<double> twists;
  for (Vertex v : vertices(mesh))
    if (!is_border_vertex(v, mesh))
      twists.push_back(
          cgal_policies::internal::normal_variation_sum(v, mesh, edge_term).mean_twist());
  return twists;
}

//   C (0,3) ---- D (4,3)
//     |  \        |
//     |    \      |      AB = CD = 4, AC = BD = 3, BC = 5
//     |      \    |
//   A (0,0) ---- B (4,0)
Mesh two_right_triangles() {
  return test_meshes::from_triangles(
      {Point(0, 0, 0), Point(4, 0, 0), Point(0, 3, 0), Point(4, 3, 0)}, {{0, 1, 2}, {1, 3, 2}});
}

TEST(FusionSideRatio, InteriorEdgeIsItsLengthOverTheFourOthers) {
  const Mesh mesh = two_right_triangles();
  const auto bc = halfedge(Vertex(1), Vertex(2), mesh).first;
  const auto vpm = get(CGAL::vertex_point, mesh);
  EXPECT_EQ(cgal_policies::internal::side_ratio(bc, mesh, vpm), 5.0 / 14.0);
  EXPECT_EQ(cgal_policies::internal::side_ratio(opposite(bc, mesh), mesh, vpm), 5.0 / 14.0);
}

TEST(FusionSideRatio, BorderEdgeIsItsLengthOverTheTwoOthers) {
  const Mesh mesh = two_right_triangles();
  const auto vpm = get(CGAL::vertex_point, mesh);
  const auto ab = halfedge(Vertex(0), Vertex(1), mesh).first;  // inside triangle ABC
  EXPECT_EQ(cgal_policies::internal::side_ratio(ab, mesh, vpm), 4.0 / 8.0);
  EXPECT_EQ(cgal_policies::internal::side_ratio(opposite(ab, mesh), mesh, vpm), 4.0 / 8.0);
  const auto ca = halfedge(Vertex(2), Vertex(0), mesh).first;
  EXPECT_EQ(cgal_policies::internal::side_ratio(ca, mesh, vpm), 3.0 / 9.0);
}

TEST(FusionTwist, IsZeroOnAPlane) {
  for (double twist : interior_twists(test_meshes::flat_grid(6))) EXPECT_EQ(twist, 0.0);
}

TEST(FusionTwist, IsNearlyZeroOnAFineSphere) {
  // An exactly radial normal field would give exactly zero; area-weighted normals of an icosphere
  // are radial up to a tessellation error, largest at its valence-5 vertices, that halves at each
  // level (max 0.0038 at this one). A saddle of the same edge length twists by more than 0.02.
  const std::vector<double> twists = interior_twists(icosphere(4));
  ASSERT_EQ(twists.size(), 2562u);
  EXPECT_LT(*std::max_element(twists.begin(), twists.end()), 0.005);
}

TEST(FusionTwist, IsLargeOnASaddle) {
  // z = xy twists its normal along the x and y edges of the grid by about the edge length.
  const std::vector<double> twists =
      interior_twists(height_field(20, [](double x, double y) { return x * y; }));
  for (double twist : twists) EXPECT_GT(twist, 0.02);
}

TEST(FusionNormalFactor, IsExactlyOneAndTwistZeroOnAFlatPatch) {
  Mesh mesh = test_meshes::flat_grid(5);
  const Policies policies(mesh, with_visual_weight(0.02));
  policies.initialize(mesh, get(CGAL::vertex_point, mesh), Kernel());
  EXPECT_DOUBLE_EQ(policies.input_mean_edge_length(), (60.0 + 25 * std::sqrt(2.0)) / 85.0);
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    EXPECT_EQ(policies.normal_factor(source(h, mesh), target(h, mesh)), 1.0);
    EXPECT_EQ(policies.edge_twist(source(h, mesh), target(h, mesh)), 0.0);
  }
}

TEST(FusionNormalFactor, GrowsWithTheNormalAngles) {
  Mesh mesh = test_meshes::icosahedron();
  const Policies policies(mesh, with_visual_weight(0.02));
  policies.initialize(mesh, get(CGAL::vertex_point, mesh), Kernel());
  // Every vertex normal of the icosahedron makes the same angle with its five neighbours'.
  const double expected = 1.0 + 2.0 * std::acos(1.0 / std::sqrt(5.0));
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    EXPECT_NEAR(policies.normal_factor(source(h, mesh), target(h, mesh)), expected, 1e-12);
  }
}

// Records the collapsed edges as (v0, v1) index pairs.
class Collapse_recorder : public SMS::Edge_collapse_visitor_base<Mesh> {
 public:
  explicit Collapse_recorder(std::vector<std::pair<int, int>>& collapses)
      : m_collapses(&collapses) {}
  template <typename Profile>
  void OnCollapsed(const Profile& profile, Vertex) {
    m_collapses->emplace_back(int(profile.v0()), int(profile.v1()));
  }

 private:
  std::vector<std::pair<int, int>>* m_collapses;
};

std::vector<std::pair<int, int>> simplify(Mesh& mesh, std::size_t edges_left,
                                          const Policies& policies) {
  std::vector<std::pair<int, int>> collapses;
  SMS::edge_collapse(mesh, cgal_policies::internal::Edge_count_stop_predicate<Mesh>(edges_left),
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>())
                         .visitor(Collapse_recorder(collapses)));
  return collapses;
}

// A bumpy disk without symmetries, so that no two costs tie.
Mesh bumpy_patch() {
  return height_field(16, [](double x, double y) {
    return 0.3 * std::sin(2.1 * x + 0.4) * std::cos(1.7 * y - 0.2) + 0.05 * x * x * y;
  });
}

// Simplifies `mesh` and checks the stored normal factors and twists against a fresh computation.
void expect_features_of_the_current_mesh(Mesh mesh, double visual_weight) {
  const Policies policies(mesh, with_visual_weight(visual_weight));
  ASSERT_GT(simplify(mesh, 300, policies).size(), 500u);
  const Policies fresh(mesh, with_visual_weight(visual_weight));
  fresh.initialize(mesh, get(CGAL::vertex_point, mesh), Kernel());
  double largest_twist = 0;
  for (auto e : edges(mesh)) {
    const Vertex a = source(halfedge(e, mesh), mesh), b = target(halfedge(e, mesh), mesh);
    EXPECT_EQ(policies.normal_factor(a, b), fresh.normal_factor(a, b));
    EXPECT_EQ(policies.edge_twist(a, b), fresh.edge_twist(a, b));
    largest_twist = (std::max)(largest_twist, fresh.edge_twist(a, b));
  }
  // The twist is computed only when the visual term is on.
  if (visual_weight > 0)
    EXPECT_GT(largest_twist, 0.0);
  else
    EXPECT_EQ(largest_twist, 0.0);
}

TEST(FusionPolicies, FeaturesAfterCollapsesAreThoseOfTheCurrentMesh) {
  expect_features_of_the_current_mesh(icosphere(3), 0.0);
  expect_features_of_the_current_mesh(icosphere(3), 0.02);
}

void expect_scale_invariant(const Mesh& input, std::size_t edges_left) {
  Mesh small = input, large = input;
  CGAL::Polygon_mesh_processing::transform(Kernel::Aff_transformation_3(CGAL::SCALING, 1000),
                                           large);
  // With the visual term on, so that both terms of the cost are checked.
  const Policies small_policies(small, with_visual_weight(0.02)),
      large_policies(large, with_visual_weight(0.02));
  const auto small_collapses = simplify(small, edges_left, small_policies);
  const auto large_collapses = simplify(large, edges_left, large_policies);
  ASSERT_GT(small_collapses.size(), 0u);
  EXPECT_EQ(small_collapses, large_collapses);
  double largest_gap = 0;
  for (Vertex v : vertices(small)) {
    const auto scaled = (small.point(v) - CGAL::ORIGIN) * 1000;
    largest_gap = (std::max)(largest_gap,
                             std::sqrt((large.point(v) - CGAL::ORIGIN - scaled).squared_length()));
  }
  EXPECT_LT(largest_gap, 1e-9 * 1000);
}

TEST(FusionPolicies, ScaledByAThousandCollapsesTheSameEdgesToTheSamePoints) {
  expect_scale_invariant(bumpy_patch(), 100);
}

TEST(FusionPolicies, ScaleInvariantOnARealMesh) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  // Not the cow: it is mirror-symmetric, so its costs tie exactly and round-off breaks the ties
  // differently at another scale.
  const Mesh bunny = test_meshes::read_clean_mesh("bunny.obj");
  expect_scale_invariant(bunny, bunny.number_of_edges() / 2);
}

}  // namespace
