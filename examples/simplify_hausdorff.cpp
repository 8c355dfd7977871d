// simplify_hausdorff IN OUT RATIO [BETA]: the Hausdorff-bounded simplification of Liu et al.
// (2017) alone, linked into a plain CGAL pipeline: read, SMS::edge_collapse with a face-count stop
// and our cost, placement and filter, write. It stops at RATIO of the faces, or earlier when no
// collapse keeps the output within BETA * D of the input (default 0.005, D the bounding-box
// diagonal). `simplify --policy hausdorff` does the same with every option, progress and measures.
#include "example_files.h"

#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args = example::arguments(
      argc, argv, "usage: simplify_hausdorff IN OUT RATIO [BETA] (0 < RATIO <= 1, BETA > 0)");
  Mesh mesh = example::read_mesh(args.input);
  cgal_policies::Hausdorff_bounded_options options;
  if (args.extra > 0) options.beta = args.extra;
  const cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> hausdorff(mesh, options);
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh,
                                                            example::target_of(mesh, args.ratio));
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(hausdorff.get_cost())
                         .get_placement(hausdorff.get_placement())
                         .filter(hausdorff.get_filter()));
  std::cout << mesh.number_of_faces() << " faces ("
            << (stop.reason() ? "target reached" : "tolerance reached") << ", tolerance "
            << hausdorff.tolerance() << ")\n";
  example::write_mesh(mesh, args.output);
}
