// The Hausdorff bounds of docs/hausdorff.md, checked by mesh_error's measure
// (apps::measure_mesh_error): Hausdorff_bounded_policies in local mode drifts while global mode
// keeps the two-sided bound, on a cylinder band and on real meshes; Hausdorff_bounded_filter
// bounds a run of another policy; Hausdorff_move_guard bounds Laplacian_smoother. The exact cases
// with the library alone are in hausdorff_policy_test.cpp.
#include "common/edge_collapse_runner.h"
#include "common/fitting.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/policy_registry.h"
#include "test_meshes.h"

#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Hausdorff_move_guard.h>
#include <cgal_policies/Laplacian_smoother.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using test_meshes::Kernel;
using test_meshes::Mesh;
using test_meshes::Point;
using Policies = cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel>;
using Alone_filter = cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel>;

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
  cgal_policies::Hausdorff_bounded_options options;
  options.beta = beta;
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

// The registry's hausdorff entry in local mode: its tolerance is no two-sided bound (the run
// above goes past it), so the app claims none, and --max-error is kept by the runner's filter.
// Before, local mode with --max-error took the tighter tolerance as its only check and went past
// the bound the user asked for.
TEST(HausdorffBoundedPolicies, LocalModeKeepsMaxErrorThroughTheRunnersFilter) {
  const double bound = 0.01;
  const apps::Policy_entry& hausdorff = *apps::find_policy("hausdorff");
  apps::Simplify_settings settings = apps::default_settings(hausdorff, 2);
  settings.options["local"] = 1;
  settings.options["tolerance"] = bound;
  EXPECT_EQ(apps::two_sided_bound(hausdorff, settings), 0.0);
  settings.max_error = bound;
  EXPECT_EQ(apps::two_sided_bound(hausdorff, settings), bound);
  Mesh mesh = cylinder_band(64);
  const Mesh original = mesh;
  const apps::Simplify_outcome outcome = hausdorff.run(mesh, settings);
  mesh.collect_garbage();
  const apps::Mesh_error error = apps::measure_mesh_error(original, mesh, 20000);
  EXPECT_LE(error.hausdorff, bound * error.bbox_diagonal);
  EXPECT_LT(mesh.number_of_faces(), original.number_of_faces());
  EXPECT_EQ(outcome.stop_reason, apps::Stop_reason::error_bound_reached);
}

// `original` simplified by the Hausdorff-bounded policies toward `target` faces.
Mesh simplified_within(const Mesh& original,
                       const cgal_policies::Hausdorff_bounded_options& options,
                       std::size_t target) {
  Mesh mesh = original;
  {
    const Policies policy(mesh, options);
    apps::Simplify_settings settings;
    settings.target_faces = target;
    apps::run_edge_collapse(mesh, settings, policy.get_cost(), policy.get_placement(),
                            policy.get_filter());
  }
  mesh.collect_garbage();
  return mesh;
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
        Mesh mesh = simplified_within(original, options, original.number_of_faces() / 20);
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

// The fitting pass in bounded mode (docs/fitting.md): the bound the simplification kept holds after
// the pass too, by the evaluator, and the mean error drops.
TEST(TwoSidedFitter, BoundedModeKeepsTheBoundOfTheRun) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  for (const std::string name : {"bunny.obj", "fandisk.obj", "teapot.obj", "cow.obj"}) {
    const Mesh original = apps::read_triangle_mesh(test_meshes::data_file(name));
    const double tolerance = 0.005;
    cgal_policies::Hausdorff_bounded_options options;
    options.beta = tolerance;
    Mesh mesh = simplified_within(original, options, original.number_of_faces() / 100);
    const apps::Mesh_error before = apps::measure_mesh_error(original, mesh);
    const apps::Fit_outcome fit = apps::fit_to_input(mesh, original, 4, 90, tolerance);
    EXPECT_GT(fit.report.moves, 0u) << name;
    const apps::Mesh_error after = apps::measure_mesh_error(original, mesh);
    EXPECT_LE(after.hausdorff, tolerance * after.bbox_diagonal)
        << name << ": Hausdorff " << after.hausdorff / after.bbox_diagonal;
    EXPECT_LT(after.mean_a_to_b + after.mean_b_to_a, before.mean_a_to_b + before.mean_b_to_a)
        << name;
    EXPECT_TRUE(apps::check_mesh_validity(mesh).valid) << name;
  }
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
