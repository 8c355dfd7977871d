#include "small_components.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace apps {
namespace {

// Removes whole components, smallest first (the first found among equals), while
// keep_dropping(component faces, faces left) holds; never the largest one. Leaves the mesh compact.
template <typename KeepDropping>
Dropped_components drop_smallest_while(Mesh& mesh, const KeepDropping& keep_dropping) {
  auto components = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<std::size_t> sizes(PMP::connected_components(mesh, components), 0);
  for (Mesh::Face_index f : faces(mesh)) ++sizes[get(components, f)];
  std::vector<std::size_t> by_size(sizes.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(),
                   [&](std::size_t a, std::size_t b) { return sizes[a] < sizes[b]; });
  Dropped_components dropped;
  std::vector<std::size_t> doomed;
  std::size_t faces_left = mesh.number_of_faces();
  // by_size.back() is the largest component: the mesh keeps it whatever is asked.
  for (std::size_t i = 0; i + 1 < by_size.size() && keep_dropping(sizes[by_size[i]], faces_left);
       ++i) {
    doomed.push_back(by_size[i]);
    faces_left -= sizes[by_size[i]];
    dropped.faces += sizes[by_size[i]];
  }
  if (doomed.empty()) return dropped;
  dropped.components = doomed.size();
  PMP::remove_connected_components(mesh, doomed, components);
  mesh.collect_garbage();
  return dropped;
}

}  // namespace

Dropped_components drop_components_smaller_than(Mesh& mesh, std::size_t min_faces) {
  if (min_faces <= 1) return {};  // every component has a face
  return drop_smallest_while(mesh,
                             [&](std::size_t faces, std::size_t) { return faces < min_faces; });
}

Dropped_components drop_smallest_components_until(Mesh& mesh, std::size_t target_faces) {
  return drop_smallest_while(mesh,
                             [&](std::size_t, std::size_t left) { return left > target_faces; });
}

}  // namespace apps
