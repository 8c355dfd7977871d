#include "clean_triangle_soup.h"

#include <cgal_policies/internal/clean_triangle_mesh.h>

namespace cgal_policies {
namespace io {

bool build_mesh_from_clean_triangles(const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons,
                                     Mesh& mesh, std::size_t& unused_points,
                                     std::vector<Mesh::Vertex_index>* vertex_of_point,
                                     std::size_t threads) {
  mesh.clear();
  // No face left (triangulation drops polygons of fewer than 3 corners): the general path says so.
  if (polygons.empty()) return false;
  std::vector<std::size_t> corners;
  corners.reserve(3 * polygons.size());
  for (const auto& polygon : polygons) {
    if (polygon.size() != 3) return false;
    corners.insert(corners.end(), polygon.begin(), polygon.end());
  }
  return build_mesh_from_clean_triangles(points, corners, mesh, unused_points, vertex_of_point,
                                         threads);
}

bool build_mesh_from_clean_triangles(const std::vector<Point>& points,
                                     const std::vector<std::size_t>& corners, Mesh& mesh,
                                     std::size_t& unused_points,
                                     std::vector<Mesh::Vertex_index>* vertex_of_point,
                                     std::size_t threads) {
  return internal::build_clean_triangle_mesh(points, corners, mesh, unused_points, vertex_of_point,
                                             threads);
}

}  // namespace io
}  // namespace cgal_policies
