// Reading and writing meshes for every app: OBJ, OFF, PLY, STL and glTF, polygon soups repaired and
// polygons triangulated with their corner attributes, and atomic writes that never leave a partial
// file or touch the input.
#ifndef CGAL_POLICIES_IO_MESH_IO_H
#define CGAL_POLICIES_IO_MESH_IO_H

#include "Io_error.h"
#include "Mesh_types.h"
#include "soup_readers.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace cgal_policies {
namespace io {

// What the faces of a mesh read from an OBJ or glTF file refer to outside it: the material
// libraries (paths resolved against the folder of the file read, inside its asset folder), the
// material names that the face material map (cgal_policies::Corner_attributes) indexes, and from
// a glTF file its materials themselves, with their textures and images, and the skeleton of its
// skin (gltf_io.h), for a glTF output to keep. `asset_root` is the folder the libraries' texture
// images may come from (Asset_folder.h): the reader's; empty, each library's own folder.
struct Material_references {
  std::vector<std::string> libraries, names;
  std::shared_ptr<const tinygltf::Model> gltf;
  std::string asset_root;
};

struct Read_report {
  std::vector<std::string> repairs;   // what was repaired, one phrase each; empty when nothing was
  Material_references materials;      // when the corner attributes were kept
  std::vector<std::string> left_out;  // what the file holds that the mesh does not, a line each
};

// Whether the reader puts a file's texture coordinates, normals, colours and materials on the mesh
// (cgal_policies::Corner_attributes), or reads the surface alone. OBJ files carry all four
// (colours per point), PLY files per-vertex normals, texture coordinates and colours, glTF files
// all four per vertex; the others none.
enum class Corner_attribute_reading { drop, keep };

// The file's extension in lower case, with its dot (".obj"); empty when it has none.
std::string lower_extension(const std::string& path);

bool has_supported_mesh_extension(const std::string& path);

// Whether the file of this name is glTF (.gltf, .glb).
bool is_gltf_file(const std::string& path);

// Whether write_mesh_atomically writes a mesh's corner attributes to a file of this name (OBJ,
// PLY, glTF).
bool writes_corner_attributes(const std::string& path);

// How a file is read: whether with its corner attributes; on how many cores a clean mesh's points
// are checked (0: all of them); and from where the files it names may come (a glTF file's buffers
// and images, an OBJ file's material libraries and their textures): empty, the folder of the file
// read and the folders below it; else a folder holding the file, for trusted assets that share
// files above their own folder (Asset_folder.h). A buffer from elsewhere is an error; a material
// library or an image from elsewhere is left out, with a line in Read_report::left_out.
struct Read_options {
  Corner_attribute_reading attributes = Corner_attribute_reading::drop;
  std::size_t threads = 1;
  std::string asset_root;
};

// Reads a triangle mesh; throws Io_error (unreadable input, "<path>: <cause>") when it cannot.
Mesh read_triangle_mesh(const std::string& path, const Read_options& options,
                        Read_report* report = nullptr);
// The same, the files it names confined to its folder.
Mesh read_triangle_mesh(const std::string& path, Read_report* report = nullptr,
                        Corner_attribute_reading attributes = Corner_attribute_reading::drop,
                        std::size_t threads = 1);

// The levels of detail of the file at `path`, finest first, each read as read_triangle_mesh reads
// a mesh: a glTF file's levels (read_gltf_levels, gltf_io.h: its nodes' MSFT_lod, as
// write_lod_chain_atomically writes them); any other file, or a glTF file without MSFT_lod, is one
// level. `report` gets level 0's materials, which every level shares, and every level's repairs,
// those of level k > 0 after "level k: ". Throws Io_error (unreadable input) as read_triangle_mesh
// and read_gltf_levels do; an error in level k > 0's mesh names "<path> (level k)". Read with
// `options` (but for its threads: one).
std::vector<Mesh> read_lod_chain(const std::string& path, const Read_options& options = {},
                                 Read_report* report = nullptr);

// The reader's second half: checks the soup (faces, finite points, indices in range), splits its
// polygons into triangles (soup_repair.h: none is refused for its shape), builds the mesh directly
// when the triangles are a clean mesh, and otherwise repairs them first. Errors name `source`, as
// above. The corner attributes of `corners`, when given, go onto the mesh, through the
// triangulation and the repairs (which is why the soup and its tables change in place). `threads`
// as read_triangle_mesh's.
Mesh triangle_mesh_from_soup(const std::string& source, std::vector<Point>& points,
                             std::vector<std::vector<std::size_t>>& polygons,
                             Read_report* report = nullptr, Corner_tables* corners = nullptr,
                             std::size_t threads = 1);

// How a glTF file stores its vertices (gltf_bytes): in float32; quantized to integers
// (KHR_mesh_quantization); or quantized, then compressed by meshoptimizer
// (EXT_meshopt_compression). Other formats have one way each.
enum class Gltf_encoding { float32, quantized, meshopt };

// The encoding of one of the names "float", "quantized" and "meshopt" (simplify's
// --gltf-encoding, the Python module's write); nothing for another name.
std::optional<Gltf_encoding> gltf_encoding_named(const std::string& name);

// Writes by extension with full precision, all or nothing (write_atomically); throws
// Io_error (unwritable output) and leaves no file behind when that fails. An OBJ file gets the
// mesh's corner attributes too (obj_text): its texture coordinates and normals per corner, colours
// per point, and `materials` (mtllib paths made relative to the file's folder, a usemtl line
// wherever the material changes); the materials of a glTF input get a library and images beside
// it (gltf_material_library.h), written in the same go, none of which may be an image file of the
// input. A PLY file gets a vertex per wedge with its values (ply_bytes). A glTF file (.gltf, .glb)
// is always written by gltf_bytes (gltf_io.h), with whatever the mesh carries, an OBJ material's
// diffuse map embedded, its vertices stored as `encoding` says. Returns what the files were written
// without that `materials` name, one line each (a texture file missing or unreadable, an image of
// a type OBJ or glTF does not hold); none is a failure.
std::vector<std::string> write_mesh_atomically(const Mesh& mesh, const std::string& path,
                                               const Material_references& materials = {},
                                               Gltf_encoding encoding = Gltf_encoding::float32);

// A level of a chain of levels of detail (write_lod_chain_atomically): its mesh, and the share of
// the screen's area below which a viewer switches to the next coarser level (glTF's
// MSFT_screencoverage; 0: never culled).
struct Lod_level {
  const Mesh* mesh;
  double screen_coverage;
};

// Whether write_lod_chain_atomically writes every level into `path` itself (glTF).
bool holds_lod_chain(const std::string& path);

// The files write_lod_chain_atomically writes for `levels` levels of `path`: `path` alone when it
// holds them all; otherwise a file per level, its stem followed by _lod0 (the finest), _lod1, ...:
// out.obj gives out_lod0.obj, out_lod1.obj, ...
std::vector<std::string> lod_level_paths(const std::string& path, std::size_t levels);

// Writes a chain of levels of detail, finest first, into lod_level_paths(path, levels.size()),
// all or none (write_all_atomically), each as write_mesh_atomically writes a mesh; a glTF file
// holds every level (gltf_bytes: MSFT_lod), stored as `encoding` says, and OBJ levels of a glTF
// input share one material library and its images, named after `path`. Returns what the files
// were written without, as write_mesh_atomically does. At most kMaxFilesWrittenAtOnce files in
// all, or Io_error before any is written.
std::vector<std::string> write_lod_chain_atomically(
    const std::vector<Lod_level>& levels, const std::string& path,
    const Material_references& materials = {}, Gltf_encoding encoding = Gltf_encoding::float32);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MESH_IO_H
