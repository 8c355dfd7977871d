// simplify_curvature IN OUT RATIO: the curvature-weighted QEM of Zhang et al. (2009) alone, and
// the example of linking one of our policies into a plain CGAL pipeline: read, SMS::edge_collapse
// with CGAL's own stop predicate and our cost, placement and filter, write. `simplify --policy
// curvature` does the same with every option, progress, timing and measures.
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/Mesh_types.h"
#include "common/app_main.h"
#include "common/mesh_io.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <iostream>
#include <string>
#include <vector>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

// CGAL 5.5 stops on edge counts; on a closed triangle mesh the edge and face ratios are equal.
const char* const kUsage =
    "usage: simplify_curvature IN OUT RATIO (0 < RATIO <= 1, the fraction of edges kept)";

int run(int argc, char** argv) {
  const Command_line cli(argc, argv);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 3) throw App_error(exit_usage, kUsage);
  const double ratio = parse_number(args[2], "RATIO");
  if (!(ratio > 0 && ratio <= 1)) throw App_error(exit_usage, kUsage);
  check_output_path(args[0], args[1], false);

  Mesh mesh = read_triangle_mesh(args[0]);
  const std::size_t input_faces = mesh.number_of_faces();

  // Default parameters: eps = 1e-3, border weight 1000, unit face weights, flips refused at 90
  // degrees.
  const cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(mesh);
  const SMS::Count_ratio_stop_predicate<Mesh> stop(ratio);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>()));

  mesh.collect_garbage();
  write_mesh_atomically(mesh, args[1]);
  std::cout << args[0] << ": " << input_faces << " -> " << mesh.number_of_faces() << " faces\n";
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  return apps::guarded_main("simplify_curvature", [&] { return apps::run(argc, argv); });
}
