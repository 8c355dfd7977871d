// Links Classic_quadric_policies and Bounded_normal_angle_filter into a plain CGAL pipeline and
// checks the result: an icosahedron collapsed as far as it goes is a tetrahedron.
#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/generators.h>

#include <iostream>

namespace SMS = CGAL::Surface_mesh_simplification;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main() {
  Mesh mesh;
  CGAL::make_icosahedron<Mesh, Kernel::Point_3>(mesh);
  cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh);
  SMS::edge_collapse(mesh, SMS::Count_stop_predicate<Mesh>(0),
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(cgal_policies::Bounded_normal_angle_filter<>(60.0)));
  std::cout << mesh.number_of_faces() << " faces\n";
  return mesh.number_of_faces() == 4 && mesh.number_of_vertices() == 4 ? 0 : 1;
}
