// Hausdorff_bounded_policies, its cost, placement and filter, Hausdorff_bounded_filter and
// Laplacian_smoother (docs/hausdorff.md, [Liu17] §2.4), with the library alone: exact cases on tiny
// meshes, the filter used alone around another policy, and the choose / collapse / commit protocol
// Hausdorff_bounded_policies relies on, recorded call by call so that a CGAL upgrade that changes
// it fails here. The bounds checked by mesh_error's measure are in hausdorff_bound_test.cpp.
#include "test_meshes.h"

#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Laplacian_smoother.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using test_meshes::Kernel;
using test_meshes::Mesh;
using test_meshes::Point;
using Vertex = Mesh::Vertex_index;
using Policies = cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel>;
using Alone_filter = cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel>;

cgal_policies::Hausdorff_bounded_options options_with(double beta) {
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = beta;
  return options;
}

// Asks the policy's filter, as edge_collapse would when it pops the edge of h.
bool collapse_accepted(Mesh& mesh, const Policies& policy, Mesh::Halfedge_index h) {
  const test_meshes::Profile profile = test_meshes::edge_profile(mesh, h);
  return bool(policy.get_filter()(profile, policy.get_placement()(profile)));
}

void start(Mesh& mesh, const Policies& policy) {
  policy.get_cost().initialize(mesh, get(CGAL::vertex_point, mesh), Kernel());
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
    Mesh mesh = test_meshes::bent_grid(4, height);
    const double diagonal = test_meshes::bbox_diagonal(mesh);
    const Policies policy(mesh, options_with(tolerance / diagonal));
    start(mesh, policy);
    const bool accepted = collapse_accepted(
        mesh, policy, test_meshes::halfedge_between(mesh, Point(1, 2, 0), Point(2, 2, height)));
    EXPECT_EQ(accepted, tolerance > height) << "tolerance " << tolerance;
  }
}

TEST(HausdorffBoundedPolicies, LockedBordersRefuseBorderEdges) {
  Mesh mesh = test_meshes::flat_grid(4);
  const Mesh::Halfedge_index border_edge =
      test_meshes::halfedge_between(mesh, Point(1, 0, 0), Point(2, 0, 0));
  cgal_policies::Hausdorff_bounded_options options = options_with(0.5);
  const Policies sliding(mesh, options);
  start(mesh, sliding);
  EXPECT_TRUE(collapse_accepted(mesh, sliding, border_edge));
  options.border = cgal_policies::Border_rule::lock;
  const Policies locked(mesh, options);
  start(mesh, locked);
  EXPECT_FALSE(collapse_accepted(mesh, locked, border_edge));
}

// Hausdorff_bounded_filter alone. What it answers, as edge_collapse would ask when it pops the edge
// from a to b.
bool alone_accepts(Mesh& mesh, const Alone_filter& filter, const Point& a, const Point& b) {
  const test_meshes::Profile profile =
      test_meshes::edge_profile(mesh, test_meshes::halfedge_between(mesh, a, b));
  return bool(filter(profile, SMS::Midpoint_placement<Mesh>()(profile)));
}

TEST(HausdorffBoundedFilterAlone, RefusesACollapseThatLeavesTheBound) {
  const double height = 0.5;
  Mesh mesh = test_meshes::bent_grid(4, height);
  const double diagonal = test_meshes::bbox_diagonal(mesh);
  // The midpoint of the edge from the bend at x = 1 up to the ridge lowers the ridge by height/2.
  const Alone_filter tight(mesh, 0.1 * height / diagonal);
  EXPECT_FALSE(alone_accepts(mesh, tight, Point(1, 2, 0), Point(2, 2, height)));
  const Alone_filter loose(mesh, 2 * height / diagonal);
  EXPECT_TRUE(alone_accepts(mesh, loose, Point(1, 2, 0), Point(2, 2, height)));
}

TEST(HausdorffBoundedFilterAlone, AcceptsACollapseThatStaysWithinTheBound) {
  const double height = 0.5;
  Mesh mesh = test_meshes::bent_grid(4, height);
  // Along the bend at x = 1 the merged vertex stays on the bend: the surface does not change.
  const Alone_filter filter(mesh, 1e-3 * height / test_meshes::bbox_diagonal(mesh));
  EXPECT_TRUE(alone_accepts(mesh, filter, Point(1, 1, 0), Point(1, 2, 0)));
}

// The protocol, recorded. Every call to the three policies and every collapse is an event.
enum class Call { placement, filter, collapsed, update_after_collapse };

// in, out: for the placement, -, its point; for the filter, the placement, its point; for
// update_after_collapse, the kept vertex's point before and after.
struct Event {
  Call call;
  std::pair<Vertex, Vertex> edge;  // the profile's v0, v1, smaller first
  Point in, out;
  bool accepted = false;  // the placement or the filter returned a point
  Vertex kept = Vertex();
};
using Log = std::vector<Event>;

const Point kNoPoint(0, 0, 0);

template <typename Profile>
std::pair<Vertex, Vertex> edge_of(const Profile& profile) {
  const Vertex a = profile.v0(), b = profile.v1();
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

template <typename Placement>
struct Recording_placement {
  Placement inner;
  Log* log;
  template <typename Profile>
  auto operator()(const Profile& profile) const {
    const auto p = inner(profile);
    log->push_back({Call::placement, edge_of(profile), kNoPoint, p ? *p : kNoPoint, bool(p)});
    return p;
  }
};

template <typename Filter>
struct Recording_filter {
  Filter inner;
  Log* log;
  template <typename Profile, typename Placement>
  Placement operator()(const Profile& profile, const Placement& placement) const {
    const Placement chosen = inner(profile, placement);
    log->push_back({Call::filter, edge_of(profile), placement ? *placement : kNoPoint,
                    chosen ? *chosen : kNoPoint, bool(chosen)});
    return chosen;
  }
};

template <typename Cost>
struct Recording_cost {
  using Update_tag = CGAL::Tag_true;
  Cost inner;
  Log* log;
  template <typename VertexPointMap>
  void initialize(const Mesh& mesh, const VertexPointMap& vpm, const Kernel& traits) const {
    inner.initialize(mesh, vpm, traits);
  }
  template <typename Profile>
  void update_after_collapse(const Profile& profile, Vertex kept) const {
    const Point before = get(profile.vertex_point_map(), kept);
    inner.update_after_collapse(profile, kept);
    log->push_back({Call::update_after_collapse, edge_of(profile), before,
                    get(profile.vertex_point_map(), kept), false, kept});
  }
  template <typename Profile, typename Placement>
  auto operator()(const Profile& profile, const Placement& placement) const {
    return inner(profile, placement);
  }
};

struct Recording_visitor : SMS::Edge_collapse_visitor_base<Mesh> {
  Log* log;
  explicit Recording_visitor(Log* l) : log(l) {}
  template <typename Profile>
  void OnCollapsed(const Profile& profile, Vertex kept) {
    log->push_back({Call::collapsed, edge_of(profile), kNoPoint, kNoPoint, false, kept});
  }
};

// A sphere of 320 faces, simplified toward 40 as far as 1% of its diagonal allows.
Log record_a_run(Mesh& mesh) {
  mesh = test_meshes::icosahedron();
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = 0.01;
  const Policies policies(mesh, options);
  Log log;
  SMS::edge_collapse(
      mesh, SMS::Count_stop_predicate<Mesh>(60),
      CGAL::parameters::get_cost(Recording_cost<Policies::Get_cost>{policies.get_cost(), &log})
          .get_placement(
              Recording_placement<Policies::Get_placement>{policies.get_placement(), &log})
          .filter(Recording_filter<Policies::Filter>{policies.get_filter(), &log})
          .visitor(Recording_visitor(&log)));
  return log;
}

TEST(HausdorffBoundedProtocol, CgalCollapsesWhatTheFilterAcceptedThenUpdatesTheCost) {
  Mesh mesh;
  const Log log = record_a_run(mesh);
  std::size_t collapses = 0, moved_by_the_filter = 0;
  for (std::size_t i = 0; i < log.size(); ++i) {
    const Event& e = log[i];
    if (e.call == Call::filter && e.accepted) {
      // Accepted: collapsed at once, nothing in between.
      ASSERT_LT(i + 1, log.size());
      EXPECT_EQ(log[i + 1].call, Call::collapsed) << "event " << i;
      EXPECT_EQ(log[i + 1].edge, e.edge) << "event " << i;
    }
    if (e.call != Call::collapsed) continue;
    ++collapses;
    // Preceded by the filter's acceptance of the same edge, which got the placement's point.
    ASSERT_GT(i, 1u);
    const Event& filter = log[i - 1];
    ASSERT_EQ(filter.call, Call::filter) << "event " << i;
    EXPECT_TRUE(filter.accepted);
    EXPECT_EQ(filter.edge, e.edge);
    const Event& placement = log[i - 2];
    ASSERT_EQ(placement.call, Call::placement) << "event " << i;
    EXPECT_EQ(placement.edge, e.edge);
    EXPECT_EQ(placement.out, filter.in);
    // Followed by update_after_collapse for that edge before any other filter call or collapse:
    // the vertex is then at the placement's point, and moved to the filter's.
    std::size_t j = i + 1;
    while (j < log.size() && log[j].call == Call::placement) ++j;
    ASSERT_LT(j, log.size());
    const Event& update = log[j];
    ASSERT_EQ(update.call, Call::update_after_collapse) << "event " << j;
    EXPECT_EQ(update.edge, e.edge);
    EXPECT_EQ(update.kept, e.kept);
    EXPECT_EQ(update.in, filter.in) << "collapsed to the placement's point";
    EXPECT_EQ(update.out, filter.out) << "moved to the filter's point";
    moved_by_the_filter += filter.out != filter.in;
  }
  EXPECT_GT(collapses, 50u);
  EXPECT_GT(moved_by_the_filter, 0u);  // the test has teeth: the two points differ
}

TEST(HausdorffBoundedProtocol, EverySurvivingKeptVertexSitsWhereTheFilterChose) {
  Mesh mesh;
  const Log log = record_a_run(mesh);
  std::map<Vertex, Point> chosen;  // the kept vertices still alive, and their last choice
  const Point* last_choice = nullptr;
  for (const Event& e : log) {
    if (e.call == Call::filter) last_choice = e.accepted ? &e.out : nullptr;
    if (e.call != Call::collapsed) continue;
    ASSERT_NE(last_choice, nullptr);
    const Vertex removed = e.kept == e.edge.first ? e.edge.second : e.edge.first;
    chosen.erase(removed);
    chosen[e.kept] = *last_choice;
  }
  ASSERT_FALSE(chosen.empty());
  for (const auto& [v, p] : chosen) {
    ASSERT_FALSE(mesh.is_removed(v));
    EXPECT_EQ(mesh.point(v), p) << "vertex " << v;
  }
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

}  // namespace
