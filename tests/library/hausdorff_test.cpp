// Hausdorff_bounded_policies, its cost, placement and filter, and Hausdorff_bounded_filter
// (docs/hausdorff.md): exact cases on tiny
// meshes, the filter used alone around another policy, and the choose / collapse / commit protocol
// Hausdorff_bounded_policies relies on, recorded call by call so that a CGAL upgrade that changes
// it fails here; and the bounds checked by mesh_error's measure (apps::measure_mesh_error): local
// mode drifts while global mode keeps the two-sided bound, on a cylinder band and on real meshes,
// and Hausdorff_bounded_filter bounds a run of another policy; and the bound kept across the parts
// of a partitioned run, in memory and as a job.
#include "Job_folder.h"
#include "pipeline_runs.h"
#include "test_meshes.h"

#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cgal_policies/Face_count_stop_predicate.h>

#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
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
      mesh, cgal_policies::internal::Edge_count_stop_predicate<Mesh>(60),
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

// The policies alone on `mesh` toward `target` faces, as far as the tolerance allows.
void collapse_within(Mesh& mesh, const cgal_policies::Hausdorff_bounded_options& options,
                     std::size_t target) {
  {
    const Policies policy(mesh, options);
    SMS::edge_collapse(mesh, cgal_policies::Face_count_stop_predicate<Mesh>(mesh, target),
                       CGAL::parameters::get_cost(policy.get_cost())
                           .get_placement(policy.get_placement())
                           .filter(policy.get_filter()));
  }
  mesh.collect_garbage();
}

apps::Mesh_error simplify_band(cgal_policies::Hausdorff_reference reference, double beta) {
  Mesh mesh = cylinder_band(64);
  const Mesh original = mesh;
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = beta;
  options.reference = reference;
  collapse_within(mesh, options, 2);
  return apps::measure_mesh_error(original, mesh, 20000);
}

TEST(HausdorffBoundedPolicies, LocalModeAccumulatesWhileGlobalModeKeepsTheBound) {
  const double beta = 0.01;
  const apps::Mesh_error local = simplify_band(cgal_policies::Hausdorff_reference::local, beta);
  const apps::Mesh_error global = simplify_band(cgal_policies::Hausdorff_reference::global, beta);
  EXPECT_GT(local.hausdorff, beta * local.bbox_diagonal);
  EXPECT_LE(global.hausdorff, beta * global.bbox_diagonal);
}

// The registry's hausdorff entry in local mode: its tolerance is no two-sided bound (the run
// above goes past it), so the app claims none, and --max-error is kept by the runner's filter.
// Before, local mode with --max-error took the tighter tolerance as its only check and went past
// the bound the user asked for.
TEST(HausdorffBoundedPolicies, LocalModeKeepsMaxErrorThroughTheRunnersFilter) {
  const double bound = 0.01;
  cgal_policies::Simplification_options options = pipeline_runs::policy_alone("hausdorff", 2);
  options.hausdorff.reference = cgal_policies::Hausdorff_reference::local;
  options.hausdorff.beta = bound;
  EXPECT_EQ(options.two_sided_bound(), 0.0);
  options.max_error = bound;
  EXPECT_EQ(options.two_sided_bound(), bound);
  Mesh mesh = cylinder_band(64);
  const Mesh original = mesh;
  const cgal_policies::Simplification_report outcome = apps::Pipeline(options).run(mesh);
  const apps::Mesh_error error = apps::measure_mesh_error(original, mesh, 20000);
  EXPECT_LE(error.hausdorff, bound * error.bbox_diagonal);
  EXPECT_LT(mesh.number_of_faces(), original.number_of_faces());
  EXPECT_EQ(outcome.stop_reason, cgal_policies::Stop_reason::error_bound_reached);
}

// The guarantee: in global mode, mesh_error's two-sided Hausdorff distance never exceeds the
// tolerance, smoothing off and bounded smoothing on. (The registry's "hausdorff" entry runs the
// same classes; property_test checks it like every policy.)
TEST(HausdorffBoundedPolicies, GlobalModeKeepsTheTwoSidedBoundOnRealMeshes) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name : {"bunny.obj", "fandisk.obj", "teapot.obj", "rocker-arm.obj"}) {
    const Mesh original = apps::read_triangle_mesh(test_meshes::data_file(name));
    for (const double tolerance : {0.001, 0.005, 0.01}) {
      cgal_policies::Hausdorff_bounded_options options;
      options.beta = tolerance;
      for (const bool smooth : {false, true}) {
        // Down to 5% of the faces, or as far as the tolerance allows: far enough that the
        // tighter tolerances stop the run, and short enough for a test.
        Mesh mesh = original;
        collapse_within(mesh, options, original.number_of_faces() / 20);
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

// Edge length and midpoints as far as they go, bounded or not.
template <typename Filter>
void collapse_shortest_edges(Mesh& mesh, const Filter& filter) {
  SMS::edge_collapse(mesh, cgal_policies::internal::Edge_count_stop_predicate<Mesh>(1),
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Mesh>())
                         .get_placement(SMS::Midpoint_placement<Mesh>())
                         .filter(filter));
  mesh.collect_garbage();
}

TEST(HausdorffBoundedFilterAlone, BoundsARunOfAnotherPolicy) {
  const double tolerance = 0.01;
  const Mesh original = test_meshes::bent_grid(8, 2.0);
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

// ---------------------------------------------------------------------------------------------
// The bound across the parts of a partitioned run (Simplification_pipeline; docs/scale.md): each
// part certified against itself as cut, in the whole's lengths, and the last pass against the
// mesh cut, not against the stitched parts.

TEST(BoundedPartitionedRun, ABoundOrTheHausdorffPolicyIsCutAsAnyOtherRun) {
  const std::size_t per_part = cgal_policies::Simplification_options::kFacesPerPart;
  cgal_policies::Simplification_options options;
  options.max_error = 0.01;
  EXPECT_EQ(options.cell_count(4 * per_part), 4u);
  EXPECT_EQ(options.cell_count(per_part), 1u);
  options.parts = 2;
  EXPECT_EQ(options.cell_count(1000), 2u);
  options.max_error = 0;
  options.policy = cgal_policies::Simplification_policy::hausdorff;
  EXPECT_EQ(options.cell_count(1000), 2u);
  options.on_collapse = [](CGAL::SM_Vertex_index, CGAL::SM_Vertex_index) {};
  EXPECT_EQ(options.cell_count(1000), 1u);  // the viewer's replay needs one mesh
}

// A mesh as text, its points to the last bit.
std::string mesh_text(const Mesh& mesh) {
  std::ostringstream out;
  out << std::setprecision(17) << mesh;
  return out.str();
}

// `input` simplified with `options` (a two-sided bound of `bound`) cut in four, on one thread and
// on two: the same mesh both times, returned; mesh_error's two-sided Hausdorff distance within the
// bound; valid, manifold and closed as the input; a quarter of its faces at most.
Mesh expect_bound_kept_in_four_parts(const Mesh& input,
                                     cgal_policies::Simplification_options options, double bound,
                                     std::size_t samples) {
  const apps::Mesh_validity before = apps::check_mesh_validity(input);
  options.parts = 4;
  std::string text[2];
  Mesh mesh;
  for (const std::size_t threads : {1, 2}) {
    options.threads = threads;
    mesh = input;
    const cgal_policies::Simplification_report report = apps::Pipeline(options).run(mesh);
    EXPECT_EQ(report.parts, 4u);
    EXPECT_EQ(report.bound, bound);
    const apps::Mesh_error error = apps::measure_mesh_error(input, mesh, samples);
    EXPECT_LE(error.hausdorff, bound * error.bbox_diagonal)
        << "Hausdorff " << error.hausdorff / error.bbox_diagonal << " of the diagonal";
    EXPECT_LE(mesh.number_of_faces(), input.number_of_faces() / 4);
    const apps::Mesh_validity after = apps::check_mesh_validity(mesh);
    EXPECT_TRUE(after.valid);
    EXPECT_EQ(after.non_manifold_vertices, 0u);
    EXPECT_EQ(after.closed, before.closed);
    EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
    text[threads - 1] = mesh_text(mesh);
  }
  EXPECT_TRUE(text[0] == text[1]) << "one thread and two gave different meshes";
  return mesh;
}

class BoundedPartitionedRun : public testing::TestWithParam<std::string> {};

// A sphere of 5,120 faces asked down to 50 within 0.5% of its diagonal: the bound stops the run.
TEST_P(BoundedPartitionedRun, KeepsTheBoundOnASphere) {
  SKIP_IF_TOO_SLOW_WHEN_SANITIZED();
  const double bound = 0.005;
  cgal_policies::Simplification_options options = pipeline_runs::policy_alone(GetParam(), 50);
  options.max_error = bound;
  Mesh sphere = test_meshes::loop_sphere(4);
  const Mesh out = expect_bound_kept_in_four_parts(sphere, options, bound, 20000);
  EXPECT_GT(out.number_of_faces(), 50u);
  options.parts = 4;
  EXPECT_EQ(apps::Pipeline(options).run(sphere).stop_reason,
            cgal_policies::Stop_reason::error_bound_reached);
}

// The bunny to 1% within 0.2% of its diagonal.
TEST_P(BoundedPartitionedRun, KeepsTheBoundOnTheBunny) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const double bound = 0.002;
  const Mesh bunny = apps::read_triangle_mesh(test_meshes::data_file("bunny.obj"));
  cgal_policies::Simplification_options options =
      pipeline_runs::policy_alone(GetParam(), bunny.number_of_faces() / 100);
  options.max_error = bound;
  expect_bound_kept_in_four_parts(bunny, options, bound, apps::kDefaultErrorSamples);
}

INSTANTIATE_TEST_SUITE_P(Policies, BoundedPartitionedRun,
                         testing::Values("lt", "classic", "hausdorff", "attributes"),
                         [](const auto& test) { return test.param; });

// The hausdorff policy's own tolerance, and the bounded fit after the parts (it runs whole).
TEST(BoundedPartitionedRunAndFit, KeepTheBoundOnASphere) {
  SKIP_IF_TOO_SLOW_WHEN_SANITIZED();
  const double bound = 0.005;
  for (const std::string policy : {"hausdorff", "lt"}) {
    SCOPED_TRACE(policy);
    cgal_policies::Simplification_options options = pipeline_runs::policy_alone(policy, 50);
    if (policy == "hausdorff")
      options.hausdorff.beta = bound;
    else
      options.max_error = bound;
    options.fit = true;
    expect_bound_kept_in_four_parts(test_meshes::loop_sphere(4), options, bound, 20000);
  }
}

// Cut, parts and stitch under a bound: the mesh of the run in memory, in one stage (the bounded
// fit runs whole, in the stitch), the bound kept.
TEST(BoundedPartitionedJob, GivesTheMeshOfTheRunInMemory) {
  SKIP_IF_TOO_SLOW_WHEN_SANITIZED();
  const double bound = 0.005;
  const Mesh sphere = test_meshes::loop_sphere(4);
  for (const bool fit : {false, true}) {
    for (const std::string policy : {"lt", "hausdorff"}) {
      SCOPED_TRACE(policy + (fit ? " + fit" : ""));
      cgal_policies::Simplification_options options = pipeline_runs::policy_alone(policy, 50);
      options.max_error = bound;
      options.fit = fit;
      options.parts = 4;
      Mesh in_memory = sphere;
      const cgal_policies::Simplification_report expected = apps::Pipeline(options).run(in_memory);
      const Job_folder folder(policy);
      Mesh mesh = sphere;
      cgal_policies::Simplification_report report;
      EXPECT_EQ(pipeline_runs::run_as_job(options, mesh, folder.path(), report), 1);
      EXPECT_EQ(report.parts, 4u);
      EXPECT_EQ(report.fitted, fit);
      EXPECT_EQ(report.stop_reason, expected.stop_reason);
      EXPECT_EQ(report.output_faces, expected.output_faces);
      EXPECT_TRUE(mesh_text(mesh) == mesh_text(in_memory))
          << "the job and the run in memory gave different meshes";
      const apps::Mesh_error error = apps::measure_mesh_error(sphere, mesh, 20000);
      EXPECT_LE(error.hausdorff, bound * error.bbox_diagonal);
    }
  }
}

}  // namespace
