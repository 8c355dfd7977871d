// The reader's fast path: most files already hold an oriented manifold triangle mesh, built
// straight from their indices (cgal_policies/internal/clean_triangle_mesh.h).
#ifndef CGAL_POLICIES_IO_CLEAN_TRIANGLE_SOUP_H
#define CGAL_POLICIES_IO_CLEAN_TRIANGLE_SOUP_H

#include "Mesh_types.h"

#include <cstddef>
#include <vector>

namespace cgal_policies {
namespace io {

// Builds `mesh` from a soup whose indices are all in range (the caller checks them) when every
// polygon is a triangle of three distinct points, no oriented edge is used twice, no edge has
// more than two faces, and the faces around each point form one fan. Points no face uses are
// left out and counted in `unused_points`. Faces, and the used points, keep the soup's order.
// Returns false and leaves `mesh` empty when the soup has no polygon or is not such a mesh: it
// needs repair, or has nothing to build.
// `vertex_of_point`, when given, gets each point's vertex (a null index for an unused point).
// The checks around each point run on up to `threads` cores (0: all of them).
bool build_mesh_from_clean_triangles(const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons,
                                     Mesh& mesh, std::size_t& unused_points,
                                     std::vector<Mesh::Vertex_index>* vertex_of_point = nullptr,
                                     std::size_t threads = 1);

// The same from the triangles `corners`, three point indices each (all below points.size()).
bool build_mesh_from_clean_triangles(const std::vector<Point>& points,
                                     const std::vector<std::size_t>& corners, Mesh& mesh,
                                     std::size_t& unused_points,
                                     std::vector<Mesh::Vertex_index>* vertex_of_point = nullptr,
                                     std::size_t threads = 1);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_CLEAN_TRIANGLE_SOUP_H
