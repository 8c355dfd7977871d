// simplify_fusion IN OUT RATIO: simplifies a mesh with Feature_fusion_policies and its default
// parameters, calling CGAL's edge_collapse directly: the smallest complete use of the policy.
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/app_main.h"
#include "common/edge_collapse_runner.h"
#include "common/mesh_io.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Feature_fusion_policies.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cmath>
#include <cstdio>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 3) throw App_error(exit_usage, "usage: simplify_fusion IN OUT RATIO");
  const double ratio = parse_number(args[2], "RATIO");
  if (!(ratio > 0 && ratio <= 1)) throw App_error(exit_usage, "the ratio must be in (0, 1]");
  check_output_path(args[0], args[1], false);

  Mesh mesh = read_triangle_mesh(args[0]);
  const std::size_t input_faces = mesh.number_of_faces();
  const cgal_policies::Feature_fusion_policies<Mesh, Kernel> policies(mesh);
  // The same face-count stop as simplify, so that RATIO means the same in both apps.
  const std::size_t target = std::size_t(std::llround(ratio * double(input_faces)));
  SMS::edge_collapse(mesh, Face_count_stop_predicate(mesh, target),
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>()));
  mesh.collect_garbage();
  write_mesh_atomically(mesh, args[1]);
  std::printf("%zu -> %zu faces\n", input_faces, std::size_t(mesh.number_of_faces()));
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  return apps::guarded_main("simplify_fusion", [&] { return apps::run(argc, argv); });
}
