// certified_bound IN OUT RATIO BOUND: any policy kept within a two-sided Hausdorff distance of its
// input. CGAL's Lindstrom-Turk policy proposes, Hausdorff_bounded_filter certifies each collapse
// against the input in both directions and refuses the ones that would leave BOUND (a fraction of
// the bounding-box diagonal): the run stops at RATIO or where no collapse keeps the bound.
#include "example_files.h"

#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Hausdorff_bounded_filter.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args = example::arguments(
      argc, argv, "usage: certified_bound IN OUT RATIO BOUND (0 < RATIO <= 1, BOUND > 0)");
  if (!(args.extra > 0)) {
    std::cerr << "certified_bound: BOUND must be above 0\n";
    return 2;
  }
  Mesh mesh = example::read_mesh(args.input);
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh,
                                                            example::target_of(mesh, args.ratio));
  SMS::edge_collapse(
      mesh, stop,
      CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
          .get_placement(SMS::LindstromTurk_placement<Mesh>())
          .filter(cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel>(mesh, args.extra)));
  std::cout << mesh.number_of_faces() << " faces ("
            << (stop.reason() ? "target reached" : "no collapse keeps the bound") << ")\n";
  example::write_mesh(mesh, args.output);
}
