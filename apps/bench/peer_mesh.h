// Indexed triangle arrays, the form in which the peer libraries take and return meshes.
#ifndef CGAL_POLICIES_APPS_BENCH_PEER_MESH_H
#define CGAL_POLICIES_APPS_BENCH_PEER_MESH_H

#include "common/Mesh_types.h"

#include <array>
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

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_PEER_MESH_H
