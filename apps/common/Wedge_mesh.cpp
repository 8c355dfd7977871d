#include "Wedge_mesh.h"

#include <cgal_policies/Corner_attributes.h>

#include <cmath>
#include <cstddef>

namespace apps {
namespace {

using Attributes = cgal_policies::Corner_attributes<Point>;

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// The values of a corner that tell wedges apart; NaN where the mesh has no such map.
std::array<double, 5> corner_values(const Attributes& attributes, Mesh::Halfedge_index h) {
  std::array<double, 5> values;
  values.fill(Attributes::kNone);
  if (attributes.uvs) values[0] = (*attributes.uvs)[h][0], values[1] = (*attributes.uvs)[h][1];
  if (attributes.normals)
    for (int i = 0; i < 3; ++i) values[2 + i] = (*attributes.normals)[h][i];
  return values;
}

bool same_values(const std::array<double, 5>& a, const std::array<double, 5>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_number(a[i], b[i])) return false;
  return true;
}

}  // namespace

Wedge_mesh wedge_mesh(const Mesh& mesh) {
  const Attributes attributes(mesh);
  Wedge_mesh wedges;
  // Each vertex's wedges so far, with their values: a vertex has few, so a scan finds them.
  std::vector<std::vector<std::pair<std::array<double, 5>, std::uint32_t>>> wedges_of(
      mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> triangle{};
    std::size_t k = 0;
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::array<double, 5> values = corner_values(attributes, h);
      auto& known = wedges_of[mesh.target(h)];
      std::size_t w = 0;
      while (w < known.size() && !same_values(known[w].first, values)) ++w;
      if (w == known.size()) {
        known.emplace_back(values, std::uint32_t(wedges.points.size()));
        wedges.points.push_back(mesh.point(mesh.target(h)));
        if (attributes.uvs) wedges.uvs.push_back((*attributes.uvs)[h]);
        if (attributes.normals) wedges.normals.push_back((*attributes.normals)[h]);
      }
      triangle[k++] = known[w].second;
    }
    wedges.triangles.push_back(triangle);
    if (attributes.materials) wedges.materials.push_back((*attributes.materials)[f]);
  }
  return wedges;
}

}  // namespace apps
