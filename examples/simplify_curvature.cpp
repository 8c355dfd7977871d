// simplify_curvature IN OUT RATIO: the curvature-weighted QEM of Zhang et al. (2009) alone, linked
// into a plain CGAL pipeline: read, SMS::edge_collapse with our cost, placement, filter and
// face-count stop predicate (CGAL's own count edges, and were renamed in 6.0), write. `simplify
// --policy curvature` does the same with every option, progress, timing and measures.
#include "example_files.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>
#include <cgal_policies/Face_count_stop_predicate.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args = example::arguments(
      argc, argv, "usage: simplify_curvature IN OUT RATIO (0 < RATIO <= 1, the faces kept)");
  Mesh mesh = example::read_mesh(args.input);
  // Default parameters: eps = 1e-3, border weight 1000, unit face weights; flips refused at 90
  // degrees.
  const cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(mesh);
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh,
                                                            example::target_of(mesh, args.ratio));
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>()));
  std::cout << mesh.number_of_faces() << " faces\n";
  example::write_mesh(mesh, args.output);
}
