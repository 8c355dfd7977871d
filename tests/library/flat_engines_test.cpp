// The flat-array engines: Fast_threshold_simplifier (docs/fast.md) and
// Flat_lindstrom_turk_simplifier (docs/flat_lt.md). Exact results on tiny meshes; on every shipped
// mesh a valid manifold output, fast's near gh's error and flat-lt's at CGAL's LindstromTurk's.
#include "pipeline_runs.h"
#include "test_meshes.h"

#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cgal_policies/Fast_threshold_simplifier.h>
#include <cgal_policies/Flat_lindstrom_turk_simplifier.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using cgal_policies::Fast_threshold_simplifier;
using test_meshes::data_file;
using test_meshes::Mesh;
using test_meshes::Point;
using test_meshes::sorted_points;

cgal_policies::Fast_threshold_options lossless() {
  cgal_policies::Fast_threshold_options options;
  options.lossless = true;
  return options;
}

cgal_policies::Fast_threshold_options any_normal_turn() {
  cgal_policies::Fast_threshold_options options;
  options.max_normal_angle_deg = 180;
  return options;
}

const std::vector<Point> kGridCorners = {Point(0, 0, 0), Point(0, 8, 0), Point(8, 0, 0),
                                         Point(8, 8, 0)};

TEST(FastThresholdSimplifier, LosslessFlatGridCollapsesToItsCornerTriangles) {
  Mesh mesh = test_meshes::flat_grid(8);
  const auto report = Fast_threshold_simplifier(lossless())(mesh, 1);
  EXPECT_FALSE(report.target_reached);  // a single triangle would cost area
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(sorted_points(mesh), kGridCorners);
}

TEST(FastThresholdSimplifier, FlatGridReachesTwoFacesOnItsCorners) {
  Mesh mesh = test_meshes::flat_grid(8);
  const auto report = Fast_threshold_simplifier()(mesh, 2);
  EXPECT_TRUE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(sorted_points(mesh), kGridCorners);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

TEST(FastThresholdSimplifier, TetrahedronStaysATetrahedron) {
  Mesh mesh = test_meshes::tetrahedron();
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Fast_threshold_simplifier(any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(sorted_points(mesh), before);
}

TEST(FastThresholdSimplifier, IcosahedronCollapsedFullyEndsAsATetrahedron) {
  Mesh mesh = test_meshes::icosahedron();
  const auto report = Fast_threshold_simplifier(any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
}

TEST(FastThresholdSimplifier, LosslessModeKeepsACurvedSurface) {
  Mesh mesh = test_meshes::icosahedron();
  const std::vector<Point> before = sorted_points(mesh);
  static_cast<void>(Fast_threshold_simplifier(lossless())(mesh, 1));
  EXPECT_EQ(mesh.number_of_faces(), 20u);
  EXPECT_EQ(sorted_points(mesh), before);
}

// Twice the area over the squared longest edge of the thinnest face (sqrt(3)/2 when equilateral).
double thinnest_face_shape(const Mesh& mesh) {
  double thinnest = 1;
  for (auto f : mesh.faces()) {
    std::vector<Point> p;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
    const double longest =
        (std::max)({CGAL::squared_distance(p[0], p[1]), CGAL::squared_distance(p[1], p[2]),
                    CGAL::squared_distance(p[2], p[0])});
    const double twice_area =
        std::sqrt(CGAL::cross_product(p[1] - p[0], p[2] - p[0]).squared_length());
    thinnest = (std::min)(thinnest, twice_area / longest);
  }
  return thinnest;
}

// A flat hexagon fan whose centre was split into three coincident vertices a, b, c: four of its
// ten faces have zero area, as the reader's repairs leave them on dragon.ply. Every edge between
// a, b and c costs nothing; the old flip test refused to move a vertex of a face that was already
// degenerate, so the faces stayed. Two collapses give back the clean six-face fan, its points
// those of the input up to round-off: a border vertex goes to its quadric's best point, which a
// solve finds within a few ulps.
TEST(FastThresholdSimplifier, RemovesTheDegenerateFacesOfTheInput) {
  std::vector<Point> points;
  for (int i = 0; i < 6; ++i)
    points.emplace_back(2 * std::cos(i * CGAL_PI / 3), 2 * std::sin(i * CGAL_PI / 3), 0);
  points.insert(points.end(), 3, Point(0, 0, 0));
  const int a = 6, b = 7, c = 8;
  Mesh mesh = test_meshes::from_triangles(points, {{a, b, c},
                                                   {a, 0, 1},
                                                   {a, 1, b},
                                                   {b, 1, 2},
                                                   {b, 2, 3},
                                                   {b, 3, c},
                                                   {c, 3, 4},
                                                   {c, 4, 5},
                                                   {c, 5, a},
                                                   {a, 5, 0}});
  ASSERT_EQ(test_meshes::degenerate_face_count(mesh), 4u);
  const auto report = Fast_threshold_simplifier()(mesh, 6);
  EXPECT_TRUE(report.target_reached);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 6u);
  EXPECT_EQ(test_meshes::degenerate_face_count(mesh), 0u);
  std::vector<Point> expected(points.begin(), points.begin() + 7);
  std::sort(expected.begin(), expected.end());
  const std::vector<Point> output = sorted_points(mesh);
  ASSERT_EQ(output.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT(CGAL::squared_distance(output[i], expected[i]), 1e-24) << i;
}

// A flat fan around v = (1, 0.5): all four collapses of v onto a border vertex cost nothing. The
// first one tried (face (b, x, v) is read from v, so edge (v, b) comes first), onto b = (0, 0),
// would turn face (v, x, y) into the sliver (b, x, y) of shape 5e-7 without turning its normal;
// it is refused, and v goes to x instead.
TEST(FastThresholdSimplifier, RefusesACollapseThatMakesASliver) {
  Mesh mesh = test_meshes::from_triangles(
      {Point(1, 0.5, 0), Point(0, 0, 0), Point(1, -1e-6, 0), Point(2, 0, 0), Point(1, 2, 0)},
      {{1, 2, 0}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
  const auto report = Fast_threshold_simplifier()(mesh, 2);
  EXPECT_TRUE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_GT(thinnest_face_shape(mesh), 0.1);
  EXPECT_EQ(sorted_points(mesh), (std::vector<Point>{Point(0, 0, 0), Point(1, -1e-6, 0),
                                                     Point(1, 2, 0), Point(2, 0, 0)}));
}

// Scaling by a power of two is exact in floating point, so a scale-invariant schedule must give
// the same collapses, exactly scaled: with unit weights, and with the planes weighted by area,
// whose errors (an area times a squared distance) the thresholds would otherwise meet at another
// pass for each scale (at 2^20 the bunny took 30 passes instead of 16).
TEST(FastThresholdSimplifier, IsScaleInvariant) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  constexpr double kScale = 1 << 20;
  const Mesh input = test_meshes::read_clean_mesh("bunny.obj");
  const std::size_t target = input.number_of_faces() / 10;
  for (const auto weighting :
       {cgal_policies::Face_weighting::area, cgal_policies::Face_weighting::unit}) {
    cgal_policies::Fast_threshold_options options;
    options.face_weighting = weighting;
    Mesh mesh = input;
    Mesh scaled = input;
    for (auto v : scaled.vertices()) {
      const Point& p = scaled.point(v);
      scaled.point(v) = Point(kScale * p.x(), kScale * p.y(), kScale * p.z());
    }
    const Fast_threshold_simplifier simplify(options);
    simplify(mesh, target);
    simplify(scaled, target);
    ASSERT_EQ(mesh.number_of_faces(), scaled.number_of_faces());
    std::vector<Point> expected;
    for (const Point& p : sorted_points(mesh))
      expected.emplace_back(kScale * p.x(), kScale * p.y(), kScale * p.z());
    EXPECT_EQ(sorted_points(scaled), expected);
  }
}

// A gentle schedule (small a) jumps its idle passes to indexes past 2^53, where one pass more is
// the same double: the search for the pass whose threshold exceeds the waiting errors once looped
// there for ever (fandisk and the cow at a = 0.05 and 0.12; found by the policy fuzzer).
TEST(FastThresholdSimplifier, GentleScheduleEndsPastTheExactPassIndexes) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  Mesh mesh = test_meshes::read_clean_mesh("fandisk.obj");
  cgal_policies::Fast_threshold_options options;
  options.aggressiveness = 0.12;
  const std::size_t target = mesh.number_of_faces() / 10;
  EXPECT_TRUE(Fast_threshold_simplifier(options)(mesh, target).target_reached);
  EXPECT_LE(mesh.number_of_faces(), target);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

// The report's method has no link condition; ours must never output a non-manifold mesh, nor a
// face of zero area.
TEST(FastThresholdSimplifier, OutputIsAValidManifoldOnEveryShippedMesh) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name :
       {"bunny.obj", "fandisk.obj", "cow.obj", "rocker-arm.obj", "teapot.obj", "nefertiti.obj",
        "spot.obj", "alligator.obj", "woody.obj", "dragon_res2.ply", "dragon.ply"}) {
    SCOPED_TRACE(name);
    Mesh mesh = apps::read_triangle_mesh(data_file(name));
    const apps::Mesh_validity input = apps::check_mesh_validity(mesh);
    for (double ratio : {0.1, 0.01}) {
      SCOPED_TRACE(ratio);
      Mesh simplified = mesh;
      cgal_policies::Fast_threshold_simplifier()(
          simplified, std::size_t(std::llround(ratio * double(input.faces))));
      const apps::Mesh_validity output = apps::check_mesh_validity(simplified);
      EXPECT_TRUE(output.valid);
      EXPECT_EQ(output.non_manifold_vertices, 0u);
      EXPECT_EQ(output.degenerate_faces, 0u);  // dragon.ply has 108 on input
      EXPECT_EQ(output.closed, input.closed);
      EXPECT_EQ(output.euler_characteristic, input.euler_characteristic);
      EXPECT_LT(output.faces, input.faces);
    }
  }
}

// A shipped mesh and the face count at a ratio of its faces.
struct Shipped_target {
  Mesh input;
  std::size_t target;
};

Shipped_target shipped_target(const char* file, double ratio) {
  Mesh input = apps::read_triangle_mesh(data_file(file));
  const std::size_t target = std::size_t(std::llround(ratio * double(input.number_of_faces())));
  return {std::move(input), target};
}

// The errors (50,000 samples a direction) of the fast method with `options`, and of gh, taken to
// the target, which each must reach.
apps::Mesh_error fast_error(const Shipped_target& run,
                            const cgal_policies::Fast_threshold_options& options = {}) {
  Mesh fast = run.input;
  EXPECT_TRUE(cgal_policies::Fast_threshold_simplifier(options)(fast, run.target).target_reached);
  return apps::measure_mesh_error(run.input, fast, 50000);
}

apps::Mesh_error gh_error(const Shipped_target& run) {
  Mesh gh = run.input;
  EXPECT_EQ(pipeline_runs::simplify(gh, "gh", run.target).stop_reason,
            cgal_policies::Stop_reason::target_reached);
  return apps::measure_mesh_error(run.input, gh, 50000);
}

struct Fast_and_gh_errors {
  apps::Mesh_error fast, gh;
};

Fast_and_gh_errors fast_and_gh_errors(const char* file, double ratio) {
  const Shipped_target run = shipped_target(file, ratio);
  return {fast_error(run), gh_error(run)};
}

// The papers' lowest count: dragon.ply (hundreds of tiny holes) to 0.25%. Both reach the target;
// the fast method's mean two-sided error is about gh's and its Hausdorff distance within 2x. The
// sliver rule brought the mean from 6.5x to 1.65x, the border rule and weight from 1.55x to about
// 1x and the Hausdorff distance from 2.1x to about 1.6x (docs/fast.md).
TEST(FastThresholdSimplifier, HasAboutGhsErrorOnDragonAtAQuarterPercent) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Fast_and_gh_errors errors = fast_and_gh_errors("dragon.ply", 0.0025);
  EXPECT_LT(errors.fast.mean(), 1.05 * errors.gh.mean());
  EXPECT_LT(errors.fast.hausdorff, 2 * errors.gh.hausdorff);
}

// The bunny, whose base has five holes, at 1%: near gh's mean two-sided error, 1.16x with the
// merged vertex pinned to a border end and the border planes at 1000 (docs/fast.md).
TEST(FastThresholdSimplifier, KeepsNearGhsErrorAroundTheBunnysHoles) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Fast_and_gh_errors errors = fast_and_gh_errors("bunny.obj", 0.01);
  EXPECT_LT(errors.fast.mean(), 1.08 * errors.gh.mean());
}

// At 1% of dragon_res2.ply the fast method has gh's mean two-sided error, which the level cap at
// 20% of the open triangles brought (the 40% it had before misses it; docs/fast.md).
TEST(FastThresholdSimplifier, HasGhsErrorOnDragonRes2AtOnePercent) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Fast_and_gh_errors errors = fast_and_gh_errors("dragon_res2.ply", 0.01);
  EXPECT_LT(errors.fast.mean(), 1.02 * errors.gh.mean());
}

// nefertiti.obj, whose triangles vary much in size, at 1%: with its planes weighted by area the
// fast method has well below gh's mean two-sided error; with unit weights, about gh's
// (docs/fast.md, "Planes weighted by area").
TEST(FastThresholdSimplifier, WeightedByAreaBeatsGhOnNefertitiAtOnePercent) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Shipped_target nefertiti = shipped_target("nefertiti.obj", 0.01);
  const double gh = gh_error(nefertiti).mean();
  EXPECT_LT(fast_error(nefertiti).mean(), 0.85 * gh);
  cgal_policies::Fast_threshold_options unit_weights;
  unit_weights.face_weighting = cgal_policies::Face_weighting::unit;
  EXPECT_GT(fast_error(nefertiti, unit_weights).mean(), 0.95 * gh);
}

using cgal_policies::Flat_lindstrom_turk_simplifier;

cgal_policies::Flat_lindstrom_turk_options lt_any_normal_turn() {
  cgal_policies::Flat_lindstrom_turk_options options;
  options.max_normal_angle_deg = 180;
  return options;
}

TEST(FlatLindstromTurk, TetrahedronStaysATetrahedron) {
  Mesh mesh = test_meshes::tetrahedron();
  const std::vector<Point> before = sorted_points(mesh);
  const auto report = Flat_lindstrom_turk_simplifier(lt_any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_EQ(report.collapses, 0u);
  EXPECT_EQ(sorted_points(mesh), before);
}

TEST(FlatLindstromTurk, IcosahedronCollapsedFullyEndsAsATetrahedron) {
  Mesh mesh = test_meshes::icosahedron();
  const auto report = Flat_lindstrom_turk_simplifier(lt_any_normal_turn())(mesh, 1);
  EXPECT_FALSE(report.target_reached);
  EXPECT_EQ(report.collapses, 8u);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(mesh.number_of_faces(), 4u);
}

// The border preservation of [LT98] keeps the grid's outline: its corners stay where they are.
TEST(FlatLindstromTurk, FlatGridReachesTwoFacesOnItsCorners) {
  Mesh mesh = test_meshes::flat_grid(8);
  const auto report = Flat_lindstrom_turk_simplifier()(mesh, 2);
  EXPECT_TRUE(report.target_reached);
  EXPECT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(sorted_points(mesh), kGridCorners);
}

// A sphere with its vertices moved off it by a fixed pseudo-random amount, so that no two edges
// cost the same: each collapse is then the same as CGAL's LindstromTurk policies choose, at the
// same point up to the order of the sums.
Mesh bumpy_sphere() {
  Mesh mesh = test_meshes::loop_sphere(2);
  std::uint32_t state = 12345;
  for (auto v : mesh.vertices()) {
    state = state * 1664525u + 1013904223u;
    const double scale = 1 + 0.05 * (double(state >> 8) / double(1u << 24) - 0.5);
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(scale * p.x(), scale * p.y(), scale * p.z());
  }
  return mesh;
}

TEST(FlatLindstromTurk, CollapsesTheEdgesCgalsLindstromTurkCollapsesAtTheSamePoints) {
  const Mesh input = bumpy_sphere();
  for (const std::size_t target : {300u, 200u, 100u}) {
    SCOPED_TRACE(target);
    Mesh cgal_lt = input;
    Mesh flat_lt = input;
    ASSERT_EQ(pipeline_runs::simplify(cgal_lt, "lt", target).stop_reason,
              cgal_policies::Stop_reason::target_reached);
    ASSERT_TRUE(Flat_lindstrom_turk_simplifier()(flat_lt, target).target_reached);
    const std::vector<Point> expected = sorted_points(cgal_lt), got = sorted_points(flat_lt);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i)
      EXPECT_LT(CGAL::squared_distance(got[i], expected[i]), 1e-20) << i;
  }
}

TEST(FlatLindstromTurk, StopsWhenInterrupted) {
  Mesh mesh = test_meshes::loop_sphere(5);  // 20480 faces: more than one poll period of collapses
  int polls = 0;
  const auto report =
      Flat_lindstrom_turk_simplifier()(mesh, 10, {}, [&polls] { return ++polls == 1; });
  EXPECT_TRUE(report.interrupted);
  EXPECT_FALSE(report.target_reached);
  EXPECT_EQ(polls, 1);
  EXPECT_EQ(report.collapses, 4096u);
  EXPECT_EQ(mesh.number_of_faces(), 20480u - 2 * 4096u);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

// flat-lt beside CGAL's lt on shipped meshes, each run alone: a valid manifold output of the same
// topology and a mean two-sided error within 5% of lt's on each mesh and ratio (measured
// 0.95-1.03x; docs/flat_lt.md).
TEST(FlatLindstromTurk, KeepsLindstromTurksErrorOnShippedMeshes) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name : {"bunny.obj", "fandisk.obj", "nefertiti.obj", "rocker-arm.obj"}) {
    SCOPED_TRACE(name);
    const Mesh input = apps::read_triangle_mesh(data_file(name));
    const apps::Mesh_validity before = apps::check_mesh_validity(input);
    for (double ratio : {0.1, 0.01}) {
      SCOPED_TRACE(ratio);
      const std::size_t target = std::size_t(std::llround(ratio * double(before.faces)));
      Mesh cgal_lt = input;
      Mesh flat_lt = input;
      pipeline_runs::simplify(cgal_lt, "lt", target);
      EXPECT_EQ(pipeline_runs::simplify(flat_lt, "flat-lt", target).stop_reason,
                cgal_policies::Stop_reason::target_reached);
      const apps::Mesh_validity after = apps::check_mesh_validity(flat_lt);
      EXPECT_TRUE(after.valid);
      EXPECT_EQ(after.non_manifold_vertices, 0u);
      EXPECT_EQ(after.closed, before.closed);
      EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
      const apps::Mesh_error lt_error = apps::measure_mesh_error(input, cgal_lt, 50000);
      const apps::Mesh_error flat_error = apps::measure_mesh_error(input, flat_lt, 50000);
      EXPECT_LT(flat_error.mean() / flat_error.bbox_diagonal,
                1.05 * (lt_error.mean() / lt_error.bbox_diagonal));
    }
  }
}

}  // namespace
