#include "Wedge_mesh.h"

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/boost/graph/iterator.h>

#include <meshoptimizer.h>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <numeric>
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
        if (attributes.second_uvs) result.second_uvs.push_back(values.second_uv);
        if (attributes.skins) result.skins.push_back(values.skin);
      }
      triangle[k++] = wedge->second;
    }
    result.triangles.push_back(triangle);
    if (attributes.materials) result.materials.push_back((*attributes.materials)[f]);
  }
  return result;
}

Wedge_mesh cache_ordered(const Wedge_mesh& wedges) {
  const std::size_t triangles = wedges.triangles.size(), vertices = wedges.points.size();
  const auto material = [&wedges](std::size_t t) {
    return wedges.materials.empty() ? 0 : wedges.materials[t];
  };
  std::vector<std::size_t> order(triangles);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return material(a) < material(b); });
  Wedge_mesh result;
  std::vector<unsigned> indices;
  for (std::size_t begin = 0, end = 0; begin < triangles; begin = end) {
    std::vector<unsigned> group;
    for (end = begin; end < triangles && material(order[end]) == material(order[begin]); ++end) {
      const std::array<std::uint32_t, 3>& triangle = wedges.triangles[order[end]];
      group.insert(group.end(), triangle.begin(), triangle.end());
      if (!wedges.materials.empty()) result.materials.push_back(material(order[end]));
    }
    indices.resize(indices.size() + group.size());
    meshopt_optimizeVertexCache(indices.data() + indices.size() - group.size(), group.data(),
                                group.size(), vertices);
  }
  std::vector<unsigned> remap(vertices);
  result.points.resize(
      meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertices));
  // Every wedge is on a triangle (wedge_mesh), so every one has a new number.
  const auto move_values = [&remap](const auto& from, auto& to) {
    if (from.empty()) return;
    to.resize(from.size());
    for (std::size_t v = 0; v < from.size(); ++v) to[remap[v]] = from[v];
  };
  move_values(wedges.points, result.points);
  move_values(wedges.uvs, result.uvs);
  move_values(wedges.normals, result.normals);
  move_values(wedges.colors, result.colors);
  move_values(wedges.second_uvs, result.second_uvs);
  move_values(wedges.skins, result.skins);
  for (std::size_t i = 0; i < indices.size(); i += 3)
    result.triangles.push_back({remap[indices[i]], remap[indices[i + 1]], remap[indices[i + 2]]});
  return result;
}

}  // namespace io
}  // namespace cgal_policies
