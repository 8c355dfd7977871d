// The GLB container around a binary glTF's JSON: a 12-byte header, then chunks of a length word,
// a type word and their bytes. tinygltf 2.7 reads it, with one gap that check_glb_chunks closes;
// with_edited_json changes the JSON of a file, GLB or not, before tinygltf reads it.
#ifndef CGAL_POLICIES_IO_GLB_CHUNKS_H
#define CGAL_POLICIES_IO_GLB_CHUNKS_H

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>

namespace cgal_policies {
namespace io {

// Throws Io_error (unreadable input, "<path>: cannot parse: ...") when a chunk of the GLB `bytes`
// reaches past the length its header declares or past the end of the bytes. tinygltf 2.7 leaves
// the BIN chunk's own 8-byte header out of that check, and so reads up to 8 bytes past the end.
void check_glb_chunks(const std::string& path, const std::string& bytes);

// The bytes of a glTF file (a GLB when `binary`) whose JSON `edit` changed, a GLB's other chunks
// kept after its new JSON chunk; `edit` returns whether it changed anything. The bytes as they are
// when the JSON does not parse or is not an object (tinygltf then says why), or when `edit`
// changes nothing.
std::string with_edited_json(std::string bytes, bool binary,
                             const std::function<bool(nlohmann::json&)>& edit);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLB_CHUNKS_H
