// The OBJ writer for meshes that carry corner attributes (cgal_policies::Corner_attributes), and
// of the material library beside it; CGAL 5.5's OBJ writer writes points and faces alone.
#ifndef CGAL_POLICIES_IO_OBJ_WRITER_H
#define CGAL_POLICIES_IO_OBJ_WRITER_H

#include "Mesh_types.h"

#include <array>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// The text of an OBJ file: `mtllib` lines for `material_libraries` (as given), the points (every
// number written so that reading it back gives the same double; after it the colour, r g b or
// r g b a, of the point's first corner that has one, as OBJ colours are per point), the distinct
// texture coordinates and normals of the corners, then the faces in the mesh's order, with a
// `usemtl` line naming `material_names[i]` wherever the face material changes to i. A corner
// without a texture coordinate or a normal names none.
std::string obj_text(const Mesh& mesh, const std::vector<std::string>& material_libraries,
                     const std::vector<std::string>& material_names);

// A material of a material library (mtl_text): its diffuse colour, its opacity and its diffuse
// map's file, named from the library's folder (none when empty).
struct Mtl_material {
  std::string name;
  std::array<double, 3> diffuse;
  double opacity;
  std::string diffuse_map;
};

// The text of a material library (.mtl): for each material, in order, a `newmtl` line, its `Kd`,
// a `d` when it is not opaque (opacity below 1) and a `map_Kd` when it has a map; every number
// written so that reading it back gives the same double.
std::string mtl_text(const std::vector<Mtl_material>& materials);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_OBJ_WRITER_H
