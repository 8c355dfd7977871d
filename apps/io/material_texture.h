// The texture image a textured OBJ mesh is drawn with: the diffuse map (map_Kd) of its materials,
// found in the material libraries the file named (mesh_io.h).
#ifndef CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
#define CGAL_POLICIES_IO_MATERIAL_TEXTURE_H

#include "mesh_io.h"

#include <optional>
#include <string>

namespace cgal_policies {
namespace io {

// The map_Kd file of the first of `materials.names` that has one, resolved against its library's
// folder; none when no library can be read or none has one. Throws Io_error (unreadable input,
// "<library>: texture '<file>' does not exist") when the file named is missing.
std::optional<std::string> diffuse_texture_file(const Material_references& materials);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
