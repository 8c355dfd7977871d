#include "Surface_distance.h"

#include <cmath>

namespace apps {

Surface_distance::Surface_distance(const Mesh& surface)
    : m_surface(surface), m_tree(faces(m_surface).first, faces(m_surface).second, m_surface) {
  m_tree.accelerate_distance_queries();
}

double Surface_distance::operator()(const Point& p) const {
  return std::sqrt(m_tree.squared_distance(p));
}

std::vector<double> Surface_distance::vertex_distances(const Indexed_mesh& mesh,
                                                       std::vector<double>& cache) const {
  std::vector<bool> used(mesh.points.size(), false);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) used[v] = true;
  std::vector<double> result(mesh.points.size(), 0.0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!used[v]) continue;
    const std::size_t id = mesh.point_ids[v];
    if (id >= cache.size()) cache.resize(id + 1, -1.0);
    if (cache[id] < 0) cache[id] = (*this)(mesh.points[v]);
    result[v] = cache[id];
  }
  return result;
}

}  // namespace apps
