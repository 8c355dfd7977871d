// Indexed triangle arrays, the form in which the peer libraries take and return meshes.
#ifndef CGAL_POLICIES_APPS_BENCH_PEER_MESH_H
#define CGAL_POLICIES_APPS_BENCH_PEER_MESH_H

#include <cgal_policies/Stop_reason.h>
#include "app_types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace apps {

struct Indexed_triangles {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

Indexed_triangles to_indexed_triangles(const Mesh& mesh);

// Unused points are dropped; a soup that is not a manifold mesh is oriented and its non-manifold
// vertices split, as mesh_io does when reading, so that every peer's result can be measured.
Mesh to_mesh(const Indexed_triangles& soup);

// Makes a peer's result the run's mesh. A peer does not say why it stopped, so the face count
// tells: the target when it is met, else no collapse left.
cgal_policies::Stop_reason adopt_peer_result(const Indexed_triangles& result,
                                             std::size_t target_faces, Mesh& mesh);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_PEER_MESH_H
