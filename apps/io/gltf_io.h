// glTF 2.0 files (.gltf and .glb), read and written through Debian's tinygltf (its shared library
// holds the implementation, built with its default options: nlohmann/json, stb_image).
#ifndef CGAL_POLICIES_IO_GLTF_IO_H
#define CGAL_POLICIES_IO_GLTF_IO_H

#include "Mesh_types.h"
#include "mesh_io.h"
#include "soup_readers.h"

#include <memory>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

struct Gltf_soup {
  Polygon_soup soup;
  // The file's materials, textures, samplers and images, for a glTF file written from this mesh
  // to keep: an image stored in the file (a bufferView or a data URI) keeps its bytes as they
  // were, undecoded; an image in a file of its own keeps its uri, made absolute (the file's path,
  // its links resolved), or is left out, with a line in `left_out`, when it lies outside the
  // asset folder.
  // With skin influences, it also holds the skeleton they refer to (keep_skeleton in
  // gltf_io.cpp): the skin, its joint nodes and their ancestors, and its inverse bind matrices.
  std::shared_ptr<const tinygltf::Model> looks;
  std::vector<std::string> left_out;  // what the reader could not carry, a line each
};

// The file at `path`, a GLB when `binary`: every triangle primitive of every mesh that the
// default scene reaches (the first scene when none is named; every mesh, untransformed, when the
// file has no scene), its positions and normals taken through its node's world transform (the
// winding turned where the transform mirrors). Points and lines are skipped, as they have no
// surface; triangle strips and fans are bad input. Each glTF vertex gives the corner tables an
// entry of its NORMAL, TEXCOORD_0 and TEXCOORD_1 (float, or normalized unsigned byte or short; v
// from the image's top, glTF's origin, made 1 - v, from its bottom as in OBJ and PLY; each set
// with the KHR_texture_transform of the material's first texture that reads it, the base colour
// texture first, applied) and COLOR_0 (RGB, alpha 1, or RGBA; the same types), and each primitive
// its material (names: the material's name, or "material_<i>" when it has none).
// KHR_mesh_quantization's integer positions, normals and texture coordinates, sparse accessors,
// EXT_meshopt_compression's views (gltf_meshopt.h) and KHR_draco_mesh_compression's primitives
// (gltf_draco.h) are read as their values. Morph targets are left out (the base shape is read),
// a line in `left_out` per mesh that has them. The points are joined where exactly equal
// (join_equal_points), so that the vertices a UV seam or a primitive boundary splits become one
// vertex whose corners disagree.
// Skins: when some mesh placed (at any level of detail) is skinned and each triangle primitive of
// a skinned mesh has JOINTS_0 and WEIGHTS_0 (u8 or u16 joints; float, or normalized u8 or u16
// weights), the skinned meshes are taken where they are, untransformed, as glTF ignores a skinned
// mesh's node transform, and each glTF vertex gives the corner tables its skin influences: its
// four heaviest joints of JOINTS_n/WEIGHTS_n, every set n (more than four influences are merged),
// renormalised. Several skins are merged into one (each node a joint once), and a mesh without a
// skin is placed by its node's transform, each vertex weighing 1 on that node, which joins the skin
// bound where it stands; two skins that bind a node differently, or a node's transform that cannot
// be inverted, leave the skin out. The skeleton's animations come too: each channel that turns,
// moves or scales one of its nodes, with its sampler's times and values (glTF's types,
// KHR_mesh_quantization's integers included, read as floats); an animation that loses a channel (of
// another node, of morph target weights, without a sampler, or whose sampler cannot be read or
// whose times do not increase) gets a line in `left_out`. A skin left out (those cases, or a
// skinned primitive without JOINTS_0 and WEIGHTS_0) gets a line saying why, and every mesh is
// placed by its node's transform; the animations are then left out, in one line. A joint outside
// the skin's range, or a skin naming a node that does not exist, is bad input. Throws Io_error
// (unreadable input, "<path>: <cause>") for a file tinygltf cannot load (malformed JSON or GLB, a
// buffer file missing), a required extension other than those three and KHR_texture_transform,
// compressed data that do not decode, an accessor or index out of range, a position, normal,
// texture coordinate or colour that is not finite, and for a buffer file outside the asset folder
// (Asset_folder.h: `asset_root`, or the file's folder when empty), whose message names the uri and
// nothing of the file it leads to. A node's MSFT_lod is not followed: this is the finest level
// (read_gltf_levels reads them all).
Gltf_soup read_gltf(const std::string& path, bool binary, const std::string& asset_root = {});

// The levels of detail of the file at `path`, finest first, each read as read_gltf reads the file,
// all sharing one `looks`. Level 0 is what read_gltf reads. Level k puts, in place of each node
// the scene reaches that carries MSFT_lod (as gltf_bytes writes it), the k-th node its `ids` name,
// or the last one when it names fewer: that node goes under the same parent, with its own
// transform and children. Without MSFT_lod, one level. Throws as read_gltf does, and for an
// MSFT_lod without an array `ids`, or whose ids name a node that does not exist or has no mesh.
std::vector<Gltf_soup> read_gltf_levels(const std::string& path, bool binary,
                                        const std::string& asset_root = {});

// The bytes of a glTF file (GLB when `binary`) holding `levels`, each a mesh of its own and a node
// holding it: one vertex per wedge (Wedge_mesh.h), one primitive per material in the order of the
// material indices. A corner without a value gets 0, or white for a colour, as glTF has no "none";
// texture coordinates are written with v made 1 - v, as glTF counts it from the image's top. A
// second set of texture coordinates is TEXCOORD_1, and comes with a TEXCOORD_0 (of zeros when the
// mesh has no first set), as glTF numbers the sets without a gap.
// `encoding` says how the vertices are stored:
// - float32: float positions, normals, texture coordinates and RGBA colours (glTF has no
//   doubles), u32 indices.
// - quantized (KHR_mesh_quantization, required): the triangles and wedges in cache_ordered's order
//   (Wedge_mesh.h), as gltfpack writes them; positions as u16 steps of 1/65535 of the level's
//   largest bounding-box side, the level's node translated to the box's lowest corner and scaled
//   by the step; unit normals as normalized i8; each set of texture coordinates as normalized u16
//   when every one lies in [0, 1], normalized i16 when every one lies in [-1, 1], float otherwise;
//   colours as normalized u8; u16 indices when the level has at most 65535 vertices, u32
//   otherwise. Each vertex attribute's elements padded to 4 bytes.
// - meshopt: the quantized views compressed by meshoptimizer (EXT_meshopt_compression, required;
//   encode_meshopt_views), their uncompressed layout in a fallback buffer without data.
// The scene holds the first level's node; with more than one level, that node carries MSFT_lod (the
// extension Microsoft and Babylon.js read; used, not required, so that other viewers show the first
// level) naming the other levels' nodes in order, and extras.MSFT_screencoverage their screen
// coverages, one per level. Materials, shared by the levels: those of `materials.gltf` when the
// mesh was read from glTF, passed through with their textures, samplers and images (an image the
// input held is embedded, an image file is named by its path relative to `output_folder` when it
// lies in that folder, and embedded otherwise, or left out with a line in `left_out` when it cannot
// be read or is neither a PNG nor a JPEG image: the file names nothing outside its folder);
// otherwise those of obj_material_looks (obj_material_looks.h), their diffuse maps embedded as base
// colour textures when the meshes have texture coordinates, and `left_out` gets a line for each map
// left out. A .gltf file holds its buffer, embedded images included, as a base64 data URI.
std::string gltf_bytes(const std::vector<Lod_level>& levels, bool binary, Gltf_encoding encoding,
                       const Material_references& materials, const std::string& output_folder,
                       std::vector<std::string>& left_out);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_IO_H
