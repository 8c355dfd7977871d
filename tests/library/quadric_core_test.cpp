// The shared quadric core (docs/quadric_core.md), the attribute quadric (docs/attributes.md),
// Classic_quadric_policies and Bounded_normal_angle_filter, on tiny meshes with exact expectations.
#include "test_meshes.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/internal/Attribute_quadric.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace test_meshes;
using cgal_policies::Face_weighting;
using cgal_policies::internal::optimal_placement;
using cgal_policies::internal::Placement_branch;
using cgal_policies::internal::Quadric;

using Quadric_map = Mesh::Property_map<Mesh::Vertex_index, Quadric>;

Quadric_map vertex_quadrics(Mesh& mesh, double border_weight) {
  Quadric_map q = mesh.add_property_map<Mesh::Vertex_index, Quadric>("v:test_quadric").first;
  cgal_policies::internal::accumulate_vertex_quadrics(mesh, mesh.points(), Face_weighting::unit,
                                                      border_weight, q, q);
  return q;
}

Eigen::Vector3d eigen(const Point& p) { return {p.x(), p.y(), p.z()}; }

TEST(Quadric, EvaluatesTheWeightedSquaredDistanceToItsPlane) {
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2) / 3.0;  // unit normal
  const Quadric q = Quadric::from_plane(n, -1.0, 2.0);       // plane n.x = 1, weight 2
  EXPECT_DOUBLE_EQ(q.evaluate({3, 0, 0}), 2.0 * 0.0);        // n.(3,0,0) = 1: on the plane
  EXPECT_DOUBLE_EQ(q.evaluate({0, 0, 0}), 2.0 * 1.0);
  EXPECT_DOUBLE_EQ(q.evaluate({1, 2, 2}), 2.0 * 4.0);  // n.x = 3
  EXPECT_DOUBLE_EQ((q + q).evaluate({0, 0, 0}), 4.0);
  EXPECT_DOUBLE_EQ(q.scaled(0.5).evaluate({0, 0, 0}), 1.0);
}

TEST(Quadric, AreaWeightingMultipliesByTheFaceArea) {
  Mesh mesh = from_triangles({{0, 0, 0}, {4, 0, 0}, {0, 3, 0}}, {{0, 1, 2}});
  const auto f = *faces(mesh).begin();
  const Quadric unit =
      cgal_policies::internal::face_plane_quadric(f, mesh, mesh.points(), Face_weighting::unit);
  const Quadric area =
      cgal_policies::internal::face_plane_quadric(f, mesh, mesh.points(), Face_weighting::area);
  EXPECT_DOUBLE_EQ(unit.evaluate({1, 1, 2}), 4.0);
  EXPECT_DOUBLE_EQ(area.evaluate({1, 1, 2}), 6.0 * 4.0);
}

// The face z = 0 with corners (0,0,0), (2,0,0), (0,2,0), weight 3, carrying two attributes:
// s0 = x + 1 (linear) and s1 = 0.5 y, and nothing in the other slots.
cgal_policies::internal::Attribute_quadric attribute_test_face() {
  using cgal_policies::internal::Attribute_quadric;
  const double none = std::numeric_limits<double>::quiet_NaN();
  const std::array<Eigen::Vector3d, 3> p{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                         Eigen::Vector3d(0, 2, 0)};
  std::array<Attribute_quadric::Attributes, 3> s;
  for (int k = 0; k < 3; ++k) {
    s[k] = Attribute_quadric::Attributes::Constant(none);
    s[k].head<2>() << p[k].x() + 1, 0.5 * p[k].y();
  }
  return Attribute_quadric::from_face(p, s, 3.0);
}

TEST(AttributeQuadric, IsZeroOnItsFaceWithTheFaceValues) {
  const auto q = attribute_test_face();
  auto s = cgal_policies::internal::Attribute_quadric::Attributes::Constant(7).eval();
  s.head<2>() << 1.5, 0.25;  // at (0.5, 0.5, 0); the others have no term
  EXPECT_NEAR(q.evaluate({0.5, 0.5, 0}, s), 0, 1e-12);
}

TEST(AttributeQuadric, AddsTheSquaredDistanceToThePlaneAndToEachField) {
  const auto q = attribute_test_face();
  auto s = cgal_policies::internal::Attribute_quadric::Attributes::Zero().eval();
  s.head<2>() << 1.5 + 0.2, 0.25 - 0.1;  // at (0.5, 0.5, 0.4)
  EXPECT_NEAR(q.evaluate({0.5, 0.5, 0.4}, s), 3.0 * (0.16 + 0.04 + 0.01), 1e-12);
}

TEST(AttributeQuadric, BestAttributesAreTheFieldsAtTheProjectionAndLeaveThePlaneQuadric) {
  const auto q = attribute_test_face();
  const Eigen::Vector3d x(0.3, -0.7, 0.5);  // the fields are extended beyond the triangle
  const auto best = q.best_attributes(x);
  EXPECT_NEAR(best[0], 1.3, 1e-12);
  EXPECT_NEAR(best[1], -0.35, 1e-12);
  for (int j = 2; j < best.size(); ++j) EXPECT_TRUE(std::isnan(best[j])) << j;
  EXPECT_NEAR(q.evaluate(x, best), 3.0 * 0.25, 1e-12);
  EXPECT_NEAR(q.position_quadric().evaluate(x), 3.0 * 0.25, 1e-12);
}

TEST(AttributeQuadric, TwoFacesDisagreeingOnAValueAreMetHalfway) {
  using cgal_policies::internal::Attribute_quadric;
  const double none = std::numeric_limits<double>::quiet_NaN();
  const std::array<Eigen::Vector3d, 3> p{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                         Eigen::Vector3d(0, 1, 0)};
  std::array<Attribute_quadric::Attributes, 3> zero, two;
  for (int k = 0; k < 3; ++k) {
    zero[k] = two[k] = Attribute_quadric::Attributes::Constant(none);
    zero[k][0] = 0;
    two[k][0] = 2;
  }
  const Attribute_quadric q =
      Attribute_quadric::from_face(p, zero, 1.0) + Attribute_quadric::from_face(p, two, 1.0);
  EXPECT_NEAR(q.best_attributes({0.2, 0.2, 0})[0], 1.0, 1e-12);
  EXPECT_NEAR(q.position_quadric().evaluate({0.2, 0.2, 0}), 2.0, 1e-12);  // 1^2 + 1^2
}

TEST(ClassicQuadricPolicies, EveryEdgeOfAFlatGridCostsZero) {
  Mesh mesh = flat_grid(3);
  const cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh);
  policies.initialize(mesh, mesh.points(), Kernel());
  for (auto h : halfedges(mesh)) {
    if (is_border(h, mesh)) continue;
    const Profile profile = edge_profile(mesh, h);
    const auto placement = policies.get_placement()(profile);
    ASSERT_TRUE(placement);
    EXPECT_EQ(placement->z(), 0.0);
    const auto cost = policies.get_cost()(profile, placement);
    ASSERT_TRUE(cost);
    EXPECT_EQ(*cost, 0.0) << "edge " << profile.p0() << " -> " << profile.p1();
  }
}

TEST(PlacementChain, SolvesWhenTheQuadricIsWellConditioned) {
  // Around an edge of a tetrahedron lie all four face planes (the edge's two faces twice): the
  // minimiser is a proper point, where the gradient A x + b vanishes, better than any point of
  // the edge.
  Mesh mesh = tetrahedron();
  const Quadric_map q = vertex_quadrics(mesh, 1000);
  const auto h = *halfedges(mesh).begin();
  const Eigen::Vector3d p0 = eigen(mesh.point(source(h, mesh))),
                        p1 = eigen(mesh.point(target(h, mesh)));
  const Quadric sum = q[source(h, mesh)] + q[target(h, mesh)];
  const auto choice = optimal_placement(sum, p0, p1);
  EXPECT_EQ(choice.branch, Placement_branch::solve);
  EXPECT_NEAR((sum.linear_part() * choice.point + sum.offset()).norm(), 0.0, 1e-12);
  for (const Eigen::Vector3d& p : {p0, p1, Eigen::Vector3d(0.5 * (p0 + p1))})
    EXPECT_LT(sum.evaluate(choice.point), sum.evaluate(p));
}

TEST(PlacementChain, MinimisesAlongTheEdgeWhenThePlanesLeaveADirectionFree) {
  // A strip across x with profile z = x on [-1, 0], z = 0 on [0, 2], z = 2 - x on [2, 3]: every
  // normal lies in the xz plane, so A is singular. Along the edge (0,0,0)-(2,0,0) the cost is
  // x^2/2 + (x - 2)^2/2, smallest at x = 1.
  Mesh mesh = from_triangles({{-1, 0, -1},
                              {0, 0, 0},
                              {2, 0, 0},
                              {3, 0, -1},
                              {-1, 1, -1},
                              {0, 1, 0},
                              {2, 1, 0},
                              {3, 1, -1}},
                             {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 6}, {3, 7, 6}});
  const Quadric_map q = vertex_quadrics(mesh, 0);  // border planes would pin the ends
  const auto h = halfedge_between(mesh, {0, 0, 0}, {2, 0, 0});
  const auto choice =
      optimal_placement(q[source(h, mesh)] + q[target(h, mesh)], {0, 0, 0}, {2, 0, 0});
  EXPECT_EQ(choice.branch, Placement_branch::segment);
  EXPECT_NEAR((choice.point - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(PlacementChain, TakesTheBestOfEndsAndMidpointWhenTheEdgeCostsNothingAnywhere) {
  // Inside a flat grid the quadric is the plane z = 0 alone: no solve, and no change along the
  // edge.
  Mesh mesh = flat_grid(3);
  const Quadric_map q = vertex_quadrics(mesh, 1000);
  const auto h = halfedge_between(mesh, {1, 1, 0}, {2, 2, 0});
  const auto choice =
      optimal_placement(q[source(h, mesh)] + q[target(h, mesh)], {1, 1, 0}, {2, 2, 0});
  EXPECT_EQ(choice.branch, Placement_branch::best_of_three);
  EXPECT_EQ(choice.point, Eigen::Vector3d(1, 1, 0));  // ties go to the first end
}

TEST(PlacementChain, RejectsAMinimiserFarFromTheEdge) {
  // Two nearly parallel planes meet far away: the well-conditioned test passes but the point is
  // more than two edge lengths off, so the chain falls back to the segment.
  const Eigen::Vector3d n1 = Eigen::Vector3d(0, 0.01, 1).normalized();
  const Eigen::Vector3d n2 = Eigen::Vector3d(0, -0.01, 1).normalized();
  const Quadric q = Quadric::from_plane(n1, -n1.z() * 0.1, 1) + Quadric::from_plane(n2, 0, 1) +
                    Quadric::from_plane({1, 0, 0}, 0, 1);
  const auto choice = optimal_placement(q, {0, 0, 0}, {0, 0.1, 0});
  EXPECT_NE(choice.branch, Placement_branch::solve);
  EXPECT_LE(choice.point.norm(), 0.1 + 1e-12);
}

TEST(PlacementChain, TheConditioningTestDecidesAsTheEigenvaluesDo) {
  // R diag(l0, l1, l2) R^T over random rotations, l0 <= l1 <= l2 with l0 / l2 from 1 down to 1e-14
  // or 0 and l1 between on a log scale, or equal to l0: the shortcuts of is_well_conditioned must
  // give l0 > 1e-6 l2 wherever they decide. Ratios within 0.1% of the limit are left out: there
  // the eigen solver's own rounding may decide either way.
  using cgal_policies::internal::is_well_conditioned;
  using cgal_policies::internal::kMinimumConditioning;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1, 1), share(0, 1);
  std::size_t well = 0, ill = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Matrix3d rotation =
        Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random))
            .normalized()
            .toRotationMatrix();
    const double l2 = std::pow(10.0, 4 * unit(random));
    const double low = -14 * share(random), high = low * share(random);
    const double l0 = i % 5 == 0 ? 0.0 : l2 * std::pow(10.0, low);
    const double l1 = i % 7 == 0 ? l0 : l2 * std::pow(10.0, high);
    if (std::abs(l0 / l2 / kMinimumConditioning - 1) < 1e-3) continue;
    const Eigen::Matrix3d a =
        rotation * Eigen::Vector3d(l0, l1, l2).asDiagonal() * rotation.transpose();
    const bool expected = l0 > kMinimumConditioning * l2;
    ASSERT_EQ(is_well_conditioned(a), expected) << "l0 " << l0 << " l1 " << l1 << " l2 " << l2;
    (expected ? well : ill) += 1;
  }
  EXPECT_GT(well, 4000u);  // both sides well covered
  EXPECT_GT(ill, 4000u);
}

TEST(BorderPlanes, KeepABorderVertexOnItsBorderLine) {
  // Collapsing a border vertex into an interior neighbour must not pull it inside.
  Mesh mesh = flat_grid(2);
  const Quadric_map q = vertex_quadrics(mesh, 1000);
  const auto h = halfedge_between(mesh, {1, 0, 0}, {1, 1, 0});
  const auto choice =
      optimal_placement(q[source(h, mesh)] + q[target(h, mesh)], {1, 0, 0}, {1, 1, 0});
  EXPECT_EQ(choice.point, Eigen::Vector3d(1, 0, 0));
}

TEST(BorderPlanes, ASimplifiedGridKeepsItsOutline) {
  Mesh mesh = flat_grid(8);
  const cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh);
  CGAL::Surface_mesh_simplification::edge_collapse(
      mesh, cgal_policies::internal::Edge_count_stop_predicate<Mesh>(20),
      CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  mesh.collect_garbage();
  ASSERT_LT(mesh.number_of_faces(), 128u);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    EXPECT_EQ(p.z(), 0.0);
    if (is_border(v, mesh)) {
      EXPECT_TRUE(p.x() == 0 || p.x() == 8 || p.y() == 0 || p.y() == 8) << p;
    }
  }
}

// The filter's verdict on collapsing the edge (2,2) -> (3,2) of the 4 x 4 flat grid to p. The
// link of the merged vertex is the octagon (1,1) (2,1) (3,1) (4,2) (4,3) (3,3) (2,3) (1,2), whose
// nearest edges lie at distance 1 from (2.5, 2).
bool angle_filter_accepts(double max_angle_degrees, const Point& p) {
  Mesh mesh = flat_grid(4);
  const Profile profile = edge_profile(mesh, halfedge_between(mesh, {2, 2, 0}, {3, 2, 0}));
  const cgal_policies::Bounded_normal_angle_filter<> filter(max_angle_degrees);
  return bool(filter(profile, cgal_policies::internal::Optional<Point>(p)));
}

TEST(BoundedNormalAngleFilter, AcceptsAPlacementInThePlane) {
  EXPECT_TRUE(angle_filter_accepts(90, {2.5, 2, 0}));
  EXPECT_TRUE(angle_filter_accepts(1, {2.5, 2, 0}));
}

TEST(BoundedNormalAngleFilter, RefusesAFold) {
  // Beyond the link edge y = 1, the faces on that edge turn upside down.
  EXPECT_FALSE(angle_filter_accepts(90, {2.5, 0.5, 0}));
  EXPECT_FALSE(angle_filter_accepts(179, {2.5, 0.5, 0}));
}

TEST(BoundedNormalAngleFilter, RefusesAFaceLeftDegenerate) {
  // On the link edge (2,1)-(3,1), the face over that edge has no area left.
  EXPECT_FALSE(angle_filter_accepts(180, {2.5, 1, 0}));
}

TEST(BoundedNormalAngleFilter, TheBoundIsTheLargestTurnOfAFaceNormal) {
  // Lifted by 1 over (2.5, 2), the faces over the nearest link edges tilt by atan(1 / 1) = 45
  // degrees, and no face tilts more.
  const Point lifted(2.5, 2, 1);
  EXPECT_TRUE(angle_filter_accepts(90, lifted));
  EXPECT_TRUE(angle_filter_accepts(45.5, lifted));
  EXPECT_FALSE(angle_filter_accepts(44.5, lifted));
  EXPECT_FALSE(angle_filter_accepts(30, lifted));
}

TEST(BoundedNormalAngleFilter, RunsItsBaseFilterFirst) {
  Mesh mesh = flat_grid(4);
  const Profile profile = edge_profile(mesh, halfedge_between(mesh, {2, 2, 0}, {3, 2, 0}));
  const auto refuse_all = [](const Profile&, cgal_policies::internal::Optional<Point>) {
    return cgal_policies::internal::Optional<Point>();
  };
  const cgal_policies::Bounded_normal_angle_filter<decltype(refuse_all)> filter(90, refuse_all);
  EXPECT_FALSE(filter(profile, cgal_policies::internal::Optional<Point>(Point(2.5, 2, 0))));
}

}  // namespace
