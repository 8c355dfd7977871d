// The GLB container around a binary glTF's JSON: a 12-byte header, then chunks of a length word,
// a type word and their bytes. tinygltf 2.7 reads it, with one gap that check_glb_chunks closes.
#ifndef CGAL_POLICIES_IO_GLB_CHUNKS_H
#define CGAL_POLICIES_IO_GLB_CHUNKS_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace cgal_policies {
namespace io {

// The 32-bit word at byte `at` of `bytes` (GLB is little-endian, as every target here is).
std::uint32_t glb_word(const std::string& bytes, std::size_t at);

// Appends `word` to `bytes` as GLB stores it.
void append_glb_word(std::string& bytes, std::uint32_t word);

// Throws Io_error (unreadable input, "<path>: cannot parse: ...") when a chunk of the GLB `bytes`
// reaches past the length its header declares or past the end of the bytes. tinygltf 2.7 leaves
// the BIN chunk's own 8-byte header out of that check, and so reads up to 8 bytes past the end.
void check_glb_chunks(const std::string& path, const std::string& bytes);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLB_CHUNKS_H
