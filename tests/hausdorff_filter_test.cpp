// Hausdorff_bounded_filter's contract with CGAL's edge_collapse (docs/hausdorff.md): used alone
// around another policy, and the choose / collapse / commit protocol Hausdorff_bounded_policies
// relies on, recorded call by call so that a CGAL upgrade that changes it fails here.
#include "common/mesh_measures.h"
#include "test_meshes.h"

#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using apps::Kernel;
using apps::Mesh;
using apps::Point;
using Vertex = Mesh::Vertex_index;
using Alone_filter = cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel>;

// An n x n grid bent along x = n / 2, whose vertices are raised by `height`: two planes meeting
// along a ridge, flat again beyond x = n / 2 -+ 1.
Mesh bent_grid(int n, double height) {
  Mesh mesh = test_meshes::flat_grid(n);
  for (auto v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    if (p.x() == n / 2) mesh.point(v) = Point(p.x(), p.y(), height);
  }
  return mesh;
}

// What the filter answers, as edge_collapse would ask when it pops the edge from a to b.
bool alone_accepts(Mesh& mesh, const Alone_filter& filter, const Point& a, const Point& b) {
  const test_meshes::Profile profile =
      test_meshes::edge_profile(mesh, test_meshes::halfedge_between(mesh, a, b));
  return bool(filter(profile, SMS::Midpoint_placement<Mesh>()(profile)));
}

TEST(HausdorffBoundedFilterAlone, RefusesACollapseThatLeavesTheBound) {
  const double height = 0.5;
  Mesh mesh = bent_grid(4, height);
  const double diagonal = apps::bbox_diagonal(mesh);
  // The midpoint of the edge from the bend at x = 1 up to the ridge lowers the ridge by height/2.
  const Alone_filter tight(mesh, 0.1 * height / diagonal);
  EXPECT_FALSE(alone_accepts(mesh, tight, Point(1, 2, 0), Point(2, 2, height)));
  const Alone_filter loose(mesh, 2 * height / diagonal);
  EXPECT_TRUE(alone_accepts(mesh, loose, Point(1, 2, 0), Point(2, 2, height)));
}

TEST(HausdorffBoundedFilterAlone, AcceptsACollapseThatStaysWithinTheBound) {
  const double height = 0.5;
  Mesh mesh = bent_grid(4, height);
  // Along the bend at x = 1 the merged vertex stays on the bend: the surface does not change.
  const Alone_filter filter(mesh, 1e-3 * height / apps::bbox_diagonal(mesh));
  EXPECT_TRUE(alone_accepts(mesh, filter, Point(1, 1, 0), Point(1, 2, 0)));
}

// Edge length and midpoints as far as they go, bounded or not.
template <typename Filter>
void collapse_shortest_edges(Mesh& mesh, const Filter& filter) {
  SMS::edge_collapse(mesh, SMS::Count_stop_predicate<Mesh>(1),
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                         .get_placement(SMS::Midpoint_placement<Mesh>())
                         .filter(filter));
  mesh.collect_garbage();
}

TEST(HausdorffBoundedFilterAlone, BoundsARunOfAnotherPolicy) {
  const double tolerance = 0.01;
  const Mesh original = bent_grid(8, 2.0);
  Mesh free = original, bounded = original;
  collapse_shortest_edges(free, SMS::internal::Dummy_filter());
  collapse_shortest_edges(
      bounded, Alone_filter(bounded, tolerance, SMS::internal::Dummy_filter(), bounded.points()));
  const apps::Mesh_error free_error = apps::measure_mesh_error(original, free, 20000);
  const apps::Mesh_error error = apps::measure_mesh_error(original, bounded, 20000);
  EXPECT_GT(free_error.hausdorff, tolerance * free_error.bbox_diagonal);  // the test has teeth
  EXPECT_LT(bounded.number_of_faces(), original.number_of_faces());
  EXPECT_LE(error.hausdorff, tolerance * error.bbox_diagonal);
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
  const cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> policies(mesh, options);
  Log log;
  using Policies = cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel>;
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

}  // namespace
