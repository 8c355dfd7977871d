// simplify_hausdorff IN OUT RATIO [BETA]: the Hausdorff-bounded simplification of Liu et al.
// (2017) alone, linked into a plain CGAL pipeline: read, SMS::edge_collapse with a face-count stop
// and our cost, placement and filter, write. It stops at RATIO of the faces, or earlier when no
// collapse keeps the output within BETA * D of the input (default 0.005, D the bounding-box
// diagonal). `simplify --policy hausdorff` does the same with every option, progress and measures.
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/Mesh_types.h"
#include "common/app_main.h"
#include "common/edge_collapse_runner.h"
#include "common/mesh_io.h"

#include <cgal_policies/Hausdorff_bounded_policies.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

const char* const kUsage =
    "usage: simplify_hausdorff IN OUT RATIO [BETA] (0 < RATIO <= 1, the fraction of faces kept; "
    "BETA > 0 the tolerance, a fraction of the bounding-box diagonal, default 0.005)";

int run(int argc, char** argv) {
  const Command_line cli(argc, argv);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 3 && args.size() != 4) throw App_error(exit_usage, kUsage);
  const double ratio = parse_number(args[2], "RATIO");
  const double beta = args.size() == 4 ? parse_number(args[3], "BETA") : 0.005;
  if (!(ratio > 0 && ratio <= 1) || !(beta > 0)) throw App_error(exit_usage, kUsage);
  check_output_path(args[0], args[1], false);

  Mesh mesh = read_triangle_mesh(args[0]);
  const std::size_t input_faces = mesh.number_of_faces();
  const std::size_t target = std::size_t(std::llround(ratio * double(input_faces)));

  cgal_policies::Hausdorff_bounded_options options;
  options.beta = beta;
  const cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> hausdorff(mesh, options);
  SMS::edge_collapse(mesh, Face_count_stop_predicate(mesh, target),
                     CGAL::parameters::get_cost(hausdorff.get_cost())
                         .get_placement(hausdorff.get_placement())
                         .filter(hausdorff.get_filter()));

  mesh.collect_garbage();
  write_mesh_atomically(mesh, args[1]);
  std::cout << args[0] << ": " << input_faces << " -> " << mesh.number_of_faces() << " faces ("
            << (mesh.number_of_faces() <= target ? "target reached" : "tolerance reached")
            << ", tolerance " << hausdorff.tolerance() << ")\n";
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  return apps::guarded_main("simplify_hausdorff", [&] { return apps::run(argc, argv); });
}
