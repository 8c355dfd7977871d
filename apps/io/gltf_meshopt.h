// EXT_meshopt_compression, which gltfpack's -c output and other glTF pipelines write: each
// compressed bufferView is decoded by Debian's meshoptimizer before the reader looks at it, and
// encoded by it for the writer.
#ifndef CGAL_POLICIES_IO_GLTF_MESHOPT_H
#define CGAL_POLICIES_IO_GLTF_MESHOPT_H

#include <nlohmann/json_fwd.hpp>

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

// Compresses the vertex attribute views (mode ATTRIBUTES, each element a multiple of 4 bytes) and
// triangle index views (mode TRIANGLES) of `model`, whose views are all in buffer 0, with
// meshoptimizer's encoders, as gltfpack -c does: the compressed bytes go to buffer 0, aligned to
// 4 bytes, and each view is moved into a new buffer 1, the fallback the extension names, which
// holds no data (so EXT_meshopt_compression must be required). Other views (images) stay in
// buffer 0 as they are. Returns what tinygltf 2.7 cannot write, for with_meshopt_extensions: the
// views' extension objects and the fallback buffer.
nlohmann::json encode_meshopt_views(tinygltf::Model& model);

// The bytes of the glTF file (a GLB when `binary`) that tinygltf 2.7 wrote for a model
// encode_meshopt_views compressed, with `extensions`, its result, in the JSON.
std::string with_meshopt_extensions(std::string bytes, bool binary,
                                    const nlohmann::json& extensions);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_MESHOPT_H
