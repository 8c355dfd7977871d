#include "mesh_validity.h"

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace apps {
namespace {

double corner_angle_deg(const Point& a, const Point& b, const Point& c) {
  const Kernel::Vector_3 u = b - a, v = c - a;
  const double lengths = std::sqrt(u.squared_length() * v.squared_length());
  if (!(lengths > 0)) return 0;
  return std::acos(std::clamp(u * v / lengths, -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

Mesh_validity check_mesh_validity(const Mesh& mesh) {
  Mesh_validity v;
  v.valid = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh);
  v.closed = CGAL::is_closed(mesh);
  v.faces = mesh.number_of_faces();
  v.vertices = mesh.number_of_vertices();
  for (auto e : edges(mesh)) v.boundary_edges += CGAL::is_border(e, mesh);
  std::vector<Mesh::Halfedge_index> pinched;
  PMP::non_manifold_vertices(mesh, std::back_inserter(pinched));
  std::vector<Mesh::Vertex_index> pinched_vertices;
  for (auto h : pinched) pinched_vertices.push_back(target(h, mesh));
  std::sort(pinched_vertices.begin(), pinched_vertices.end());
  v.non_manifold_vertices = std::size_t(
      std::unique(pinched_vertices.begin(), pinched_vertices.end()) - pinched_vertices.begin());
  v.min_angle_deg = 180;
  for (auto f : faces(mesh)) {
    if (!v.valid) break;  // corners are only defined on triangles
    v.degenerate_faces += PMP::is_degenerate_triangle_face(f, mesh);
    const auto h = halfedge(f, mesh);
    const Point& p = mesh.point(source(h, mesh));
    const Point& q = mesh.point(target(h, mesh));
    const Point& r = mesh.point(target(next(h, mesh), mesh));
    v.min_angle_deg = std::min({v.min_angle_deg, corner_angle_deg(p, q, r),
                                corner_angle_deg(q, r, p), corner_angle_deg(r, p, q)});
  }
  v.euler_characteristic =
      long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  return v;
}

}  // namespace apps
