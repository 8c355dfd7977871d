// An OBJ file's materials as glTF materials, for the glTF writer (gltf_io.h): what obj2gltf and
// gltfpack make of them, a material per name with its diffuse map as its base colour texture.
#ifndef CGAL_POLICIES_IO_OBJ_MATERIAL_LOOKS_H
#define CGAL_POLICIES_IO_OBJ_MATERIAL_LOOKS_H

#include "mesh_io.h"

#include <memory>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// The looks of `materials` (an OBJ file's, mesh_io.h) in the form read_gltf keeps a glTF file's
// (Gltf_soup::looks): one material per name, named after it. When `textured`, each material whose
// map_Kd (material_texture.h) is a PNG or JPEG file, told by its first bytes and not by its
// extension, gets it as its pbrMetallicRoughness.baseColorTexture (texCoord 0): an image holding
// the file's bytes unchanged (mimeType image/png or image/jpeg) and a texture with a repeating,
// mipmapped sampler; materials that name the same file share its image and texture. A map whose
// file does not exist, cannot be read or is neither PNG nor JPEG (glTF's two image types) is left
// out, and `left_out` gets one line saying so ("<library>: texture '<file>' does not exist;
// written without it"): real assets name files they do not ship, and the mesh is worth more than
// its texture.
std::shared_ptr<const tinygltf::Model> obj_material_looks(const Material_references& materials,
                                                          bool textured,
                                                          std::vector<std::string>& left_out);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_OBJ_MATERIAL_LOOKS_H
