// policy_with_filter IN OUT RATIO: one of this library's policies in a plain CGAL pipeline, with a
// filter of its own: Classic_quadric_policies (area-weighted face planes) under
// Bounded_normal_angle_filter at 60 degrees, stopped by Face_count_stop_predicate.
#include "example_files.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Face_count_stop_predicate.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args =
      example::arguments(argc, argv, "usage: policy_with_filter IN OUT RATIO (0 < RATIO <= 1)");
  Mesh mesh = example::read_mesh(args.input);
  cgal_policies::Quadric_options options;  // border weight 1000
  options.face_weighting = cgal_policies::Face_weighting::area;
  const cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh, options);
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh,
                                                            example::target_of(mesh, args.ratio));
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>(60.0)));
  std::cout << mesh.number_of_faces() << " faces ("
            << cgal_policies::to_string(
                   stop.reason().value_or(cgal_policies::Stop_reason::no_collapse_left))
            << ")\n";
  example::write_mesh(mesh, args.output);
}
