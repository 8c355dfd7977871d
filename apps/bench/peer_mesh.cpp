#include "peer_mesh.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <limits>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace apps {

Indexed_triangles to_indexed_triangles(const Mesh& mesh) {
  Indexed_triangles soup;
  std::vector<std::uint32_t> index(mesh.num_vertices());  // by vertex index, garbage included
  for (Mesh::Vertex_index v : mesh.vertices()) {
    index[v] = std::uint32_t(soup.points.size());
    soup.points.push_back(mesh.point(v));
  }
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    std::size_t i = 0;
    for (Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) t[i++] = index[v];
    soup.triangles.push_back(t);
  }
  return soup;
}

Mesh to_mesh(const Indexed_triangles& soup) {
  constexpr std::size_t kUnused = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> new_index(soup.points.size(), kUnused);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : soup.triangles) {
    std::vector<std::size_t> polygon;
    for (std::uint32_t i : t) {
      if (new_index[i] == kUnused) {
        new_index[i] = points.size();
        points.push_back(soup.points[i]);
      }
      polygon.push_back(new_index[i]);
    }
    polygons.push_back(std::move(polygon));
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return mesh;
}

cgal_policies::Stop_reason adopt_peer_result(const Indexed_triangles& result,
                                             std::size_t target_faces, Mesh& mesh) {
  mesh = to_mesh(result);
  return mesh.number_of_faces() <= target_faces ? cgal_policies::Stop_reason::target_reached
                                                : cgal_policies::Stop_reason::no_collapse_left;
}

}  // namespace apps
