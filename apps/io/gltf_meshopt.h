// EXT_meshopt_compression, which gltfpack's -c output and other glTF pipelines write: each
// compressed bufferView is decoded by Debian's meshoptimizer before the reader looks at it.
#ifndef CGAL_POLICIES_IO_GLTF_MESHOPT_H
#define CGAL_POLICIES_IO_GLTF_MESHOPT_H

#include <string>

namespace tinygltf {
class Model;
}

namespace cgal_policies {
namespace io {

// The bytes of a glTF file (a GLB when `binary`) that tinygltf 2.7 can load: it cannot take
// EXT_meshopt_compression's fallback buffers, which have no data (it copies a GLB's binary chunk
// into them, or refuses a .gltf's for its missing uri), so each gets 4 bytes of its own as a data
// URI; decode_meshopt_views points every view away from it. The bytes as they are when the file
// has no fallback buffer or does not parse (tinygltf then says why).
std::string with_loadable_fallback_buffers(std::string bytes, bool binary);

// Decodes every bufferView of `model` that has the EXT_meshopt_compression extension (modes
// ATTRIBUTES, TRIANGLES and INDICES; filters NONE, OCTAHEDRAL, QUATERNION and EXPONENTIAL) into a
// buffer of its own, and points the view at it, so that its accessors read plain data. Throws
// Io_error (unreadable input, "<path>: <cause>") when a view's compressed bytes are out of range
// or do not decode.
void decode_meshopt_views(const std::string& path, tinygltf::Model& model);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_MESHOPT_H
