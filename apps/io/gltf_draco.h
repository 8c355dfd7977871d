// KHR_draco_mesh_compression, which gltf-pipeline, glTF Transform and Blender write: each
// compressed primitive is decoded by Debian's Draco before the reader looks at it.
#ifndef CGAL_POLICIES_IO_GLTF_DRACO_H
#define CGAL_POLICIES_IO_GLTF_DRACO_H

#include <string>

namespace tinygltf {
class Model;
}

namespace cgal_policies {
namespace io {

// The bytes of a glTF file (a GLB when `binary`) that tinygltf 2.7 can load: it refuses a
// primitive whose indices accessor has no bufferView, as a Draco primitive's may have (its indices
// are in the compressed data), so each such accessor is pointed at its primitive's Draco view,
// which decode_draco_primitives replaces. The bytes as they are when no accessor needs it or the
// file does not parse (tinygltf then says why).
std::string with_loadable_draco_indices(std::string bytes, bool binary);

// Decodes the Draco mesh of every triangle primitive of `model` that has the
// KHR_draco_mesh_compression extension, and gives its indices accessor (made when it has none)
// and the accessors of its POSITION, NORMAL, TEXCOORD_0, TEXCOORD_1, COLOR_0, JOINTS_0/1 and
// WEIGHTS_0/1 (the Draco attributes the extension names by unique id) a buffer of their own holding
// the decoded values, in the accessor's component type (u32 for the indices), so that they read as
// plain data. The other attributes stay without data, as the reader skips them. Throws Io_error
// (unreadable input,
// "<path>: <cause>") when the compressed bytes are out of range or do not decode, or when what
// they decode to does not match the accessors.
void decode_draco_primitives(const std::string& path, tinygltf::Model& model);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_DRACO_H
