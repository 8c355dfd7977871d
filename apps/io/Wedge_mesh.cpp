#include "Wedge_mesh.h"

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <utility>

namespace cgal_policies {
namespace io {

Wedge_mesh wedge_mesh(const Mesh& mesh) {
  using Attributes = cgal_policies::Corner_attributes<Point>;
  const Attributes attributes(mesh);
  // The wedges found so far at each vertex: their values and their index.
  using Found = boost::container::small_vector<std::pair<Attributes::Values, std::uint32_t>, 1>;
  std::vector<Found> found(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  Wedge_mesh result;
  result.triangles.reserve(mesh.number_of_faces());
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> triangle{};
    std::size_t k = 0;
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const auto v = mesh.target(h);
      const Attributes::Values values = attributes.values(h);
      Found& wedges = found[std::size_t(v)];
      auto wedge = std::find_if(wedges.begin(), wedges.end(), [&](const auto& w) {
        return Attributes::same_values(w.first, values);
      });
      if (wedge == wedges.end()) {
        wedge = wedges.insert(wedges.end(), {values, std::uint32_t(result.points.size())});
        result.points.push_back(mesh.point(v));
        if (attributes.uvs) result.uvs.push_back(values.uv);
        if (attributes.normals) result.normals.push_back(values.normal);
        if (attributes.colors) result.colors.push_back(values.color);
      }
      triangle[k++] = wedge->second;
    }
    result.triangles.push_back(triangle);
    if (attributes.materials) result.materials.push_back((*attributes.materials)[f]);
  }
  return result;
}

}  // namespace io
}  // namespace cgal_policies
