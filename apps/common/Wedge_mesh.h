// A mesh as the formats that store one set of values per vertex (glTF) want it: one vertex per
// wedge, that is, per mesh vertex and distinct tuple of values among its corners
// (cgal_policies::Corner_attributes), so that a seam splits a vertex in as many as it has sides.
#ifndef CGAL_POLICIES_APPS_WEDGE_MESH_H
#define CGAL_POLICIES_APPS_WEDGE_MESH_H

#include "Mesh_types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace apps {

struct Wedge_mesh {
  std::vector<Point> points;                            // one per wedge
  std::vector<std::array<double, 2>> uvs;               // per wedge; empty when the mesh has none
  std::vector<Kernel::Vector_3> normals;                // likewise
  std::vector<std::array<double, 4>> colors;            // likewise, RGBA in [0, 1]
  std::vector<std::array<std::uint32_t, 3>> triangles;  // wedge indices, in the mesh's face order
  std::vector<std::uint32_t> materials;  // per triangle; empty without a material map
};

// The wedges of a triangle mesh, each vertex's in the order its corners are first met face by face.
Wedge_mesh wedge_mesh(const Mesh& mesh);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_WEDGE_MESH_H
