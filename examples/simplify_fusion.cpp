// simplify_fusion IN OUT RATIO: Feature_fusion_policies (Wang et al. 2013) with its default
// parameters, calling CGAL's edge_collapse directly: the smallest complete use of the policy.
#include "example_files.h"

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Feature_fusion_policies.h>

#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace SMS = CGAL::Surface_mesh_simplification;
using example::Kernel;
using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args =
      example::arguments(argc, argv, "usage: simplify_fusion IN OUT RATIO (0 < RATIO <= 1)");
  Mesh mesh = example::read_mesh(args.input);
  const cgal_policies::Feature_fusion_policies<Mesh, Kernel> policies(mesh);
  // A face-count stop, as simplify's, so that RATIO means the same in both.
  SMS::edge_collapse(
      mesh,
      cgal_policies::Face_count_stop_predicate<Mesh>(mesh, example::target_of(mesh, args.ratio)),
      CGAL::parameters::get_cost(policies.get_cost())
          .get_placement(policies.get_placement())
          .filter(cgal_policies::Bounded_normal_angle_filter<>()));
  std::cout << mesh.number_of_faces() << " faces\n";
  example::write_mesh(mesh, args.output);
}
