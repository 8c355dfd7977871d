#include "glb_chunks.h"

#include "Io_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace cgal_policies {
namespace io {
namespace {

// The 32-bit word at byte `at` of `bytes` (GLB is little-endian, as every target here is).
std::uint32_t glb_word(const std::string& bytes, std::size_t at) {
  std::uint32_t word = 0;
  std::memcpy(&word, bytes.data() + at, 4);
  return word;
}

void append_glb_word(std::string& bytes, std::uint32_t word) {
  bytes.append(reinterpret_cast<const char*>(&word), 4);
}

}  // namespace

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

std::string with_edited_json(std::string bytes, bool binary,
                             const std::function<bool(nlohmann::json&)>& edit) {
  // A GLB: a 12-byte header, then the JSON chunk (length, type, text), then the rest.
  std::size_t json_begin = 0, json_size = bytes.size();
  if (binary) {
    if (bytes.size() < 20) return bytes;
    json_begin = 20;
    json_size = glb_word(bytes, 12);
    if (json_size > bytes.size() - json_begin) return bytes;
  }
  nlohmann::json gltf =
      nlohmann::json::parse(bytes.begin() + std::ptrdiff_t(json_begin),
                            bytes.begin() + std::ptrdiff_t(json_begin + json_size), nullptr, false);
  if (!gltf.is_object() || !edit(gltf)) return bytes;
  std::string text = gltf.dump();
  if (!binary) return text;
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::string glb = bytes.substr(0, 8);
  const std::string rest = bytes.substr(json_begin + json_size);
  append_glb_word(glb, std::uint32_t(20 + text.size() + rest.size()));
  append_glb_word(glb, std::uint32_t(text.size()));
  glb += bytes.substr(16, 4);  // "JSON"
  return glb + text + rest;
}

}  // namespace io
}  // namespace cgal_policies
