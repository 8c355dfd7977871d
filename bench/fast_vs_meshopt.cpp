// fast_vs_meshopt MESH... [--ratio R] [--repeat N] [--samples N]: the fast threshold QEM against
// CGAL's Garland-Heckbert policy (gh) and meshoptimizer's meshopt_simplify, in one run, on the
// same meshes and face targets (docs/evaluation.md: ratios measured in the same run, minimum time
// of N repetitions, two-sided errors by mesh_error's measure).
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/app_main.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/policy_registry.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <vector>

namespace apps {
namespace {

struct Result {
  double seconds = std::numeric_limits<double>::infinity();
  Mesh mesh;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Result run_policy(const std::string& name, const Mesh& input, std::size_t target, int repeat) {
  Result result;
  const Policy_entry& policy = *find_policy(name);
  for (int r = 0; r < repeat; ++r) {
    Mesh mesh = input;
    const Simplify_outcome outcome = policy.run(mesh, default_settings(policy, target));
    mesh.collect_garbage();
    if (outcome.seconds < result.seconds) result = {outcome.seconds, std::move(mesh)};
  }
  return result;
}

// Timed: the copy to meshoptimizer's buffers and meshopt_simplify (as the fast policy's time
// includes its copies to and from arrays). Not timed: rebuilding a Surface_mesh from its output,
// which needs soup repairs because meshopt_simplify does not keep a manifold.
Result run_meshopt(const Mesh& input, std::size_t target, int repeat) {
  Result result;
  std::vector<unsigned> kept;
  std::vector<float> positions;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    positions.clear();
    for (auto v : input.vertices())
      for (int i = 0; i < 3; ++i) positions.push_back(float(input.point(v)[i]));
    std::vector<unsigned> indices;
    for (auto f : input.faces())
      for (auto v : CGAL::vertices_around_face(input.halfedge(f), input)) indices.push_back(v);
    kept.resize(indices.size());
    kept.resize(meshopt_simplify(kept.data(), indices.data(), indices.size(), positions.data(),
                                 input.number_of_vertices(), 3 * sizeof(float), 3 * target,
                                 /*target_error=*/1.0f, /*options=*/0, nullptr));
    result.seconds = std::min(result.seconds, seconds_since(start));
  }
  // Only the vertices meshopt_simplify kept: the soup repairs are slow on unused points.
  std::vector<Point> points;
  std::vector<std::size_t> renumbered(input.number_of_vertices(), std::size_t(-1));
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t i = 0; i < kept.size(); i += 3) {
    std::array<std::size_t, 3> triangle;
    for (int j = 0; j < 3; ++j) {
      std::size_t& id = renumbered[kept[i + j]];
      if (id == std::size_t(-1)) {
        id = points.size();
        const float* p = &positions[3 * std::size_t(kept[i + j])];
        points.emplace_back(p[0], p[1], p[2]);
      }
      triangle[j] = id;
    }
    triangles.push_back(triangle);
  }
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::repair_polygon_soup(points, triangles);
  PMP::orient_polygon_soup(points, triangles);
  PMP::polygon_soup_to_polygon_mesh(points, triangles, result.mesh);
  return result;
}

double mean_two_sided(const Mesh_error& e) { return 0.5 * (e.mean_a_to_b + e.mean_b_to_a); }

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  const double ratio = cli.take_number("ratio").value_or(0.01);
  const int repeat = int(cli.take_number("repeat").value_or(3));
  const std::size_t samples =
      std::size_t(cli.take_number("samples").value_or(kDefaultErrorSamples));
  const std::vector<std::string> meshes = cli.positionals();
  if (meshes.empty() || !(ratio > 0 && ratio <= 1) || repeat < 1)
    throw App_error(exit_usage,
                    "usage: fast_vs_meshopt MESH... [--ratio R] [--repeat N] [--samples N]");

  std::printf("%-16s %-8s %9s %9s %10s %12s %10s\n", "mesh", "method", "faces", "seconds",
              "time/gh", "mean2_%diag", "err/gh");
  for (const std::string& path : meshes) {
    const Mesh input = read_triangle_mesh(path);
    const std::size_t target = std::size_t(std::llround(ratio * double(input.number_of_faces())));
    std::vector<Result> results;
    results.push_back(run_policy("gh", input, target, repeat));
    results.push_back(run_policy("fast", input, target, repeat));
    results.push_back(run_meshopt(input, target, repeat));
    // meshopt_simplify may stop short of the target: compare errors at its face count too.
    results.push_back(run_policy("fast", input, results[2].mesh.number_of_faces(), repeat));
    const char* names[] = {"gh", "fast", "meshopt", "fast@mo"};
    double errors[4];
    for (int m = 0; m < 4; ++m) {
      const Mesh_error error = measure_mesh_error(input, results[m].mesh, samples);
      errors[m] = mean_two_sided(error);
      const Mesh_validity validity = check_mesh_validity(results[m].mesh);
      std::printf("%-16s %-8s %9zu %9.3f %10.3f %12.5f %10.3f  hausdorff %.4f%% %s nm=%zu\n",
                  path.substr(path.find_last_of('/') + 1).c_str(), names[m],
                  std::size_t(results[m].mesh.number_of_faces()), results[m].seconds,
                  results[m].seconds / results[0].seconds, 100 * errors[m] / error.bbox_diagonal,
                  errors[m] / errors[0], 100 * error.hausdorff / error.bbox_diagonal,
                  validity.valid ? "valid" : "INVALID", validity.non_manifold_vertices);
    }
    std::printf("%-16s fast/meshopt at meshopt's face count: time %.3fx, mean error %.3fx\n",
                path.substr(path.find_last_of('/') + 1).c_str(),
                results[3].seconds / results[2].seconds, errors[3] / errors[2]);
    std::fflush(stdout);
  }
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  return apps::guarded_main("fast_vs_meshopt", [&] { return apps::run(argc, argv); });
}
