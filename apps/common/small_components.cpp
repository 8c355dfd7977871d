#include "small_components.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace apps {
namespace {

using Face_component_map =
    boost::property_map<Mesh, CGAL::dynamic_face_property_t<std::size_t>>::type;

// The face count of each component, indexed by the component ids of `components`.
std::vector<std::size_t> component_sizes(const Mesh& mesh, const Face_component_map& components,
                                         std::size_t count) {
  std::vector<std::size_t> sizes(count, 0);
  for (Mesh::Face_index f : faces(mesh)) ++sizes[get(components, f)];
  return sizes;
}

// The component ids, smallest first, the first found first among equals: the last is the largest
// component, which the mesh keeps whatever is asked.
std::vector<std::size_t> ids_by_size(const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> ids(sizes.size());
  std::iota(ids.begin(), ids.end(), 0);
  std::stable_sort(ids.begin(), ids.end(),
                   [&](std::size_t a, std::size_t b) { return sizes[a] < sizes[b]; });
  return ids;
}

Dropped_components remove_components(Mesh& mesh, const Face_component_map& components,
                                     const std::vector<std::size_t>& sizes,
                                     const std::vector<std::size_t>& doomed) {
  Dropped_components dropped;
  if (doomed.empty()) return dropped;
  for (std::size_t id : doomed) dropped.faces += sizes[id];
  dropped.components = doomed.size();
  PMP::remove_connected_components(mesh, doomed, components);
  mesh.collect_garbage();
  return dropped;
}

}  // namespace

Dropped_components drop_components_smaller_than(Mesh& mesh, std::size_t min_faces) {
  if (min_faces <= 1) return {};  // every component has a face
  auto components = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::vector<std::size_t> sizes =
      component_sizes(mesh, components, PMP::connected_components(mesh, components));
  const std::vector<std::size_t> by_size = ids_by_size(sizes);
  std::vector<std::size_t> doomed;
  for (std::size_t i = 0; i + 1 < by_size.size() && sizes[by_size[i]] < min_faces; ++i)
    doomed.push_back(by_size[i]);
  return remove_components(mesh, components, sizes, doomed);
}

Dropped_components drop_smallest_components_until(Mesh& mesh, std::size_t target_faces) {
  auto components = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::vector<std::size_t> sizes =
      component_sizes(mesh, components, PMP::connected_components(mesh, components));
  const std::vector<std::size_t> by_size = ids_by_size(sizes);
  std::vector<std::size_t> doomed;
  std::size_t faces_left = mesh.number_of_faces();
  for (std::size_t i = 0; i + 1 < by_size.size() && faces_left > target_faces; ++i) {
    doomed.push_back(by_size[i]);
    faces_left -= sizes[by_size[i]];
  }
  return remove_components(mesh, components, sizes, doomed);
}

}  // namespace apps
