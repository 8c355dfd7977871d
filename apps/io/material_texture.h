// The texture images a textured OBJ mesh is drawn with: the diffuse maps (map_Kd) of its materials,
// found in the material libraries the file named (mesh_io.h), and the image types a texture may
// have.
#ifndef CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
#define CGAL_POLICIES_IO_MATERIAL_TEXTURE_H

#include "mesh_io.h"

#include <optional>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// A material's map_Kd line: the library that holds it, the file as the line names it, and that
// file resolved against the library's folder (whether or not it exists).
struct Diffuse_map {
  std::string library, file, path;
};

// The map_Kd of each of `materials.names`, in their order: the first that the material's
// definitions give over all libraries, none for a material without one or a library that cannot
// be read.
std::vector<std::optional<Diffuse_map>> diffuse_maps(const Material_references& materials);

// The map_Kd file of the first of `materials.names` that has one (diffuse_maps); none when none
// has one. Throws Io_error (unreadable input, "<library>: texture '<file>' does not exist") when
// the file named is missing.
std::optional<std::string> diffuse_texture_file(const Material_references& materials);

// The mimeType of an image's bytes, from their signature: "image/png" or "image/jpeg", glTF's two
// image types; empty when neither. A file's extension is often wrong in real assets; its first
// bytes are not.
std::string image_mime_type(const std::vector<unsigned char>& bytes);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
