// A glTF file's materials as an OBJ material library, for the OBJ files written from its mesh
// (mesh_io.h): the inverse of obj_material_looks.h, each material's base colour as a diffuse colour
// and map.
#ifndef CGAL_POLICIES_IO_GLTF_MATERIAL_LIBRARY_H
#define CGAL_POLICIES_IO_GLTF_MATERIAL_LIBRARY_H

#include "mesh_io.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// The files OBJ files of a glTF file's mesh need beside them, with their bytes: the material
// library first, then the images it names that the glTF file held inside it.
struct Gltf_material_library {
  struct File {
    std::string path, bytes;
  };
  std::vector<File> files;            // none when no material is used
  std::vector<std::string> left_out;  // a line for each base colour texture left out
};

// The library of the materials of `looks` (Gltf_soup::looks) that `used` marks, named as `names`
// names them (Material_references::names, which the OBJ files' usemtl lines use), for OBJ files
// in the folder of `path`: `<stem>.mtl`, `path`'s stem, holding for each material in order a
// `newmtl`, the rgb of its baseColorFactor as `Kd`, its alpha as `d` unless the material is opaque
// (alphaMode OPAQUE, which ignores the alpha), and the image of its baseColorTexture as `map_Kd`
// (mtl_text, obj_writer.h). An image file (a uri) is named by its path from that folder and left
// where it is; an image the glTF file held (in a bufferView or a data URI) becomes a file of its
// bytes, unchanged, `<stem>_image<i>.png` or `.jpg` as its first bytes tell (image_mime_type),
// `i` its index in `looks`. A texture whose image is neither is left out, with a line in
// `left_out` ("<library>: material '<name>': ... written without it"): glTF holds no other type
// but through extensions, and an OBJ is worth more than its texture.
Gltf_material_library gltf_material_library(const tinygltf::Model& looks,
                                            const std::vector<std::string>& names,
                                            const std::vector<bool>& used, const std::string& path);

// The index in `looks.images` of the image of the base colour texture of
// `looks.materials[material]`; -1 when it has none (a texture may have its image in an extension
// alone, KHR_texture_basisu's or EXT_texture_webp's). The OBJ library and the viewer's picture take
// the same image.
int base_color_image(const tinygltf::Model& looks, std::size_t material);

// Throws Io_error (unwritable output, "<file>: refusing to overwrite an image of the input") when
// one of `files` is an image file that `looks` names.
void check_no_image_of(const tinygltf::Model& looks, const std::vector<std::string>& files);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_MATERIAL_LIBRARY_H
