#include "gltf_draco.h"

#include "Io_error.h"
#include "glb_chunks.h"

#include <draco/compression/decode.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, path + ": " + cause);
}

// The attributes the reader reads; the others keep no data.
const std::array<std::string, 9> kReadAttributes = {"POSITION",  "NORMAL",     "TEXCOORD_0",
                                                    "COLOR_0",   "TEXCOORD_1", "JOINTS_0",
                                                    "WEIGHTS_0", "JOINTS_1",   "WEIGHTS_1"};

// The member `key` of `object`, or null when `object` is no object or has no such member.
const nlohmann::json* member(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto found = object.find(key);
  return found == object.end() ? nullptr : &*found;
}

// The whole number at `key` of `object`, or -1 when there is none.
int index_at(const tinygltf::Value& object, const std::string& key) {
  if (!object.Has(key) || !object.Get(key).IsNumber()) return -1;
  const double value = object.Get(key).GetNumberAsDouble();
  return value >= 0 && value < 2147483647.0 ? int(value) : -1;
}

// Stores `bytes` as a buffer and a view of their own, and returns the view.
int append_view(tinygltf::Model& model, std::vector<unsigned char> bytes) {
  tinygltf::BufferView view;
  view.buffer = int(model.buffers.size());
  view.byteLength = bytes.size();
  model.buffers.emplace_back();
  model.buffers.back().data = std::move(bytes);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

// Each point's value of `attribute`, converted by Draco to T, `components` per point, as bytes;
// empty when a value does not convert.
template <typename T>
std::vector<unsigned char> converted(const draco::PointAttribute& attribute, std::uint32_t points,
                                     int components) {
  std::vector<T> values(std::size_t(points) * std::size_t(components));
  for (std::uint32_t p = 0; p < points; ++p)
    if (!attribute.ConvertValue<T>(attribute.mapped_index(draco::PointIndex(p)),
                                   std::int8_t(components), &values[std::size_t(p) * components]))
      return {};
  const auto* first = reinterpret_cast<const unsigned char*>(values.data());
  return std::vector<unsigned char>(first, first + values.size() * sizeof(T));
}

// The Draco mesh in the bufferView the extension names.
std::unique_ptr<draco::Mesh> decoded_mesh(const std::string& path, const tinygltf::Model& model,
                                          const tinygltf::Value& draco, const std::string& name) {
  const int index = index_at(draco, "bufferView");
  if (index < 0 || std::size_t(index) >= model.bufferViews.size())
    fail(path, name + ": its Draco bufferView does not exist");
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(index)];
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
      view.byteOffset > model.buffers[std::size_t(view.buffer)].data.size() ||
      view.byteLength > model.buffers[std::size_t(view.buffer)].data.size() - view.byteOffset)
    fail(path, name + ": its Draco bufferView reaches past its buffer");
  draco::DecoderBuffer bytes;
  bytes.Init(reinterpret_cast<const char*>(model.buffers[std::size_t(view.buffer)].data.data() +
                                           view.byteOffset),
             view.byteLength);
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&bytes);
  if (!mesh.ok() || !mesh.value())
    fail(path, name + ": its Draco data do not decode (" + mesh.status().error_msg_string() + ")");
  return std::move(mesh).value();
}

// Gives accessor `index` the values of the Draco attribute whose unique id is `id`, one per point
// of `mesh`.
void decode_attribute(const std::string& path, tinygltf::Model& model, const draco::Mesh& mesh,
                      int index, int id, const std::string& name) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(path, name + ": accessor " + std::to_string(index) + " does not exist");
  tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(std::uint32_t(id));
  if (!attribute) fail(path, name + ": Draco has no attribute " + std::to_string(id));
  const int components = tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type));
  if (components != attribute->num_components())
    fail(path, name + ": Draco's attribute has " + std::to_string(attribute->num_components()) +
                   " components, its accessor " + std::to_string(components));
  if (accessor.count != mesh.num_points())
    fail(path, name + ": Draco decodes " + std::to_string(mesh.num_points()) +
                   " points, its accessor declares " + std::to_string(accessor.count));
  // A forged mapping could be shorter than the points it maps.
  if (!attribute->is_mapping_identity() && attribute->indices_map_size() < mesh.num_points())
    fail(path, name + ": Draco maps fewer points than it has");
  std::vector<unsigned char> bytes;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      bytes = converted<std::int8_t>(*attribute, mesh.num_points(), components);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      bytes = converted<std::uint8_t>(*attribute, mesh.num_points(), components);
      break;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      bytes = converted<std::int16_t>(*attribute, mesh.num_points(), components);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      bytes = converted<std::uint16_t>(*attribute, mesh.num_points(), components);
      break;
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      bytes = converted<float>(*attribute, mesh.num_points(), components);
      break;
    default:
      fail(path, name + ": unsupported component type for Draco data");
  }
  if (bytes.empty() && mesh.num_points() > 0)
    fail(path, name + ": Draco's values do not fit its accessor's component type");
  accessor.bufferView = append_view(model, std::move(bytes));
  accessor.byteOffset = 0;
}

// Gives the primitive's indices accessor (a new one when it has none) the mesh's triangles.
void decode_indices(const std::string& path, tinygltf::Model& model, const draco::Mesh& mesh,
                    tinygltf::Primitive& primitive, const std::string& name) {
  if (primitive.indices < 0) {
    primitive.indices = int(model.accessors.size());
    model.accessors.emplace_back();
    model.accessors.back().type = TINYGLTF_TYPE_SCALAR;
    model.accessors.back().count = std::size_t(mesh.num_faces()) * 3;
  }
  if (std::size_t(primitive.indices) >= model.accessors.size())
    fail(path, name + ": accessor " + std::to_string(primitive.indices) + " does not exist");
  tinygltf::Accessor& accessor = model.accessors[std::size_t(primitive.indices)];
  if (accessor.count != std::size_t(mesh.num_faces()) * 3)
    fail(path, name + ": Draco decodes " + std::to_string(mesh.num_faces()) +
                   " triangles, its accessor declares " + std::to_string(accessor.count) +
                   " indices");
  std::vector<std::uint32_t> indices;
  indices.reserve(accessor.count);
  for (std::uint32_t f = 0; f < mesh.num_faces(); ++f)
    for (const draco::PointIndex& point : mesh.face(draco::FaceIndex(f)))
      indices.push_back(point.value());
  const auto* first = reinterpret_cast<const unsigned char*>(indices.data());
  accessor.bufferView =
      append_view(model, std::vector<unsigned char>(first, first + indices.size() * 4));
  accessor.byteOffset = 0;
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  accessor.normalized = false;
}

}  // namespace

std::string with_loadable_draco_indices(std::string bytes, bool binary) {
  if (bytes.find("KHR_draco_mesh_compression") == std::string::npos) return bytes;
  return with_edited_json(std::move(bytes), binary, [](nlohmann::json& gltf) {
    const nlohmann::json* meshes = member(gltf, "meshes");
    if (!meshes || !meshes->is_array() || !member(gltf, "accessors")) return false;
    nlohmann::json& accessors = gltf["accessors"];
    bool edited = false;
    for (const nlohmann::json& mesh : *meshes) {
      const nlohmann::json* primitives = member(mesh, "primitives");
      if (!primitives || !primitives->is_array()) continue;
      for (const nlohmann::json& primitive : *primitives) {
        const nlohmann::json* extensions = member(primitive, "extensions");
        const nlohmann::json* draco =
            extensions ? member(*extensions, "KHR_draco_mesh_compression") : nullptr;
        const nlohmann::json* view = draco ? member(*draco, "bufferView") : nullptr;
        const nlohmann::json* indices = member(primitive, "indices");
        if (!view || !indices || !indices->is_number_unsigned() || !accessors.is_array() ||
            indices->get<std::size_t>() >= accessors.size())
          continue;
        nlohmann::json& accessor = accessors[indices->get<std::size_t>()];
        if (!accessor.is_object() || accessor.contains("bufferView")) continue;
        accessor["bufferView"] = *view;
        edited = true;
      }
    }
    return edited;
  });
}

void decode_draco_primitives(const std::string& path, tinygltf::Model& model) {
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
      const auto draco = primitive.extensions.find("KHR_draco_mesh_compression");
      // Points and lines are skipped by the reader, strips and fans refused: only triangles.
      if (draco == primitive.extensions.end() ||
          (primitive.mode >= 0 && primitive.mode != TINYGLTF_MODE_TRIANGLES))
        continue;
      const std::string name = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      const std::unique_ptr<draco::Mesh> mesh = decoded_mesh(path, model, draco->second, name);
      const tinygltf::Value none;
      const tinygltf::Value& ids =
          draco->second.Has("attributes") ? draco->second.Get("attributes") : none;
      for (const std::string& attribute : kReadAttributes) {
        const auto accessor = primitive.attributes.find(attribute);
        if (accessor == primitive.attributes.end()) continue;
        const int id = index_at(ids, attribute);
        if (id < 0) fail(path, name + ": " + attribute + " is not among its Draco attributes");
        decode_attribute(path, model, *mesh, accessor->second, id, name + " " + attribute);
      }
      decode_indices(path, model, *mesh, primitive, name + " indices");
      primitive.extensions.erase(draco);
    }
}

}  // namespace io
}  // namespace cgal_policies
