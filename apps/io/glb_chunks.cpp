#include "glb_chunks.h"

#include "Io_error.h"

#include <algorithm>
#include <cstring>

namespace cgal_policies {
namespace io {

std::uint32_t glb_word(const std::string& bytes, std::size_t at) {
  std::uint32_t word = 0;
  std::memcpy(&word, bytes.data() + at, 4);
  return word;
}

void append_glb_word(std::string& bytes, std::uint32_t word) {
  bytes.append(reinterpret_cast<const char*>(&word), 4);
}

void check_glb_chunks(const std::string& path, const std::string& bytes) {
  // Shorter than the header and one chunk header: tinygltf refuses it with its own cause.
  if (bytes.size() < 20) return;
  const std::size_t length = std::min<std::size_t>(glb_word(bytes, 8), bytes.size());
  for (std::size_t at = 12; at + 8 <= length;) {
    const std::size_t chunk = glb_word(bytes, at);
    if (chunk > length - at - 8)
      throw Io_error(Io_error::Kind::unreadable_input,
                     path + ": cannot parse: the GLB chunk at byte " + std::to_string(at) +
                         " reaches past the end of the file");
    at += 8 + chunk;
  }
}

}  // namespace io
}  // namespace cgal_policies
