// Dropping small connected components whole: the specks and fragments around a scanned surface are
// components of their own, which edge collapses cannot shrink below a few faces each.
// Simplification_pipeline drops them before the run (min_component) or after it
// (drop_small_pieces). For any face graph; a CGAL::Surface_mesh is left compact (garbage
// collected).
#ifndef CGAL_POLICIES_SMALL_COMPONENTS_H
#define CGAL_POLICIES_SMALL_COMPONENTS_H

#include <cgal_policies/internal/Is_surface_mesh.h>
#include <cgal_policies/internal/face_count.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace cgal_policies {

struct Dropped_components {
  std::size_t components = 0;
  std::size_t faces = 0;
};

namespace internal {

// Removes whole components, smallest first (the first found among equals), while
// keep_dropping(component faces, faces left) holds; never the largest one.
template <typename FaceGraph, typename KeepDropping>
Dropped_components drop_smallest_while(FaceGraph& mesh, const KeepDropping& keep_dropping) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto components = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<std::size_t> sizes(PMP::connected_components(mesh, components), 0);
  for (auto f : faces(mesh)) ++sizes[get(components, f)];
  std::vector<std::size_t> by_size(sizes.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(),
                   [&](std::size_t a, std::size_t b) { return sizes[a] < sizes[b]; });
  Dropped_components dropped;
  std::vector<std::size_t> doomed;
  std::size_t faces_left = face_count(mesh);
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
  if constexpr (Is_surface_mesh<FaceGraph>::value) mesh.collect_garbage();
  return dropped;
}

}  // namespace internal

// Removes every connected component of fewer than `min_faces` faces but the largest, so the mesh
// never ends empty.
template <typename FaceGraph>
Dropped_components drop_components_smaller_than(FaceGraph& mesh, std::size_t min_faces) {
  if (min_faces <= 1) return {};  // every component has a face
  return internal::drop_smallest_while(
      mesh, [&](std::size_t faces, std::size_t) { return faces < min_faces; });
}

// Removes connected components whole, smallest first (the first found among equals), while the
// mesh has more than `target_faces` faces; never the largest one.
template <typename FaceGraph>
Dropped_components drop_smallest_components_until(FaceGraph& mesh, std::size_t target_faces) {
  return internal::drop_smallest_while(
      mesh, [&](std::size_t, std::size_t left) { return left > target_faces; });
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SMALL_COMPONENTS_H
