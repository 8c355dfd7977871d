// lt_then_fit IN OUT RATIO: CGAL's Lindstrom-Turk policy, then this library's two-sided fitting
// pass (Two_sided_fitter), which moves the output's vertices and flips its edges toward the input
// in both directions: the suite's lowest mean error (docs/fitting.md).
#include "example_files.h"

#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Two_sided_fitter.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args =
      example::arguments(argc, argv, "usage: lt_then_fit IN OUT RATIO (0 < RATIO <= 1)");
  Mesh mesh = example::read_mesh(args.input);
  const Mesh input = mesh;  // the fitter measures against it
  SMS::edge_collapse(
      mesh,
      cgal_policies::Face_count_stop_predicate<Mesh>(mesh, example::target_of(mesh, args.ratio)),
      CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
          .get_placement(SMS::LindstromTurk_placement<Mesh>()));
  mesh.collect_garbage();
  const cgal_policies::Two_sided_fit_report report =
      cgal_policies::Two_sided_fitter<Mesh>(input).fit(mesh);
  std::cout << mesh.number_of_faces() << " faces; fit: " << report.rounds << " rounds, "
            << report.moves << " moves, " << report.flips << " flips\n";
  example::write_mesh(mesh, args.output);
}
