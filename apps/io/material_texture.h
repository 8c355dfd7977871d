// The texture images a textured OBJ mesh is drawn with: the diffuse maps (map_Kd) of its materials,
// found in the material libraries the file named (mesh_io.h), and the image types a texture may
// have.
#ifndef CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
#define CGAL_POLICIES_IO_MATERIAL_TEXTURE_H

#include "Asset_folder.h"
#include "mesh_io.h"

#include <optional>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// The paths of the material libraries `libraries` that the OBJ file at `path` names (its mtllib
// lines), resolved against its folder; a library that `folder` refuses is left out, with a line in
// `left_out` ("<path>: material library '<name>' <why>; read without it").
std::vector<std::string> material_library_paths(const std::string& path,
                                                const std::vector<std::string>& libraries,
                                                const Asset_folder& folder,
                                                std::vector<std::string>& left_out);

// A line of a material library that names a texture file (map_Kd, map_Bump, bump, disp, decal,
// refl, norm, any map_*): its keyword, its options as written (-s 1 1 1, -clamp on, ...: each
// option with the arguments the format gives it), and the file, the rest of the line (a name may
// hold spaces); none for any other line, or one that names no file.
struct Texture_line {
  std::string keyword, options, file;
};
std::optional<Texture_line> texture_line(const std::string& line);

// A material's map_Kd line: the library that holds it, the file as the line names it, and that
// file resolved against the library's folder (whether or not it exists); or, when the file lies
// outside the asset folder (Material_references::asset_root, else the library's folder), no path
// and the reason.
struct Diffuse_map {
  std::string library, file, path, refusal;
};

// The map_Kd of each of `materials.names`, in their order: the first that the material's
// definitions give over all libraries, none for a material without one or a library that cannot
// be read.
std::vector<std::optional<Diffuse_map>> diffuse_maps(const Material_references& materials);

// The map_Kd file of the first of `materials.names` that has one (diffuse_maps); none when none
// has one. Throws Io_error (unreadable input, "<library>: texture '<file>' does not exist", or the
// reason it is refused) when the file named is missing or outside the asset folder.
std::optional<std::string> diffuse_texture_file(const Material_references& materials);

// The mimeType of an image's bytes, from their signature: "image/png" or "image/jpeg", glTF's two
// image types; empty when neither. A file's extension is often wrong in real assets; its first
// bytes are not.
std::string image_mime_type(const std::vector<unsigned char>& bytes);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MATERIAL_TEXTURE_H
