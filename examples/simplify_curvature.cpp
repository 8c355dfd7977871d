// simplify_curvature IN OUT RATIO: the curvature-weighted QEM of Zhang et al. (2009) alone, linked
// into a plain CGAL pipeline: read, SMS::edge_collapse with CGAL's own stop predicate and our cost,
// placement and filter, write. `simplify --policy curvature` does the same with every option,
// progress, timing and measures.
#include "example_files.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  // CGAL 5.5 stops on edge counts; on a closed triangle mesh the edge and face ratios are equal.
  const example::Arguments args = example::arguments(
      argc, argv, "usage: simplify_curvature IN OUT RATIO (0 < RATIO <= 1, the edges kept)");
  Mesh mesh = example::read_mesh(args.input);
  // Default parameters: eps = 1e-3, border weight 1000, unit face weights; flips refused at 90
  // degrees.
  const cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(mesh);
  SMS::edge_collapse(mesh, SMS::Count_ratio_stop_predicate<Mesh>(args.ratio),
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>()));
  std::cout << mesh.number_of_faces() << " faces\n";
  example::write_mesh(mesh, args.output);
}
