// A mesh as formats with per-vertex attributes (PLY, glTF) store it: one vertex per wedge, a wedge
// being a mesh vertex with one distinct tuple of its corners' values
// (cgal_policies::Corner_attributes), so that each side of a seam keeps its own values.
#ifndef CGAL_POLICIES_IO_WEDGE_MESH_H
#define CGAL_POLICIES_IO_WEDGE_MESH_H

#include "Mesh_types.h"

#include <cgal_policies/Corner_attributes.h>

#include <array>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace io {

struct Wedge_mesh {
  std::vector<Point> points;                      // one per wedge
  std::vector<std::array<double, 2>> uvs;         // per wedge; empty when the mesh has none
  std::vector<Kernel::Vector_3> normals;          // likewise
  std::vector<std::array<double, 4>> colors;      // likewise, RGBA in [0, 1]
  std::vector<std::array<double, 2>> second_uvs;  // likewise
  std::vector<Corner_attributes<Point>::Skin_influences> skins;  // likewise
  std::vector<std::array<std::uint32_t, 3>> triangles;  // wedge indices, in the mesh's face order
  std::vector<std::uint32_t> materials;  // per triangle; empty without a material map
};

// The wedges numbered in the order the faces first use them; a vertex on no face has none.
Wedge_mesh wedge_mesh(const Mesh& mesh);

// `wedges` in the order gltfpack draws them: the triangles grouped by material (in the order of
// the material indices, none last), each group in the order meshoptimizer's vertex cache
// optimization gives it, then the wedges renumbered in the order the triangles first use them
// (its vertex fetch optimization). Neighbouring triangles and wedges then hold close values,
// which the GPU's vertex cache and meshoptimizer's compression both favour.
Wedge_mesh cache_ordered(const Wedge_mesh& wedges);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_WEDGE_MESH_H
