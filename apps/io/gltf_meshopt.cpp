#include "gltf_meshopt.h"

#include "Io_error.h"
#include "glb_chunks.h"

#include <meshoptimizer.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, path + ": " + cause);
}

std::size_t whole_number(const tinygltf::Value& object, const char* key, std::size_t otherwise) {
  if (!object.Has(key)) return otherwise;
  const double value = object.Get(key).GetNumberAsDouble();
  return value >= 0 && value < 1e15 ? std::size_t(value) : std::size_t(-1);
}

std::string text(const tinygltf::Value& object, const char* key, const char* otherwise) {
  return object.Has(key) && object.Get(key).IsString() ? object.Get(key).Get<std::string>()
                                                       : otherwise;
}

// The decoded bytes of a view's compressed data, as the extension describes it.
std::vector<unsigned char> decoded(const std::string& path, const tinygltf::Model& model,
                                   const tinygltf::Value& compression, const std::string& name) {
  const std::size_t buffer = whole_number(compression, "buffer", std::size_t(-1));
  const std::size_t offset = whole_number(compression, "byteOffset", 0);
  const std::size_t length = whole_number(compression, "byteLength", std::size_t(-1));
  const std::size_t stride = whole_number(compression, "byteStride", 0);
  const std::size_t count = whole_number(compression, "count", std::size_t(-1));
  if (buffer >= model.buffers.size() || offset > model.buffers[buffer].data.size() ||
      length > model.buffers[buffer].data.size() - offset)
    fail(path, name + ": its compressed bytes reach past their buffer");
  // Each element takes at least a bit of the compressed bytes: a larger count is forged.
  if (stride == 0 || stride > 256 || count > 8 * length + 1024)
    fail(path, name + ": a compressed view of " + std::to_string(count) + " elements of " +
                   std::to_string(stride) + " bytes in " + std::to_string(length) + " bytes");
  std::vector<unsigned char> bytes(count * stride);
  const unsigned char* source = model.buffers[buffer].data.data() + offset;
  const std::string mode = text(compression, "mode", "");
  int status = -1;
  if (mode == "ATTRIBUTES" && stride % 4 == 0)
    status = meshopt_decodeVertexBuffer(bytes.data(), count, stride, source, length);
  else if (mode == "TRIANGLES" && (stride == 2 || stride == 4))
    status = meshopt_decodeIndexBuffer(bytes.data(), count, stride, source, length);
  else if (mode == "INDICES" && (stride == 2 || stride == 4))
    status = meshopt_decodeIndexSequence(bytes.data(), count, stride, source, length);
  else
    fail(path, name + ": unsupported compression mode '" + mode + "' for " +
                   std::to_string(stride) + "-byte elements");
  if (status != 0) fail(path, name + ": its compressed bytes do not decode");
  const std::string filter = text(compression, "filter", "NONE");
  if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
    meshopt_decodeFilterOct(bytes.data(), count, stride);
  else if (filter == "QUATERNION" && stride == 8)
    meshopt_decodeFilterQuat(bytes.data(), count, stride);
  else if (filter == "EXPONENTIAL" && stride % 4 == 0)
    meshopt_decodeFilterExp(bytes.data(), count, stride);
  else if (filter != "NONE")
    fail(path, name + ": unsupported filter '" + filter + "'");
  return bytes;
}

std::size_t aligned_to_4(std::size_t size) { return (size + 3) / 4 * 4; }

// `count` indices of `stride` bytes (2 or 4), a triangle list, as meshopt_encodeIndexBuffer's
// mode TRIANGLES encodes them.
std::vector<unsigned char> encoded_triangles(const unsigned char* bytes, std::size_t count,
                                             std::size_t stride) {
  std::vector<unsigned> indices(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (stride == 4) {
      std::memcpy(&indices[i], bytes + 4 * i, 4);
      continue;
    }
    std::uint16_t index = 0;
    std::memcpy(&index, bytes + 2 * i, 2);
    indices[i] = index;
  }
  const std::size_t vertices =
      indices.empty() ? 0 : std::size_t(*std::max_element(indices.begin(), indices.end())) + 1;
  std::vector<unsigned char> encoded(meshopt_encodeIndexBufferBound(count, vertices));
  encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), count));
  return encoded;
}

std::vector<unsigned char> encoded_attributes(const unsigned char* bytes, std::size_t count,
                                              std::size_t stride) {
  std::vector<unsigned char> encoded(meshopt_encodeVertexBufferBound(count, stride));
  encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), bytes, count, stride));
  return encoded;
}

}  // namespace

nlohmann::json encode_meshopt_views(tinygltf::Model& model) {
  // A view's element size, when it has no byteStride: its accessor's (one per view, or an index
  // view's several, of one type).
  std::vector<std::size_t> element_size(model.bufferViews.size(), 0);
  for (const tinygltf::Accessor& accessor : model.accessors)
    if (accessor.bufferView >= 0)
      element_size[std::size_t(accessor.bufferView)] =
          std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType)) *
                      tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)));
  const std::vector<unsigned char> source = std::move(model.buffers[0].data);
  std::vector<unsigned char>& packed = model.buffers[0].data;
  packed.clear();
  nlohmann::json views = nlohmann::json::object();
  std::size_t fallback_length = 0;
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const unsigned char* bytes = source.data() + view.byteOffset;
    packed.resize(aligned_to_4(packed.size()), 0);
    const bool attributes = view.target == TINYGLTF_TARGET_ARRAY_BUFFER;
    if (!attributes && view.target != TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER) {
      view.byteOffset = packed.size();
      packed.insert(packed.end(), bytes, bytes + view.byteLength);
      continue;
    }
    const std::size_t stride = view.byteStride > 0 ? view.byteStride : element_size[v];
    const std::size_t count = view.byteLength / stride;
    const std::vector<unsigned char> encoded = attributes ? encoded_attributes(bytes, count, stride)
                                                          : encoded_triangles(bytes, count, stride);
    views[std::to_string(v)] = {{"buffer", 0},
                                {"byteOffset", packed.size()},
                                {"byteLength", encoded.size()},
                                {"byteStride", stride},
                                {"count", count},
                                {"mode", attributes ? "ATTRIBUTES" : "TRIANGLES"}};
    packed.insert(packed.end(), encoded.begin(), encoded.end());
    fallback_length = aligned_to_4(fallback_length);
    view.buffer = 1;
    view.byteOffset = fallback_length;
    fallback_length += view.byteLength;
  }
  model.buffers.resize(2);
  return {{"bufferViews", views},
          {"fallback",
           {{"byteLength", fallback_length},
            {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}};
}

std::string with_meshopt_extensions(std::string bytes, bool binary,
                                    const nlohmann::json& extensions) {
  return with_edited_json(std::move(bytes), binary, [&extensions](nlohmann::json& gltf) {
    for (const auto& [view, compression] : extensions["bufferViews"].items())
      gltf["bufferViews"][std::stoul(view)]["extensions"]["EXT_meshopt_compression"] = compression;
    // tinygltf gave the fallback buffer an empty data URI; it has no uri at all.
    gltf["buffers"][1] = extensions["fallback"];
    return true;
  });
}

std::string with_loadable_fallback_buffers(std::string bytes, bool binary) {
  if (bytes.find("\"fallback\"") == std::string::npos) return bytes;
  return with_edited_json(std::move(bytes), binary, [](nlohmann::json& gltf) {
    if (!gltf.contains("buffers") || !gltf["buffers"].is_array()) return false;
    bool edited = false;
    for (nlohmann::json& buffer : gltf["buffers"]) {
      const nlohmann::json* fallback =
          buffer.is_object() && buffer.contains("extensions") ? &buffer["extensions"] : nullptr;
      if (!fallback || !fallback->is_object() || !fallback->contains("EXT_meshopt_compression") ||
          (*fallback)["EXT_meshopt_compression"].value("fallback", false) != true)
        continue;
      buffer["uri"] = "data:application/octet-stream;base64,AAAAAA==";
      buffer["byteLength"] = 4;
      edited = true;
    }
    return edited;
  });
}

void decode_meshopt_views(const std::string& path, tinygltf::Model& model) {
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const auto compression = view.extensions.find("EXT_meshopt_compression");
    if (compression == view.extensions.end()) continue;
    std::vector<unsigned char> bytes =
        decoded(path, model, compression->second, "bufferView " + std::to_string(v));
    view.byteLength = bytes.size();
    view.byteOffset = 0;
    view.buffer = int(model.buffers.size());
    view.extensions.erase(compression);
    model.buffers.emplace_back();
    model.buffers.back().data = std::move(bytes);
  }
}

}  // namespace io
}  // namespace cgal_policies
