#include "gltf_io.h"

#include "Asset_folder.h"
#include "Io_error.h"
#include "Wedge_mesh.h"
#include "glb_chunks.h"
#include "gltf_draco.h"
#include "gltf_images.h"
#include "gltf_meshopt.h"
#include "obj_material_looks.h"

#include <CGAL/Bbox_3.h>
#include <tiny_gltf.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <vector>

namespace cgal_policies {
namespace io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, path + ": " + cause);
}

// tinygltf's messages end each cause with a newline: one line for the error.
std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::string line;
  for (char c : text) line += c == '\n' ? std::string("; ") : std::string(1, c);
  return line;
}

// Keeps an image's bytes as the file holds them: nothing here looks at pixels, and a glTF file
// written from this one embeds them unchanged (stb would decode them, and re-encode on writing).
bool keep_image_bytes(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// glTF's texture coordinates start at the image's top left corner, v downward; the mesh's, as
// OBJ's and PLY's, at its bottom left, v upward. The change is its own inverse.
std::array<double, 2> texture_coordinates_of_gltf(double u, double v) { return {u, 1 - v}; }

// ---- Reading ---------------------------------------------------------------------------------

// The extensions the reader decodes into plain geometry and texture coordinates.
const std::array<std::string, 4> kDecodedExtensions = {
    "KHR_mesh_quantization", "EXT_meshopt_compression", "KHR_draco_mesh_compression",
    "KHR_texture_transform"};

using Matrix = std::array<double, 16>;  // column-major, as glTF stores it
constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix product(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return c;
}

// The inverse of an affine transform; none when it flattens space.
std::optional<Matrix> affine_inverse(const Matrix& m) {
  const Eigen::Map<const Eigen::Matrix4d> transform(m.data());  // column-major, as glTF's
  if (!std::isnormal(transform.topLeftCorner<3, 3>().determinant())) return std::nullopt;
  Matrix inverse;
  Eigen::Map<Eigen::Matrix4d>(inverse.data()) =
      Eigen::Affine3d(transform).inverse(Eigen::Affine).matrix();
  return inverse;
}

// The node's matrix, or its translation * rotation * scale.
Matrix local_matrix(const tinygltf::Node& node) {
  Matrix m = kIdentity;
  if (node.matrix.size() == 16) {
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  if (node.rotation.size() == 4) {
    const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                 w = node.rotation[3];
    // The rotation matrix, column by column.
    // clang-format off
    m = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w),     2 * (x * z - y * w),     0,
         2 * (x * y - z * w),     1 - 2 * (x * x + z * z), 2 * (y * z + x * w),     0,
         2 * (x * z + y * w),     2 * (y * z - x * w),     1 - 2 * (x * x + y * y), 0,
         0,                       0,                       0,                       1};
    // clang-format on
  }
  if (node.scale.size() == 3)
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) m[col * 4 + row] *= node.scale[std::size_t(col)];
  if (node.translation.size() == 3)
    for (int row = 0; row < 3; ++row) m[12 + row] = node.translation[std::size_t(row)];
  return m;
}

struct Placed_mesh {
  int mesh;
  Matrix world;
  int skin;  // its node's, or -1
  int node;  // -1 for a file without scenes, whose meshes have none
};

// Deeper hierarchies are refused rather than risking the stack on a forged file.
constexpr std::size_t kMaxNodeDepth = 1000;

// The nodes that stand for `node` at each level of detail, finest first: itself, then the nodes
// its MSFT_lod names, each of which must hold a mesh; itself alone without the extension.
std::vector<int> lod_nodes(const std::string& path, const tinygltf::Model& model, int node) {
  std::vector<int> nodes = {node};
  const tinygltf::ExtensionMap& extensions = model.nodes[std::size_t(node)].extensions;
  const auto lod = extensions.find("MSFT_lod");
  if (lod == extensions.end()) return nodes;
  const std::string where = "node " + std::to_string(node) + "'s MSFT_lod";
  // Has() checks that the value is an object, which Get(key) asserts.
  if (!lod->second.Has("ids") || !lod->second.Get("ids").IsArray())
    fail(path, where + " has no array of node indices (ids)");
  const tinygltf::Value& ids = lod->second.Get("ids");
  for (std::size_t i = 0; i < ids.ArrayLen(); ++i) {
    const tinygltf::Value& id = ids.Get(int(i));
    if (!id.IsNumber()) fail(path, where + " names a node by something other than a number");
    const double index = id.GetNumberAsDouble();
    if (!(index >= 0 && index < double(model.nodes.size()) && index == std::floor(index))) {
      std::ostringstream text;
      text << index;
      fail(path, where + " names node " + text.str() + ", which does not exist");
    }
    if (model.nodes[std::size_t(index)].mesh < 0)
      fail(path, where + " names node " + std::to_string(int(index)) + ", which has no mesh");
    nodes.push_back(int(index));
  }
  return nodes;
}

// Which level of detail placed_meshes places: level 0 is the scene as it stands; at level k > 0,
// when `follow_lod`, each node carrying MSFT_lod gives way to the k-th node it names, or to its
// coarsest when it names fewer. `levels` gets the most levels a node reached offers.
struct Lod_walk {
  std::size_t level = 0;
  bool follow_lod = false;
  std::size_t levels = 1;
};

// `on_path` marks the node's ancestors, so that a cycle is found at once. A node standing in for
// another takes its place under the same parent, with its own transform and children.
void place_node(const std::string& path, const tinygltf::Model& model, int node,
                const Matrix& parent, std::vector<char>& on_path, std::size_t depth, Lod_walk& walk,
                std::vector<Placed_mesh>& placed) {
  if (node < 0 || std::size_t(node) >= model.nodes.size())
    fail(path, "node " + std::to_string(node) + " does not exist");
  if (depth > kMaxNodeDepth)
    fail(path, "the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
  int shown = node;
  if (walk.follow_lod) {
    const std::vector<int> stand_ins = lod_nodes(path, model, node);
    walk.levels = std::max(walk.levels, stand_ins.size());
    shown = stand_ins[std::min(walk.level, stand_ins.size() - 1)];
  }
  if (on_path[std::size_t(node)] || on_path[std::size_t(shown)])
    fail(path, "the node hierarchy has a cycle");
  const tinygltf::Node& n = model.nodes[std::size_t(shown)];
  const Matrix world = product(parent, local_matrix(n));
  if (n.mesh >= 0) placed.push_back({n.mesh, world, n.skin, shown});
  on_path[std::size_t(node)] = on_path[std::size_t(shown)] = 1;
  for (int child : n.children)
    place_node(path, model, child, world, on_path, depth + 1, walk, placed);
  on_path[std::size_t(node)] = on_path[std::size_t(shown)] = 0;
}

std::vector<Placed_mesh> placed_meshes(const std::string& path, const tinygltf::Model& model,
                                       Lod_walk& walk) {
  std::vector<Placed_mesh> placed;
  if (model.scenes.empty()) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
      placed.push_back({int(m), kIdentity, -1, -1});
    return placed;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (std::size_t(scene) >= model.scenes.size())
    fail(path, "scene " + std::to_string(scene) + " does not exist");
  std::vector<char> on_path(model.nodes.size(), 0);
  for (int node : model.scenes[std::size_t(scene)].nodes)
    place_node(path, model, node, kIdentity, on_path, 0, walk, placed);
  return placed;
}

// One component, normalized integers mapped onto [0, 1] or [-1, 1] as the glTF spec says.
double component(const unsigned char* at, int component_type, bool normalized) {
  const auto read = [at](auto value) {
    std::memcpy(&value, at, sizeof value);  // glTF is little-endian, as is every target here
    return value;
  };
  const auto scaled = [normalized](double value, double largest) {
    return normalized ? std::max(value / largest, -1.0) : value;
  };
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return scaled(read(std::int8_t()), 127);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return scaled(read(std::uint8_t()), 255);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return scaled(read(std::int16_t()), 32767);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return scaled(read(std::uint16_t()), 65535);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return read(std::uint32_t());
    default:
      return read(float());
  }
}

// What an accessor of an attribute may hold: its element type, its component types, and whether
// integers must be normalized (`normalized`), must not be (indices), or may be either
// (KHR_mesh_quantization's positions and texture coordinates).
struct Accessor_rule {
  enum class Integers { normalized, not_normalized, either };
  int type;
  std::vector<int> component_types;
  Integers integers;
};

// BufferView `index`, after checking that it exists.
const tinygltf::BufferView& buffer_view(const std::string& path, const tinygltf::Model& model,
                                        int index, const std::string& name) {
  if (index < 0 || std::size_t(index) >= model.bufferViews.size())
    fail(path, name + ": no bufferView");
  return model.bufferViews[std::size_t(index)];
}

// The bytes [offset, offset + size) of bufferView `index`, after checking that they are there.
const unsigned char* view_bytes(const std::string& path, const tinygltf::Model& model, int index,
                                std::size_t offset, std::size_t size, const std::string& name) {
  const tinygltf::BufferView& view = buffer_view(path, model, index, name);
  if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
      view.byteOffset > model.buffers[std::size_t(view.buffer)].data.size() ||
      view.byteLength > model.buffers[std::size_t(view.buffer)].data.size() - view.byteOffset)
    fail(path, name + ": its bufferView reaches past its buffer");
  if (offset > view.byteLength || size > view.byteLength - offset)
    fail(path, name + ": reaches past its bufferView");
  return model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + offset;
}

// The values of accessor `index`, `components` per element, after checking it against `rule` and
// that the file holds every element it declares; a sparse accessor's substitutions applied.
std::vector<double> accessor_values(const std::string& path, const tinygltf::Model& model,
                                    int index, const Accessor_rule& rule, const std::string& what) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    fail(path, what + ": accessor " + std::to_string(index) + " does not exist");
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
  const std::string name = what + " (accessor " + std::to_string(index) + ")";
  const std::vector<int>& allowed = rule.component_types;
  if (accessor.type != rule.type ||
      std::find(allowed.begin(), allowed.end(), accessor.componentType) == allowed.end())
    fail(path, name + ": unsupported element or component type");
  if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    if (rule.integers == Accessor_rule::Integers::normalized && !accessor.normalized)
      fail(path, name + ": integer values must be normalized");
    if (rule.integers == Accessor_rule::Integers::not_normalized && accessor.normalized)
      fail(path, name + ": indices cannot be normalized");
  }
  const std::size_t components =
      std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(rule.type)));
  const std::size_t size =
      std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType)));
  const std::size_t element = size * components;
  const std::size_t count = accessor.count;
  const auto read_elements = [&](const unsigned char* first, std::size_t stride, std::size_t n,
                                 std::vector<double>& values) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < components; ++c)
        values.push_back(
            component(first + i * stride + c * size, accessor.componentType, accessor.normalized));
  };
  std::vector<double> values;
  values.reserve(count * components);
  if (accessor.bufferView < 0) {
    // Only a sparse accessor may have no bufferView: its elements start at zero.
    if (!accessor.sparse.isSparse) fail(path, name + ": no bufferView");
    values.assign(count * components, 0.0);
  } else if (count > 0) {
    const std::size_t view_stride =
        std::size_t(buffer_view(path, model, accessor.bufferView, name).byteStride);
    const std::size_t stride = view_stride > 0 ? view_stride : element;
    if (stride < element ||
        count - 1 > (std::numeric_limits<std::size_t>::max() - element) / stride)
      fail(path, name + ": reaches past its bufferView");
    read_elements(view_bytes(path, model, accessor.bufferView, accessor.byteOffset,
                             (count - 1) * stride + element, name),
                  stride, count, values);
  }
  if (!accessor.sparse.isSparse) return values;
  // The sparse substitutions: `changed` indices, then as many elements, both tightly packed.
  const auto& sparse = accessor.sparse;
  const std::size_t changed = std::size_t(std::max(sparse.count, 0));
  const int index_type = sparse.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail(path, name + ": unsupported sparse index type");
  if (changed == 0 || changed > count) fail(path, name + ": sparse count out of range");
  const std::size_t index_size =
      std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(index_type)));
  const unsigned char* indices = view_bytes(path, model, sparse.indices.bufferView,
                                            std::size_t(std::max(sparse.indices.byteOffset, 0)),
                                            changed * index_size, name + " sparse indices");
  std::vector<double> substitutes;
  substitutes.reserve(changed * components);
  read_elements(view_bytes(path, model, sparse.values.bufferView,
                           std::size_t(std::max(sparse.values.byteOffset, 0)), changed * element,
                           name + " sparse values"),
                element, changed, substitutes);
  for (std::size_t i = 0; i < changed; ++i) {
    const double at = component(indices + i * index_size, index_type, false);
    if (at >= double(count))
      fail(path, name + ": sparse index " + std::to_string(std::size_t(at)) + " is out of range");
    std::copy_n(substitutes.begin() + std::ptrdiff_t(i * components), components,
                values.begin() + std::ptrdiff_t(std::size_t(at) * components));
  }
  return values;
}

void check_finite(const std::string& path, const std::vector<double>& values,
                  std::size_t components, const std::string& what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      fail(path, what + " of vertex " + std::to_string(i / components) + " is not finite");
}

// Applies `m` to the points (w = 1) or directions (w = 0) stored three by three in `values`.
void transform(const Matrix& m, double w, std::vector<double>& values) {
  for (std::size_t i = 0; i + 2 < values.size(); i += 3) {
    const double x = values[i], y = values[i + 1], z = values[i + 2];
    for (std::size_t row = 0; row < 3; ++row)
      values[i + row] = m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row] * w;
  }
}

double determinant3(const Matrix& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}

// The transform of normals under `m`: its 3 x 3 part's cofactor matrix (the inverse transpose
// times the determinant), turned to face outward when `m` mirrors.
Matrix normal_matrix(const Matrix& m) {
  const auto at = [&m](int row, int col) { return m[std::size_t(col * 4 + row)]; };
  const double sign = determinant3(m) < 0 ? -1 : 1;
  Matrix n{};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      const int r1 = (row + 1) % 3, r2 = (row + 2) % 3, c1 = (col + 1) % 3, c2 = (col + 2) % 3;
      n[std::size_t(col * 4 + row)] = sign * (at(r1, c1) * at(r2, c2) - at(r1, c2) * at(r2, c1));
    }
  return n;
}

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT, kByte = TINYGLTF_COMPONENT_TYPE_BYTE,
              kUnsignedByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              kShort = TINYGLTF_COMPONENT_TYPE_SHORT,
              kUnsignedShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
using Integers = Accessor_rule::Integers;

// What glTF allows for each attribute, and what KHR_mesh_quantization adds when the file uses it.
struct Attribute_rules {
  Accessor_rule position, normal, uv, indices;
  explicit Attribute_rules(bool quantized)
      : position{TINYGLTF_TYPE_VEC3,
                 quantized ? std::vector<int>{kFloat, kByte, kUnsignedByte, kShort, kUnsignedShort}
                           : std::vector<int>{kFloat},
                 Integers::either},
        normal{TINYGLTF_TYPE_VEC3,
               quantized ? std::vector<int>{kFloat, kByte, kShort} : std::vector<int>{kFloat},
               Integers::normalized},
        uv{TINYGLTF_TYPE_VEC2,
           quantized ? std::vector<int>{kFloat, kByte, kUnsignedByte, kShort, kUnsignedShort}
                     : std::vector<int>{kFloat, kUnsignedByte, kUnsignedShort},
           quantized ? Integers::either : Integers::normalized},
        indices{TINYGLTF_TYPE_SCALAR,
                {kUnsignedByte, kUnsignedShort, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                Integers::not_normalized} {}
  static Accessor_rule color(int type) {
    return {type, {kFloat, kUnsignedByte, kUnsignedShort}, Integers::normalized};
  }
  // JOINTS_n and WEIGHTS_n, as the core spec allows them (KHR_mesh_quantization adds none).
  static Accessor_rule joints() {
    return {TINYGLTF_TYPE_VEC4, {kUnsignedByte, kUnsignedShort}, Integers::not_normalized};
  }
  static Accessor_rule weights() {
    return {TINYGLTF_TYPE_VEC4, {kFloat, kUnsignedByte, kUnsignedShort}, Integers::normalized};
  }
};

bool uses(const tinygltf::Model& model, const std::string& extension) {
  return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) !=
         model.extensionsUsed.end();
}

// The texture coordinate set a texture reference reads: its KHR_texture_transform may name one,
// which overrides the reference's own.
template <class Texture_info>
int texture_set(const Texture_info& texture) {
  const auto found = texture.extensions.find("KHR_texture_transform");
  if (found != texture.extensions.end() && found->second.Has("texCoord"))
    return found->second.Get("texCoord").GetNumberAsInt();
  return texture.texCoord;
}

// The KHR_texture_transform of the first texture of `material` that reads texture coordinate set
// `set`, as the matrix it applies to them (in glTF's convention, before the v turn), rows of
// three; the identity without one. A set has one transform baked into it, so the other textures
// reading it are drawn without theirs.
std::array<double, 6> texture_transform(const tinygltf::Material& material, int set) {
  std::array<double, 6> m = {1, 0, 0, 0, 1, 0};
  const tinygltf::Value* transform = nullptr;
  bool found = false;
  for_each_texture(material, [&](const auto& texture) {
    if (found || texture.index < 0 || texture_set(texture) != set) return;
    found = true;
    const auto extension = texture.extensions.find("KHR_texture_transform");
    if (extension != texture.extensions.end()) transform = &extension->second;
  });
  if (!transform) return m;
  const tinygltf::Value& t = *transform;
  const auto pair = [&t](const char* key, double a, double b) {
    const tinygltf::Value& v = t.Get(key);
    return v.IsArray() && v.ArrayLen() == 2
               ? std::array<double, 2>{v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble()}
               : std::array<double, 2>{a, b};
  };
  const std::array<double, 2> offset = pair("offset", 0, 0), scale = pair("scale", 1, 1);
  const double rotation = t.Has("rotation") ? t.Get("rotation").GetNumberAsDouble() : 0;
  const double c = std::cos(rotation), s = std::sin(rotation);
  // translation * rotation * scale, as the extension defines them.
  return {c * scale[0], s * scale[1], offset[0], -s * scale[0], c * scale[1], offset[1]};
}

// The skin whose influences the soups carry: the skins of the meshes placed, merged into one.
struct Carried_skin {
  std::vector<int> joints;  // the nodes: the first skin's joints, then each next skin's new ones
  // By input skin: each of its joints' index in `joints`; empty for a skin no placed mesh has.
  std::vector<std::vector<std::uint16_t>> joint_of;
  std::vector<double> inverse_bind_matrices;  // 16 per joint; none when no skin has them
  int skeleton = -1;                          // the skins' common skeleton root, or none
  std::string name;                           // the first skin's
  // The joint of each node whose mesh has no skin: the node itself, its vertices weighing 1 on it.
  std::map<int, std::uint16_t> rigid_joint_of;
};

// Builds the soup primitive by primitive: a point for each glTF vertex a triangle uses, the
// corner tables an entry for each glTF vertex.
class Soup_builder {
  // The kinds of corner values, in the order of m_any.
  static constexpr std::size_t kKinds = 5;

 public:
  // `skin`: the skin whose influences the soup carries (carried_skin), or none.
  Soup_builder(const std::string& path, const tinygltf::Model& model,
               const std::optional<Carried_skin>& skin)
      : m_path(path),
        m_model(model),
        m_rules(uses(model, "KHR_mesh_quantization")),
        m_quantized(uses(model, "KHR_mesh_quantization")),
        m_skin(skin) {}

  // `mesh`: where the primitive's mesh is placed, for its skin influences.
  void add_primitive(const tinygltf::Primitive& primitive, const Matrix& world,
                     const Placed_mesh& mesh, const std::string& what) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP)
      return;
    if (mode != TINYGLTF_MODE_TRIANGLES)
      fail(m_path, what + ": triangle strips and fans are not supported");
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) fail(m_path, what + ": no POSITION");
    std::vector<double> positions =
        accessor_values(m_path, m_model, position->second, m_rules.position, what + " POSITION");
    check_finite(m_path, positions, 3, what + ": the position");
    const std::size_t vertices = positions.size() / 3;
    const bool moved = world != kIdentity;
    if (moved) transform(world, 1, positions);

    Corner_tables& tables = m_soup.corners;
    const std::array<std::size_t, kKinds> base = {tables.uvs.size(), tables.normals.size(),
                                                  tables.colors.size(), tables.second_uvs.size(),
                                                  tables.skins.size()};
    const std::array<bool, kKinds> with = {read_uvs(primitive, 0, vertices, what),
                                           read_normals(primitive, vertices, moved, world, what),
                                           read_colors(primitive, vertices, what),
                                           read_uvs(primitive, 1, vertices, what),
                                           read_skin(primitive, mesh, vertices, what)};
    const std::array<std::vector<std::vector<std::size_t>>*, kKinds> lists = {
        &tables.polygon_uvs, &tables.polygon_normals, &tables.polygon_colors,
        &tables.polygon_second_uvs, &tables.polygon_skins};

    const std::vector<std::size_t> corners = triangle_corners(primitive, vertices, what);
    if (primitive.material >= 0 && std::size_t(primitive.material) >= m_model.materials.size())
      fail(m_path, what + ": material " + std::to_string(primitive.material) + " does not exist");

    std::vector<std::size_t> point_of_vertex(vertices, Corner_tables::kNoEntry);
    // A mirroring transform turns the winding: two corners swap to keep the faces outward.
    const bool mirrored = moved && determinant3(world) < 0;
    for (std::size_t t = 0; t < corners.size(); t += 3) {
      std::vector<std::size_t> polygon;
      std::array<std::vector<std::size_t>, kKinds> entries;
      for (std::size_t k : {std::size_t(0), mirrored ? std::size_t(2) : std::size_t(1),
                            mirrored ? std::size_t(1) : std::size_t(2)}) {
        const std::size_t v = corners[t + k];
        if (point_of_vertex[v] == Corner_tables::kNoEntry) {
          point_of_vertex[v] = m_soup.points.size();
          m_soup.points.emplace_back(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
        }
        polygon.push_back(point_of_vertex[v]);
        for (std::size_t kind = 0; kind < kKinds; ++kind)
          entries[kind].push_back(with[kind] ? base[kind] + v : Corner_tables::kNoEntry);
      }
      m_soup.polygons.push_back(std::move(polygon));
      for (std::size_t kind = 0; kind < kKinds; ++kind)
        lists[kind]->push_back(std::move(entries[kind]));
      tables.polygon_materials.push_back(primitive.material >= 0 ? std::uint32_t(primitive.material)
                                                                 : Corner_tables::kNoMaterial);
    }
    for (std::size_t kind = 0; kind < kKinds; ++kind) m_any[kind] = m_any[kind] || with[kind];
  }

  // The soup, its points joined where they are equal; the corner lists of a kind no primitive
  // has are left empty, as the other readers leave them.
  Polygon_soup soup() && {
    Corner_tables& corners = m_soup.corners;
    if (!m_any[0]) corners.polygon_uvs.clear();
    if (!m_any[1]) corners.polygon_normals.clear();
    if (!m_any[2]) corners.polygon_colors.clear();
    if (!m_any[3]) corners.polygon_second_uvs.clear();
    if (!m_any[4]) corners.polygon_skins.clear();
    if (std::all_of(corners.polygon_materials.begin(), corners.polygon_materials.end(),
                    [](std::uint32_t m) { return m == Corner_tables::kNoMaterial; }))
      corners.polygon_materials.clear();
    else
      for (std::size_t i = 0; i < m_model.materials.size(); ++i)
        corners.material_names.push_back(m_model.materials[i].name.empty()
                                             ? "material_" + std::to_string(i)
                                             : m_model.materials[i].name);
    join_equal_points(m_soup);
    return std::move(m_soup);
  }

 private:
  // The corners of the primitive's triangles, as glTF vertex numbers.
  std::vector<std::size_t> triangle_corners(const tinygltf::Primitive& primitive,
                                            std::size_t vertices, const std::string& what) {
    std::vector<std::size_t> corners;
    if (primitive.indices < 0) {
      for (std::size_t v = 0; v < vertices; ++v) corners.push_back(v);
    } else {
      for (double index : accessor_values(m_path, m_model, primitive.indices, m_rules.indices,
                                          what + " indices")) {
        if (index >= double(vertices))
          fail(m_path, what + ": index " + std::to_string(std::size_t(index)) +
                           " is out of range (" + std::to_string(vertices) + " vertices)");
        corners.push_back(std::size_t(index));
      }
    }
    if (corners.size() % 3 != 0)
      fail(m_path, what + ": " + std::to_string(corners.size()) +
                       " corners, not a whole number of triangles");
    return corners;
  }

  // Texture coordinate set `set`, 0 or 1, into the corner table of that set.
  bool read_uvs(const tinygltf::Primitive& primitive, int set, std::size_t vertices,
                const std::string& what) {
    const std::string name = "TEXCOORD_" + std::to_string(set);
    const auto uv = primitive.attributes.find(name);
    if (uv == primitive.attributes.end()) return false;
    const std::vector<double> values =
        accessor_values(m_path, m_model, uv->second, m_rules.uv, what + " " + name);
    check_vertex_count(values.size() / 2, vertices, what + " " + name);
    check_finite(m_path, values, 2, what + ": the texture coordinate (" + name + ")");
    // The transform of the texture reading the set, baked in (the written materials leave it out).
    const std::array<double, 6> m =
        primitive.material >= 0 && std::size_t(primitive.material) < m_model.materials.size()
            ? texture_transform(m_model.materials[std::size_t(primitive.material)], set)
            : texture_transform(tinygltf::Material(), set);
    std::vector<std::array<double, 2>>& table =
        set == 0 ? m_soup.corners.uvs : m_soup.corners.second_uvs;
    for (std::size_t i = 0; i < values.size(); i += 2)
      table.push_back(texture_coordinates_of_gltf(m[0] * values[i] + m[1] * values[i + 1] + m[2],
                                                  m[3] * values[i] + m[4] * values[i + 1] + m[5]));
    return true;
  }

  bool read_normals(const tinygltf::Primitive& primitive, std::size_t vertices, bool moved,
                    const Matrix& world, const std::string& what) {
    const auto normal = primitive.attributes.find("NORMAL");
    if (normal == primitive.attributes.end()) return false;
    std::vector<double> values =
        accessor_values(m_path, m_model, normal->second, m_rules.normal, what + " NORMAL");
    check_vertex_count(values.size() / 3, vertices, what + " NORMAL");
    check_finite(m_path, values, 3, what + ": the normal");
    if (moved) transform(normal_matrix(world), 0, values);
    for (std::size_t i = 0; i < values.size(); i += 3) {
      Kernel::Vector_3 n(values[i], values[i + 1], values[i + 2]);
      const double length = std::sqrt(n.squared_length());
      // A scaled node scales its normals too, and quantized ones are a little off unit length.
      if ((moved || m_quantized) && length > 0) n = n / length;
      m_soup.corners.normals.push_back(n);
    }
    return true;
  }

  // RGB (alpha 1) or RGBA, as the accessor's type says.
  bool read_colors(const tinygltf::Primitive& primitive, std::size_t vertices,
                   const std::string& what) {
    const auto color = primitive.attributes.find("COLOR_0");
    if (color == primitive.attributes.end()) return false;
    const bool rgb = color->second >= 0 && std::size_t(color->second) < m_model.accessors.size() &&
                     m_model.accessors[std::size_t(color->second)].type == TINYGLTF_TYPE_VEC3;
    const std::size_t channels = rgb ? 3 : 4;
    const std::vector<double> values = accessor_values(
        m_path, m_model, color->second,
        Attribute_rules::color(rgb ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4), what + " COLOR_0");
    check_vertex_count(values.size() / channels, vertices, what + " COLOR_0");
    check_finite(m_path, values, channels, what + ": the colour");
    for (std::size_t i = 0; i < values.size(); i += channels)
      m_soup.corners.colors.push_back(
          {values[i], values[i + 1], values[i + 2], rgb ? 1.0 : values[i + 3]});
    return true;
  }

  // The influences of JOINTS_n and WEIGHTS_n, for every set n the primitive has (sets past the
  // first hold the influences past four): each vertex keeps its four heaviest joints,
  // renormalised (Corner_attributes::normalized_skin).
  // Joint j of the mesh's skin becomes the carried skin's joint_of[skin][j]; a mesh without a skin
  // weighs 1 on its node's joint.
  bool read_skin(const tinygltf::Primitive& primitive, const Placed_mesh& mesh,
                 std::size_t vertices, const std::string& what) {
    if (!m_skin) return false;
    if (mesh.skin < 0) {
      const auto on_the_node =
          Corner_attributes<Point>::normalized_skin({{m_skin->rigid_joint_of.at(mesh.node), 1.0}});
      m_soup.corners.skins.insert(m_soup.corners.skins.end(), vertices, on_the_node);
      return true;
    }
    const std::vector<std::uint16_t>& joint_of = m_skin->joint_of[std::size_t(mesh.skin)];
    const std::size_t skin_joints = joint_of.size();
    std::vector<std::vector<std::pair<std::uint16_t, double>>> influences(vertices);
    for (int set = 0;; ++set) {
      const std::string joints_name = "JOINTS_" + std::to_string(set),
                        weights_name = "WEIGHTS_" + std::to_string(set);
      const auto joints = primitive.attributes.find(joints_name);
      const auto weights = primitive.attributes.find(weights_name);
      if (joints == primitive.attributes.end() || weights == primitive.attributes.end()) break;
      const std::vector<double> joint_values = accessor_values(
          m_path, m_model, joints->second, Attribute_rules::joints(), what + " " + joints_name);
      const std::vector<double> weight_values = accessor_values(
          m_path, m_model, weights->second, Attribute_rules::weights(), what + " " + weights_name);
      check_vertex_count(joint_values.size() / 4, vertices, what + " " + joints_name);
      check_vertex_count(weight_values.size() / 4, vertices, what + " " + weights_name);
      check_finite(m_path, weight_values, 4, what + ": the weight (" + weights_name + ")");
      for (std::size_t i = 0; i < joint_values.size(); ++i) {
        if (!(weight_values[i] > 0)) continue;  // an unused slot may name any joint
        if (joint_values[i] >= double(skin_joints))
          fail(m_path, what + ": joint " + std::to_string(std::size_t(joint_values[i])) +
                           " of vertex " + std::to_string(i / 4) + " is out of range (skin " +
                           std::to_string(mesh.skin) + " has " + std::to_string(skin_joints) +
                           " joints)");
        influences[i / 4].emplace_back(joint_of[std::size_t(joint_values[i])], weight_values[i]);
      }
    }
    for (auto& vertex : influences)
      m_soup.corners.skins.push_back(Corner_attributes<Point>::normalized_skin(std::move(vertex)));
    return true;
  }

  void check_vertex_count(std::size_t count, std::size_t vertices, const std::string& what) {
    if (count != vertices)
      fail(m_path, what + ": " + std::to_string(count) + " values for " + std::to_string(vertices) +
                       " vertices");
  }

  const std::string& m_path;
  const tinygltf::Model& m_model;
  const Attribute_rules m_rules;
  const bool m_quantized;
  const std::optional<Carried_skin>& m_skin;
  Polygon_soup m_soup;
  // Whether any primitive has texture coordinates, normals, colours, second texture coordinates,
  // skin influences.
  std::array<bool, kKinds> m_any{};
};

// The file path of a relative URI reference: each %XX escape the byte it stands for. glTF's
// uris are URI references: "my%20skin.png" names the file "my skin.png".
std::string uri_path(const std::string& uri) {
  const auto hex = [](char c) {
    return c >= '0' && c <= '9'   ? c - '0'
           : c >= 'a' && c <= 'f' ? c - 'a' + 10
           : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                  : -1;
  };
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      path.push_back(char(hex(uri[i + 1]) * 16 + hex(uri[i + 2])));
      i += 2;
    } else {
      path.push_back(uri[i]);
    }
  }
  return path;
}

// A relative file path as a URI reference: every byte but the unreserved ones and the slashes
// percent-encoded.
std::string uri_of_path(const fs::path& path) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string uri;
  for (const char c : path.generic_string()) {
    const bool unreserved = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') ||
                            (c >= 'A' && c <= 'Z') ||
                            std::string_view("-._~/").find(c) != std::string_view::npos;
    const unsigned byte = static_cast<unsigned char>(c);
    if (unreserved)
      uri.push_back(c);
    else
      uri += {'%', kHex[byte >> 4], kHex[byte & 15]};
  }
  return uri;
}

// What a written file keeps of the input: its looks, image files named by their resolved paths
// and embedded images as bytes (the geometry's buffers are not needed any more). An image file
// that `folder` refuses is left out, with a line in `left_out`.
std::shared_ptr<tinygltf::Model> kept_looks(tinygltf::Model& model, const std::string& path,
                                            const Asset_folder& folder,
                                            std::vector<std::string>& left_out) {
  auto looks = std::make_shared<tinygltf::Model>();
  const fs::path gltf_folder = fs::absolute(path).parent_path();
  std::vector<bool> refused(model.images.size(), false);
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    tinygltf::Image& image = model.images[i];
    if (!image.uri.empty()) {
      const Asset_folder::Resolved file = folder.resolve(gltf_folder, uri_path(image.uri));
      if (!file.refusal.empty()) {
        refused[i] = true;
        left_out.push_back(path + ": image " + std::to_string(i) + "'s uri " +
                           Asset_folder::quoted(image.uri) + " " + file.refusal +
                           "; written without it");
      }
      image.uri = file.path.string();
      image.image.clear();  // the file stays where it is
    }
    image.bufferView = -1;
  }
  remove_images(model, refused);
  // The texture transform is baked into the texture coordinates (read_uvs); the set it named, if
  // any, becomes the texture's.
  for (tinygltf::Material& material : model.materials)
    for_each_texture(material, [](auto& texture) {
      texture.texCoord = texture_set(texture);
      texture.extensions.erase("KHR_texture_transform");
    });
  looks->materials = std::move(model.materials);
  looks->textures = std::move(model.textures);
  looks->samplers = std::move(model.samplers);
  looks->images = std::move(model.images);
  // The extensions the looks still use: not those of the geometry, nor the baked transform.
  for (std::string& extension : model.extensionsUsed)
    if (std::find(kDecodedExtensions.begin(), kDecodedExtensions.end(), extension) ==
        kDecodedExtensions.end())
      looks->extensionsUsed.push_back(std::move(extension));
  return looks;
}

// tinygltf's file system, confined to an asset folder: a file outside it neither exists nor is
// read, and each reference refused is kept with its reason for the error message. tinygltf asks
// for its base folder joined to the decoded URI, then for "./" joined to it, a guess in the
// working folder, which is never the asset's: that one does not exist.
struct Confined_files {
  const Asset_folder* folder;
  std::string base;                                          // the folder tinygltf is given
  std::vector<std::pair<std::string, std::string>> refused;  // reference, refusal

  // The file the path tinygltf joined names, or why not; none for its guess.
  std::optional<Asset_folder::Resolved> resolved(const std::string& joined) const {
    if (joined.compare(0, prefix().size(), prefix()) != 0) return std::nullopt;
    return folder->resolve(base, reference(joined));
  }
  // As tinygltf joins (JoinPath).
  std::string prefix() const { return !base.empty() && base.back() == '/' ? base : base + "/"; }
  std::string reference(const std::string& joined) const { return joined.substr(prefix().size()); }

  static bool exists(const std::string& path, void* files) {
    auto& self = *static_cast<Confined_files*>(files);
    const std::optional<Asset_folder::Resolved> file = self.resolved(path);
    if (!file) return false;
    if (!file->refusal.empty()) {
      self.refused.emplace_back(self.reference(path), file->refusal);
      return false;
    }
    std::error_code missing;
    return fs::is_regular_file(file->path, missing);
  }

  static std::string as_is(const std::string& path, void*) { return path; }

  static bool read(std::vector<unsigned char>* bytes, std::string* error, const std::string& path,
                   void* files) {
    const std::optional<Asset_folder::Resolved> file =
        static_cast<Confined_files*>(files)->resolved(path);
    std::ifstream in;
    if (file && file->refusal.empty()) in.open(file->path, std::ios::binary);
    if (!in) {
      if (error) *error += "cannot be read";
      return false;
    }
    bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
  }

  static bool no_write(std::string* error, const std::string&, const std::vector<unsigned char>&,
                       void*) {
    if (error) *error += "the reader writes no file";
    return false;
  }
};

// The file's model, its compressed views and primitives decoded, its buffer files read from
// `folder` alone; Io_error as read_gltf says.
tinygltf::Model loaded_model(const std::string& path, bool binary, const Asset_folder& folder) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  Confined_files files{&folder, fs::absolute(path).parent_path().string(), {}};
  loader.SetFsCallbacks({&Confined_files::exists, &Confined_files::as_is, &Confined_files::read,
                         &Confined_files::no_write, &files});
  tinygltf::Model model;
  std::string error, warning;
  bool loaded = false;
  try {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, "cannot open");
    const std::string bytes = with_loadable_draco_indices(
        with_loadable_fallback_buffers(
            std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()),
            binary),
        binary);
    if (binary) check_glb_chunks(path, bytes);
    if (bytes.size() > std::numeric_limits<unsigned>::max())
      fail(path, "cannot parse: larger than tinygltf reads (4 GiB)");
    loaded = binary
                 ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               static_cast<unsigned>(bytes.size()), files.base)
                 : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                              static_cast<unsigned>(bytes.size()), files.base);
  } catch (const Io_error&) {
    throw;
  } catch (const std::exception& e) {
    error = e.what();
  }
  // A buffer refused (tinygltf's error names it; an image refused is one of its warnings, and
  // kept_looks leaves it out): said so, naming the reference, never what the file it names holds.
  for (const auto& [reference, refusal] : files.refused)
    if (!loaded && error.find("File not found : " + reference + "\n") != std::string::npos)
      fail(path, "a buffer's uri " + Asset_folder::quoted(reference) + " " + refusal + " (" +
                     folder.root().string() + "); an asset root above it widens that");
  if (!loaded)
    fail(path,
         "cannot parse: " + (error.empty() && warning.empty() ? std::string("not a valid glTF file")
                                                              : one_line(error + warning)));
  for (const std::string& extension : model.extensionsRequired)
    if (std::find(kDecodedExtensions.begin(), kDecodedExtensions.end(), extension) ==
        kDecodedExtensions.end())
      fail(path, "requires the extension " + extension + ", which this reader does not support");

  decode_meshopt_views(path, model);
  decode_draco_primitives(path, model);
  return model;
}

// The primitives of mesh `mesh`, after checking that it exists.
const std::vector<tinygltf::Primitive>& primitives_of(const std::string& path,
                                                      const tinygltf::Model& model, int mesh) {
  if (mesh < 0 || std::size_t(mesh) >= model.meshes.size())
    fail(path, "mesh " + std::to_string(mesh) + " does not exist");
  return model.meshes[std::size_t(mesh)].primitives;
}

// Whether two inverse bind matrices bind a joint alike: equal up to the floats they are stored in.
bool same_binding(const double* a, const double* b) {
  for (int i = 0; i < 16; ++i)
    if (std::abs(a[i] - b[i]) > 1e-6 * (std::max)({1.0, std::abs(a[i]), std::abs(b[i])}))
      return false;
  return true;
}

// Skin `skin`'s inverse bind matrices, 16 values per joint; identities when it has none.
std::vector<double> inverse_bind_matrices(const std::string& path, const tinygltf::Model& model,
                                          int skin) {
  const tinygltf::Skin& input = model.skins[std::size_t(skin)];
  if (input.inverseBindMatrices < 0) {
    std::vector<double> identities;
    for (std::size_t j = 0; j < input.joints.size(); ++j)
      identities.insert(identities.end(), kIdentity.begin(), kIdentity.end());
    return identities;
  }
  std::vector<double> matrices =
      accessor_values(path, model, input.inverseBindMatrices,
                      {TINYGLTF_TYPE_MAT4, {kFloat}, Integers::not_normalized},
                      "skin " + std::to_string(skin) + " inverseBindMatrices");
  if (matrices.size() != 16 * input.joints.size())
    fail(path, "skin " + std::to_string(skin) + ": " + std::to_string(matrices.size() / 16) +
                   " inverse bind matrices for " + std::to_string(input.joints.size()) + " joints");
  return matrices;
}

// `skins`, those of the meshes `levels` place, as one: each skin's joints in the order of the
// skins, then the node of each mesh without a skin as a joint of its own, bound where the node is.
// A node that two of them bind must be bound alike, else `reason` says which do not and there is
// none.
std::optional<Carried_skin> merged_skins(const std::string& path, const tinygltf::Model& model,
                                         const std::set<int>& skins,
                                         const std::vector<std::vector<Placed_mesh>>& levels,
                                         std::string& reason) {
  Carried_skin merged;
  merged.joint_of.resize(model.skins.size());
  merged.skeleton = model.skins[std::size_t(*skins.begin())].skeleton;
  merged.name = model.skins[std::size_t(*skins.begin())].name;
  bool any_matrices = false;
  // Each joint's node: who bound it first, for the reason.
  std::map<int, std::pair<std::string, std::size_t>> bound;
  // The joint of `node` bound by `matrix` for `who`; none when another bound it otherwise.
  const auto bind = [&](int node, const double* matrix,
                        const std::string& who) -> std::optional<std::uint16_t> {
    const auto [first, added] = bound.emplace(node, std::make_pair(who, merged.joints.size()));
    if (!added) {
      const std::size_t joint = first->second.second;
      if (same_binding(matrix, &merged.inverse_bind_matrices[16 * joint]))
        return std::uint16_t(joint);
      reason = first->second.first + " and " + who + " bind node " + std::to_string(node) +
               " differently";
      return std::nullopt;
    }
    if (merged.joints.size() > std::numeric_limits<std::uint16_t>::max()) {
      reason = "more than 65536 joints";
      return std::nullopt;
    }
    merged.joints.push_back(node);
    merged.inverse_bind_matrices.insert(merged.inverse_bind_matrices.end(), matrix, matrix + 16);
    return std::uint16_t(merged.joints.size() - 1);
  };
  for (int skin : skins) {
    const tinygltf::Skin& input = model.skins[std::size_t(skin)];
    if (input.skeleton != merged.skeleton) merged.skeleton = -1;
    std::vector<int> named = input.joints;
    if (input.skeleton >= 0) named.push_back(input.skeleton);
    for (int node : named)
      if (node < 0 || std::size_t(node) >= model.nodes.size())
        fail(path, "skin " + std::to_string(skin) + " names node " + std::to_string(node) +
                       ", which does not exist");
    any_matrices = any_matrices || input.inverseBindMatrices >= 0;
    const std::vector<double> matrices = inverse_bind_matrices(path, model, skin);
    for (std::size_t j = 0; j < input.joints.size(); ++j) {
      const std::optional<std::uint16_t> joint =
          bind(input.joints[j], &matrices[16 * j], "skin " + std::to_string(skin));
      if (!joint) return std::nullopt;
      merged.joint_of[std::size_t(skin)].push_back(*joint);
    }
  }
  for (const std::vector<Placed_mesh>& placed : levels)
    for (const Placed_mesh& mesh : placed) {
      if (mesh.skin >= 0 || merged.rigid_joint_of.count(mesh.node)) continue;
      const std::string who = "node " + std::to_string(mesh.node) + "'s mesh";
      const std::optional<Matrix> inverse = affine_inverse(mesh.world);
      if (!inverse) {
        reason = "node " + std::to_string(mesh.node) + "'s transform flattens its mesh";
        return std::nullopt;
      }
      any_matrices = true;
      const std::optional<std::uint16_t> joint = bind(mesh.node, inverse->data(), who);
      if (!joint) return std::nullopt;
      merged.rigid_joint_of[mesh.node] = *joint;
    }
  if (!any_matrices) merged.inverse_bind_matrices.clear();
  return merged;
}

// The skin whose influences the soups carry: the skins of every mesh placed at every level, and
// the nodes of those without one, merged (merged_skins), when some mesh is skinned and each
// triangle primitive of a skinned mesh has JOINTS_0 and WEIGHTS_0; none otherwise, and then, when
// some placed mesh has a skin, `left_out` says why it is left out.
std::optional<Carried_skin> carried_skin(const std::string& path, const tinygltf::Model& model,
                                         const std::vector<std::vector<Placed_mesh>>& levels,
                                         std::vector<std::string>& left_out) {
  std::set<int> skins;
  std::string reason;
  for (const std::vector<Placed_mesh>& placed : levels)
    for (const Placed_mesh& mesh : placed) {
      if (mesh.skin < 0) continue;
      if (std::size_t(mesh.skin) >= model.skins.size())
        fail(path, "skin " + std::to_string(mesh.skin) + " does not exist");
      skins.insert(mesh.skin);
      const std::vector<tinygltf::Primitive>& primitives = primitives_of(path, model, mesh.mesh);
      for (std::size_t p = 0; p < primitives.size() && reason.empty(); ++p) {
        const tinygltf::Primitive& primitive = primitives[p];
        const bool triangles = primitive.mode < 0 || primitive.mode == TINYGLTF_MODE_TRIANGLES;
        if (triangles &&
            !(primitive.attributes.count("JOINTS_0") && primitive.attributes.count("WEIGHTS_0")))
          reason = "mesh " + std::to_string(mesh.mesh) + " primitive " + std::to_string(p) +
                   " has no JOINTS_0 and WEIGHTS_0";
      }
    }
  if (skins.empty()) return std::nullopt;
  if (reason.empty())
    if (std::optional<Carried_skin> merged = merged_skins(path, model, skins, levels, reason))
      return merged;
  left_out.push_back(path + ": the skin is left out (" + reason +
                     "); every mesh is placed by its node's transform");
  return std::nullopt;
}

// A line in `left_out` for each mesh placed at some level whose primitives have morph targets:
// the reader takes the base shape.
void note_morph_targets(const std::string& path, const tinygltf::Model& model,
                        const std::vector<std::vector<Placed_mesh>>& levels,
                        std::vector<std::string>& left_out) {
  std::set<int> noted;
  for (const std::vector<Placed_mesh>& placed : levels)
    for (const Placed_mesh& mesh : placed) {
      const std::vector<tinygltf::Primitive>& primitives = primitives_of(path, model, mesh.mesh);
      const bool morphed = std::any_of(primitives.begin(), primitives.end(),
                                       [](const auto& p) { return !p.targets.empty(); });
      if (morphed && noted.insert(mesh.mesh).second)
        left_out.push_back(path + ": mesh " + std::to_string(mesh.mesh) +
                           ": its morph targets are left out; its base shape is read");
    }
}

// The soup of the meshes `placed`; with a carried skin (carried_skin), the skinned ones where they
// are, as glTF ignores a skinned mesh's node transform, and every one with its influences.
Polygon_soup soup_of(const std::string& path, const tinygltf::Model& model,
                     const std::vector<Placed_mesh>& placed,
                     const std::optional<Carried_skin>& skin) {
  Soup_builder builder(path, model, skin);
  for (const Placed_mesh& mesh : placed) {
    const std::vector<tinygltf::Primitive>& primitives = primitives_of(path, model, mesh.mesh);
    for (std::size_t p = 0; p < primitives.size(); ++p)
      builder.add_primitive(
          primitives[p], skin && mesh.skin >= 0 ? kIdentity : mesh.world, mesh,
          "mesh " + std::to_string(mesh.mesh) + " primitive " + std::to_string(p));
  }
  return std::move(builder).soup();
}

// Appends `bytes` to buffer 0 as a bufferView of its own, at an offset that is a multiple of 4
// (glTF aligns every accessor to its component size).
int append_view(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  data.resize((data.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* first = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), first, first + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

int append_accessor(tinygltf::Model& model, int view, std::size_t byte_offset, int component_type,
                    int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = byte_offset;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return int(model.accessors.size() - 1);
}

// The bounds of an accessor, which the spec requires of positions and of an animation's times:
// those of the values it stores, `components` to an element, after one another.
template <class Value>
void set_bounds(tinygltf::Accessor& accessor, const std::vector<Value>& values,
                std::size_t components) {
  accessor.minValues.assign(components, std::numeric_limits<double>::infinity());
  accessor.maxValues.assign(components, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < values.size(); ++i) {
    double& low = accessor.minValues[i % components];
    double& high = accessor.maxValues[i % components];
    low = (std::min)(low, double(values[i]));
    high = (std::max)(high, double(values[i]));
  }
}

// Appends `values` to `looks` as float elements of `type`, an accessor and a view of their own in
// buffer 0; with each component's bounds when `bounded` (glTF asks them of an animation's times).
int keep_floats(tinygltf::Model& looks, const std::vector<double>& values, int type, bool bounded) {
  if (looks.buffers.empty()) looks.buffers.emplace_back();
  const std::vector<float> floats(values.begin(), values.end());
  const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
  const int view = append_view(looks, floats.data(), floats.size() * sizeof(float), 0);
  const int index = append_accessor(looks, view, 0, kFloat, type, floats.size() / components);
  if (bounded) set_bounds(looks.accessors[std::size_t(index)], floats, components);
  return index;
}

// The times and values of an animation's sampler that moves a node's `target_path` ("rotation",
// "translation" or "scale"); none for another path, or when they cannot be read (an accessor
// missing or of the wrong type) or break glTF's rules (times finite and increasing, as many values
// as the interpolation needs, all finite), so that no file written from them breaks the rules.
struct Sampler_values {
  std::vector<double> times, values;
};

std::optional<Sampler_values> sampler_values(const std::string& path, const tinygltf::Model& model,
                                             const tinygltf::AnimationSampler& sampler,
                                             const std::string& target_path,
                                             const std::string& what) {
  const bool rotation = target_path == "rotation";
  if (!rotation && target_path != "translation" && target_path != "scale") return std::nullopt;
  Sampler_values read;
  // KHR_mesh_quantization allows integers besides floats, normalized for a rotation.
  const std::vector<int> types = {kFloat, kByte, kUnsignedByte, kShort, kUnsignedShort};
  try {
    read.times = accessor_values(path, model, sampler.input,
                                 {TINYGLTF_TYPE_SCALAR, {kFloat}, Integers::not_normalized},
                                 what + " input");
    read.values =
        accessor_values(path, model, sampler.output,
                        rotation ? Accessor_rule{TINYGLTF_TYPE_VEC4, types, Integers::normalized}
                                 : Accessor_rule{TINYGLTF_TYPE_VEC3, types, Integers::either},
                        what + " output");
  } catch (const Io_error&) {
    return std::nullopt;  // a motion that cannot be read leaves the mesh readable
  }
  const std::size_t per_time =
      (sampler.interpolation == "CUBICSPLINE" ? 3 : 1) * (rotation ? 4 : 3);
  const auto finite = [](double x) { return std::isfinite(x); };
  if (read.times.empty() || read.values.size() != per_time * read.times.size() ||
      !std::all_of(read.times.begin(), read.times.end(), finite) ||
      !std::all_of(read.values.begin(), read.values.end(), finite) ||
      std::adjacent_find(read.times.begin(), read.times.end(), std::greater_equal<double>()) !=
          read.times.end())
    return std::nullopt;
  return read;
}

// The animations' channels that move the kept skeleton's nodes (`index`: an input node's index
// among them, -1 for the others), with their samplers' times and values (sampler_values) as
// floats in `looks`, the samplers that share their times sharing one copy. An animation that
// loses channels (of other nodes, of morph target weights, without a sampler, or whose sampler
// cannot be read or breaks glTF's rules) gets a line in `left_out`; none makes the file
// unreadable.
void keep_animations(const std::string& path, const tinygltf::Model& model,
                     const std::vector<int>& index, tinygltf::Model& looks,
                     std::vector<std::string>& left_out) {
  std::map<int, int> kept_times;  // by the input's accessor
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    const std::string what = "animation " + std::to_string(a);
    tinygltf::Animation kept;
    kept.name = animation.name;
    std::map<std::pair<int, std::string>, int> kept_samplers;  // by input sampler and path
    std::size_t dropped = 0;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
      const int node = channel.target_node;
      if (node < 0 || std::size_t(node) >= index.size() || index[std::size_t(node)] < 0 ||
          channel.sampler < 0 || std::size_t(channel.sampler) >= animation.samplers.size()) {
        ++dropped;
        continue;
      }
      const auto key = std::make_pair(channel.sampler, channel.target_path);
      auto found = kept_samplers.find(key);
      if (found == kept_samplers.end()) {
        const tinygltf::AnimationSampler& sampler =
            animation.samplers[std::size_t(channel.sampler)];
        const std::optional<Sampler_values> read =
            sampler_values(path, model, sampler, channel.target_path,
                           what + " sampler " + std::to_string(channel.sampler));
        if (!read) {
          ++dropped;
          continue;
        }
        tinygltf::AnimationSampler& to = kept.samplers.emplace_back();
        to.interpolation = sampler.interpolation;
        const auto times = kept_times.emplace(sampler.input, -1).first;
        if (times->second < 0)
          times->second = keep_floats(looks, read->times, TINYGLTF_TYPE_SCALAR, true);
        to.input = times->second;
        to.output = keep_floats(
            looks, read->values,
            channel.target_path == "rotation" ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, false);
        found = kept_samplers.emplace(key, int(kept.samplers.size() - 1)).first;
      }
      tinygltf::AnimationChannel& to = kept.channels.emplace_back();
      to.sampler = found->second;
      to.target_node = index[std::size_t(node)];
      to.target_path = channel.target_path;
    }
    if (dropped > 0)
      left_out.push_back(
          path + ": " + what + (animation.name.empty() ? "" : " ('" + animation.name + "')") +
          ": " + std::to_string(dropped) + " of " + std::to_string(animation.channels.size()) +
          " channels left out (they move nodes other than the skeleton's, or "
          "morph target weights, or break glTF's rules)");
    if (!kept.channels.empty()) looks.animations.push_back(std::move(kept));
  }
}

// The nodes the carried skin needs, with the skin, for a written file to pose the mesh as the
// input does: its joints and skeleton root and all their ancestors, in the input's order, each with
// its name, transform and the children among them (no mesh, camera or extension); the skin's
// joints and skeleton named among them, its inverse bind matrices (when it has them) as MAT4
// floats, and the animations of those nodes (keep_animations), each accessor with a view of its
// own in buffer 0.
void keep_skeleton(const std::string& path, const tinygltf::Model& model, const Carried_skin& skin,
                   tinygltf::Model& looks, std::vector<std::string>& left_out) {
  std::vector<int> parent(model.nodes.size(), -1);
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    for (int child : model.nodes[n].children)
      if (child >= 0 && std::size_t(child) < model.nodes.size())
        parent[std::size_t(child)] = int(n);
  std::vector<char> kept(model.nodes.size(), 0);
  std::vector<int> named = skin.joints;
  if (skin.skeleton >= 0) named.push_back(skin.skeleton);
  for (int node : named)
    // At most one step per node: a cycle of parents (a forged file) stops.
    for (std::size_t steps = 0; node >= 0 && steps <= model.nodes.size(); ++steps) {
      kept[std::size_t(node)] = 1;
      node = parent[std::size_t(node)];
    }
  std::vector<int> index(model.nodes.size(), -1);
  for (std::size_t n = 0; n < model.nodes.size(); ++n)
    if (kept[n]) index[n] = int(looks.nodes.size()), looks.nodes.emplace_back();
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (!kept[n]) continue;
    const tinygltf::Node& from = model.nodes[n];
    tinygltf::Node& to = looks.nodes[std::size_t(index[n])];
    to.name = from.name;
    to.matrix = from.matrix;
    to.translation = from.translation;
    to.rotation = from.rotation;
    to.scale = from.scale;
    for (int child : from.children)
      if (child >= 0 && std::size_t(child) < model.nodes.size() && kept[std::size_t(child)])
        to.children.push_back(index[std::size_t(child)]);
  }
  tinygltf::Skin& kept_skin = looks.skins.emplace_back();
  kept_skin.name = skin.name;
  for (int joint : skin.joints) kept_skin.joints.push_back(index[std::size_t(joint)]);
  kept_skin.skeleton = skin.skeleton >= 0 ? index[std::size_t(skin.skeleton)] : -1;
  keep_animations(path, model, index, looks, left_out);
  if (!skin.inverse_bind_matrices.empty())
    kept_skin.inverseBindMatrices =
        keep_floats(looks, skin.inverse_bind_matrices, TINYGLTF_TYPE_MAT4, false);
}

// read_gltf_levels, or with `follow_lod` false the finest level alone, as read_gltf reads it.
std::vector<Gltf_soup> read_levels(const std::string& path, bool binary, bool follow_lod,
                                   const std::string& asset_root) {
  const Asset_folder folder(path, asset_root);
  tinygltf::Model model = loaded_model(path, binary, folder);
  Lod_walk walk;
  walk.follow_lod = follow_lod;
  std::vector<std::vector<Placed_mesh>> placed;
  // Level 0's walk finds how many levels there are.
  for (; walk.level < walk.levels; ++walk.level) placed.push_back(placed_meshes(path, model, walk));
  std::vector<std::string> left_out;
  const std::optional<Carried_skin> skin = carried_skin(path, model, placed, left_out);
  note_morph_targets(path, model, placed, left_out);
  std::vector<Gltf_soup> levels;
  for (const std::vector<Placed_mesh>& level : placed)
    levels.push_back({soup_of(path, model, level, skin), nullptr, {}});
  // Last: the soups above name the materials, which the looks take away.
  std::shared_ptr<tinygltf::Model> looks = kept_looks(model, path, folder, left_out);
  if (skin)
    keep_skeleton(path, model, *skin, *looks, left_out);
  else if (!model.animations.empty())
    left_out.push_back(path + ": its " + std::to_string(model.animations.size()) +
                       (model.animations.size() == 1 ? " animation is" : " animations are") +
                       " left out: the meshes are written where their nodes place them");
  for (Gltf_soup& level : levels) {
    level.looks = looks;
    level.left_out = left_out;
  }
  return levels;
}

// ---- Writing ---------------------------------------------------------------------------------

// A float vertex attribute of every wedge; a value without a number (a corner without one)
// becomes `none`, as glTF has no "none".
int append_float_attribute(tinygltf::Model& model, std::vector<float> values, int type,
                           float none = 0) {
  for (float& v : values)
    if (std::isnan(v)) v = none;
  const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
  const int view = append_view(model, values.data(), values.size() * sizeof(float),
                               TINYGLTF_TARGET_ARRAY_BUFFER);
  return append_accessor(model, view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                         values.size() / components);
}

// The looks (a glTF input's, or an OBJ input's made glTF's), their image files named from the
// folder of the file written, `output`, when they lie in it, their other images stored in buffer 0:
// the file names no file outside its folder. An image file that cannot be stored is left out,
// with a line in `left_out`.
void pass_looks_through(tinygltf::Model& model, const tinygltf::Model& looks,
                        const Asset_folder& output, std::vector<std::string>& left_out) {
  model.materials = looks.materials;
  model.textures = looks.textures;
  model.samplers = looks.samplers;
  model.extensionsUsed = looks.extensionsUsed;
  model.images = looks.images;
  std::vector<bool> unreadable(model.images.size(), false);
  for (std::size_t i = 0; i < model.images.size(); ++i) {
    tinygltf::Image& image = model.images[i];
    if (image.uri.empty()) continue;
    if (const Asset_folder::Resolved inside = output.check(image.uri); inside.refusal.empty()) {
      image.uri = uri_of_path(inside.path.lexically_relative(output.root()));
      continue;
    }
    Image_file file = read_image_file(image.uri);
    if (!file.failure.empty()) {
      unreadable[i] = true;
      left_out.push_back("image " + Asset_folder::quoted(image.uri) + " " + file.failure +
                         "; written without it");
      continue;
    }
    image.uri.clear();
    image.image = std::move(file.bytes);
    image.mimeType = file.mime_type;
  }
  remove_images(model, unreadable);
  for (tinygltf::Image& image : model.images) {
    if (image.uri.empty()) {
      image.bufferView = append_view(model, image.image.data(), image.image.size(), 0);
      image.image.clear();
    }
    image.as_is = false;
  }
}

// glTF's component type of an integer type.
template <class Integer>
constexpr int component_type_of() {
  if constexpr (std::is_same_v<Integer, std::int8_t>) return kByte;
  if constexpr (std::is_same_v<Integer, std::uint8_t>) return kUnsignedByte;
  if constexpr (std::is_same_v<Integer, std::int16_t>) return kShort;
  if constexpr (std::is_same_v<Integer, std::uint16_t>) return kUnsignedShort;
  return TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// An integer vertex attribute of every wedge, `type`'s components each, every element padded to a
// multiple of 4 bytes: glTF aligns each element of a vertex attribute so.
template <class Integer>
int append_integer_attribute(tinygltf::Model& model, const std::vector<Integer>& values, int type,
                             bool normalized) {
  const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
  const std::size_t count = values.size() / components, element = components * sizeof(Integer);
  const std::size_t stride = (element + 3) / 4 * 4;
  std::vector<unsigned char> bytes(count * stride, 0);
  for (std::size_t i = 0; i < count; ++i)
    std::memcpy(bytes.data() + i * stride, values.data() + i * components, element);
  const int view = append_view(model, bytes.data(), bytes.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
  model.bufferViews[std::size_t(view)].byteStride = stride;
  const int accessor = append_accessor(model, view, 0, component_type_of<Integer>(), type, count);
  model.accessors[std::size_t(accessor)].normalized = normalized;
  return accessor;
}

// `value` (NaN: `none`) as a normalized integer, to the nearest step: an unsigned one holds
// [0, 1], a signed one [-1, 1].
template <class Integer>
Integer normalized_integer(double value, double none) {
  constexpr double largest = std::numeric_limits<Integer>::max();
  constexpr double lowest = std::is_signed_v<Integer> ? -1.0 : 0.0;
  const double v = std::isnan(value) ? none : std::clamp(value, lowest, 1.0);
  return Integer(std::lround(v * largest));
}

// KHR_mesh_quantization's positions: unsigned 16-bit steps from `origin` along each axis, the
// step the same on every axis, so that the node's scale, which dequantizes them, is uniform and
// leaves the normals' directions as they are.
struct Position_grid {
  std::array<double, 3> origin;
  double step;
};

Position_grid position_grid(const std::vector<Point>& points) {
  CGAL::Bbox_3 box;  // empty, as for a level without points
  for (const Point& p : points) box += p.bbox();
  const double extent =
      std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  return {{box.xmin(), box.ymin(), box.zmin()}, extent > 0 ? extent / 65535 : 1};
}

// The positions on `grid`, their bounds (which the spec requires) those of the integers.
int append_quantized_positions(tinygltf::Model& model, const std::vector<Point>& points,
                               const Position_grid& grid) {
  std::vector<std::uint16_t> steps;
  for (const Point& p : points)
    for (int axis = 0; axis < 3; ++axis)
      steps.push_back(std::uint16_t(
          std::min(65535.0, std::round((p[axis] - grid.origin[std::size_t(axis)]) / grid.step))));
  const int position = append_integer_attribute(model, steps, TINYGLTF_TYPE_VEC3, false);
  set_bounds(model.accessors[std::size_t(position)], steps, 3);
  return position;
}

int append_float_positions(tinygltf::Model& model, const std::vector<Point>& points) {
  std::vector<float> positions;
  for (const Point& p : points)
    for (double c : {p.x(), p.y(), p.z()}) positions.push_back(float(c));
  const int position = append_float_attribute(model, positions, TINYGLTF_TYPE_VEC3);
  set_bounds(model.accessors[std::size_t(position)], positions, 3);
  return position;
}

// How far from 1 the length of a quantized normal may be: a little inside the Khronos validator's
// 0.00674 for a unit vector, which it measures in single precision.
constexpr double kUnitLengthTolerance = 0.0067;

// A unit vector as normalized signed bytes: its components rounded to the nearest steps of 1/127,
// unless that makes it too long or too short (near the diagonal, three components rounded up by
// almost half a step make it 0.0068 too long); then, of the roundings of each component down or
// up, the one nearest in direction whose length is within kUnitLengthTolerance of 1.
std::array<std::int8_t, 3> unit_vector_bytes(const std::array<double, 3>& unit) {
  const auto length_error = [](const std::array<double, 3>& steps) {
    return std::abs(std::hypot(steps[0], steps[1], steps[2]) / 127 - 1);
  };
  std::array<double, 3> best;
  for (int k = 0; k < 3; ++k) best[std::size_t(k)] = std::round(unit[std::size_t(k)] * 127);
  if (length_error(best) > kUnitLengthTolerance) {
    double best_cosine = -2;
    for (int corner = 0; corner < 8; ++corner) {
      std::array<double, 3> steps;
      double dot = 0, squared = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        const double scaled = unit[k] * 127;
        steps[k] = corner >> k & 1 ? std::ceil(scaled) : std::floor(scaled);
        dot += steps[k] * unit[k];
        squared += steps[k] * steps[k];
      }
      const double cosine = squared > 0 ? dot / std::sqrt(squared) : -1;
      if (length_error(steps) <= kUnitLengthTolerance && cosine > best_cosine) {
        best_cosine = cosine;
        best = steps;
      }
    }
  }
  return {std::int8_t(best[0]), std::int8_t(best[1]), std::int8_t(best[2])};
}

// The normals; quantized, made unit and stored as normalized signed bytes (unit_vector_bytes), as
// gltfpack writes them, a normal without a direction (a corner without one) being 0.
int append_normals(tinygltf::Model& model, const std::vector<Kernel::Vector_3>& normals,
                   bool quantized) {
  if (!quantized) {
    std::vector<float> floats;
    for (const Kernel::Vector_3& n : normals)
      for (double c : {n.x(), n.y(), n.z()}) floats.push_back(float(c));
    return append_float_attribute(model, floats, TINYGLTF_TYPE_VEC3);
  }
  std::vector<std::int8_t> bytes;
  for (const Kernel::Vector_3& n : normals) {
    const double length = std::sqrt(n.squared_length());
    const std::array<std::int8_t, 3> unit =
        length > 0 && std::isfinite(length)
            ? unit_vector_bytes({n.x() / length, n.y() / length, n.z() / length})
            : std::array<std::int8_t, 3>{0, 0, 0};
    bytes.insert(bytes.end(), unit.begin(), unit.end());
  }
  return append_integer_attribute(model, bytes, TINYGLTF_TYPE_VEC3, true);
}

// The texture coordinates in glTF's convention; quantized, as normalized unsigned shorts when all
// lie in [0, 1], or signed ones when all lie in [-1, 1], which is all they can hold without a
// texture transform on every material; float otherwise.
int append_uvs(tinygltf::Model& model, const std::vector<std::array<double, 2>>& wedge_uvs,
               bool quantized) {
  std::vector<double> uvs;
  for (const auto& uv : wedge_uvs) {
    const std::array<double, 2> flipped = texture_coordinates_of_gltf(uv[0], uv[1]);
    uvs.insert(uvs.end(), flipped.begin(), flipped.end());
  }
  const auto all_within = [&uvs](double lowest) {
    return std::all_of(uvs.begin(), uvs.end(),
                       [lowest](double c) { return std::isnan(c) || (c >= lowest && c <= 1); });
  };
  const auto normalized = [&uvs, &model](auto integer) {
    std::vector<decltype(integer)> steps;
    for (double c : uvs) steps.push_back(normalized_integer<decltype(integer)>(c, 0));
    return append_integer_attribute(model, steps, TINYGLTF_TYPE_VEC2, true);
  };
  if (quantized && all_within(0)) return normalized(std::uint16_t());
  if (quantized && all_within(-1)) return normalized(std::int16_t());
  return append_float_attribute(model, std::vector<float>(uvs.begin(), uvs.end()),
                                TINYGLTF_TYPE_VEC2);
}

// RGBA colours; quantized, as normalized unsigned bytes, as gltfpack writes them. A corner without
// a colour is white, which leaves the material's colour as it is.
int append_colors(tinygltf::Model& model, const std::vector<std::array<double, 4>>& wedge_colors,
                  bool quantized) {
  if (!quantized) {
    std::vector<float> colors;
    for (const auto& color : wedge_colors)
      for (double c : color) colors.push_back(float(c));
    return append_float_attribute(model, colors, TINYGLTF_TYPE_VEC4, 1);
  }
  std::vector<std::uint8_t> bytes;
  for (const auto& color : wedge_colors)
    for (double c : color) bytes.push_back(normalized_integer<std::uint8_t>(c, 1));
  return append_integer_attribute(model, bytes, TINYGLTF_TYPE_VEC4, true);
}

// The triangles' indices as one view, `Index` each, and a primitive per material of `model`
// (whose materials are in place) reading its share of them, in the order of the material indices
// (none last), each of its triangles in the mesh's order; every primitive has `shape`'s
// attributes.
template <class Index>
std::vector<tinygltf::Primitive> primitives_per_material(tinygltf::Model& model,
                                                         const Wedge_mesh& wedges,
                                                         const tinygltf::Primitive& shape) {
  std::map<std::uint32_t, std::vector<Index>> indices_of_material;
  for (std::size_t t = 0; t < wedges.triangles.size(); ++t) {
    const std::uint32_t material =
        wedges.materials.empty() ? Corner_tables::kNoMaterial : wedges.materials[t];
    auto& indices = indices_of_material[material];
    indices.insert(indices.end(), wedges.triangles[t].begin(), wedges.triangles[t].end());
  }
  std::vector<Index> all_indices;
  for (const auto& group : indices_of_material)
    all_indices.insert(all_indices.end(), group.second.begin(), group.second.end());
  const int index_view = append_view(model, all_indices.data(), all_indices.size() * sizeof(Index),
                                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  std::vector<tinygltf::Primitive> primitives;
  std::size_t offset = 0;
  for (const auto& [material, indices] : indices_of_material) {
    tinygltf::Primitive primitive = shape;
    primitive.indices =
        append_accessor(model, index_view, offset * sizeof(Index), component_type_of<Index>(),
                        TINYGLTF_TYPE_SCALAR, indices.size());
    primitive.material = material < model.materials.size() ? int(material) : -1;
    offset += indices.size();
    primitives.push_back(std::move(primitive));
  }
  return primitives;
}

// A vertex's skin influences as glTF stores them: four joints and weights whose stored sum is
// exactly 1, the first weight (the largest) taking up the others' rounding, and a slot whose
// stored weight is 0 naming joint 0. A corner without influences gets joint 0 with weight 1, as
// glTF has no "none". `Weight` is float, or a normalized unsigned integer.
template <class Weight>
void stored_influences(const Corner_attributes<Point>::Skin_influences& skin,
                       std::array<std::uint16_t, 4>& joints, std::array<Weight, 4>& weights) {
  constexpr bool integer = std::is_integral_v<Weight>;
  constexpr Weight one = integer ? std::numeric_limits<Weight>::max() : Weight(1);
  joints = skin.joints;
  weights = {one, 0, 0, 0};
  if (std::isnan(skin.weights[0])) {
    joints = {0, 0, 0, 0};
    return;
  }
  for (std::size_t i = 1; i < 4; ++i) {
    if constexpr (integer)
      weights[i] = normalized_integer<Weight>(skin.weights[i], 0);
    else
      weights[i] = Weight(skin.weights[i]);
    weights[0] = Weight(weights[0] - weights[i]);
    if (weights[i] == 0) joints[i] = 0;
  }
}

// JOINTS_0 (u8 when every joint is below 256, u16 otherwise) and WEIGHTS_0 (float; quantized,
// normalized u16) of the wedges' influences (stored_influences).
void add_skin_influences(tinygltf::Model& model,
                         const std::vector<Corner_attributes<Point>::Skin_influences>& skins,
                         bool quantized, tinygltf::Primitive& shape) {
  std::vector<std::uint16_t> joints;
  std::vector<float> floats;
  std::vector<std::uint16_t> steps;
  for (const auto& skin : skins) {
    std::array<std::uint16_t, 4> stored_joints;
    if (quantized) {
      std::array<std::uint16_t, 4> weights;
      stored_influences(skin, stored_joints, weights);
      steps.insert(steps.end(), weights.begin(), weights.end());
    } else {
      std::array<float, 4> weights;
      stored_influences(skin, stored_joints, weights);
      floats.insert(floats.end(), weights.begin(), weights.end());
    }
    joints.insert(joints.end(), stored_joints.begin(), stored_joints.end());
  }
  const bool bytes = std::all_of(joints.begin(), joints.end(), [](auto j) { return j < 256; });
  shape.attributes["JOINTS_0"] =
      bytes
          ? append_integer_attribute(model, std::vector<std::uint8_t>(joints.begin(), joints.end()),
                                     TINYGLTF_TYPE_VEC4, false)
          : append_integer_attribute(model, joints, TINYGLTF_TYPE_VEC4, false);
  shape.attributes["WEIGHTS_0"] =
      quantized ? append_integer_attribute(model, steps, TINYGLTF_TYPE_VEC4, true)
                : append_float_attribute(model, floats, TINYGLTF_TYPE_VEC4);
}

// Accessor `index` of `looks` (keep_floats), appended to `model` with a view of its own.
int append_kept_accessor(tinygltf::Model& model, const tinygltf::Model& looks, int index) {
  tinygltf::Accessor accessor = looks.accessors[std::size_t(index)];
  const tinygltf::BufferView& view = looks.bufferViews[std::size_t(accessor.bufferView)];
  accessor.bufferView =
      append_view(model, looks.buffers[0].data.data() + view.byteOffset, view.byteLength, 0);
  model.accessors.push_back(std::move(accessor));
  return int(model.accessors.size() - 1);
}

// The skeleton that `looks` kept (keep_skeleton), appended to `model`: its nodes after those
// `model` has, its skin as `model`'s skin 0, its inverse bind matrices and its animations. Returns
// the skeleton's roots, for the scene to hold.
std::vector<int> append_skeleton(tinygltf::Model& model, const tinygltf::Model& looks) {
  const int first = int(model.nodes.size());
  std::vector<char> is_child(looks.nodes.size(), 0);
  for (tinygltf::Node node : looks.nodes) {
    for (int& child : node.children) {
      is_child[std::size_t(child)] = 1;
      child += first;
    }
    model.nodes.push_back(std::move(node));
  }
  tinygltf::Skin skin = looks.skins.front();
  for (int& joint : skin.joints) joint += first;
  if (skin.skeleton >= 0) skin.skeleton += first;
  // Each accessor once: samplers share their times.
  std::vector<int> appended(looks.accessors.size(), -1);
  const auto append = [&](int index) {
    int& to = appended[std::size_t(index)];
    if (to < 0) to = append_kept_accessor(model, looks, index);
    return to;
  };
  if (skin.inverseBindMatrices >= 0) skin.inverseBindMatrices = append(skin.inverseBindMatrices);
  for (tinygltf::Animation animation : looks.animations) {
    for (tinygltf::AnimationChannel& channel : animation.channels) channel.target_node += first;
    for (tinygltf::AnimationSampler& sampler : animation.samplers) {
      sampler.input = append(sampler.input);
      sampler.output = append(sampler.output);
    }
    model.animations.push_back(std::move(animation));
  }
  model.skins.push_back(std::move(skin));
  std::vector<int> roots;
  for (std::size_t n = 0; n < looks.nodes.size(); ++n)
    if (!is_child[n]) roots.push_back(first + int(n));
  return roots;
}

// A level's mesh and the node holding it: its wedges' attributes, its indices, and a primitive per
// material (primitives_per_material); every primitive shares the wedges. Quantized, the node's
// transform dequantizes the positions (KHR_mesh_quantization), unless the mesh is `skinned` (by
// skin 0): glTF ignores a skinned mesh's node transform, so its positions stay float.
void add_level(tinygltf::Model& model, const Wedge_mesh& wedges, bool quantized, bool skinned) {
  tinygltf::Node node;
  tinygltf::Primitive shape;
  shape.mode = TINYGLTF_MODE_TRIANGLES;
  if (quantized && !skinned) {
    const Position_grid grid = position_grid(wedges.points);
    shape.attributes["POSITION"] = append_quantized_positions(model, wedges.points, grid);
    node.translation.assign(grid.origin.begin(), grid.origin.end());
    node.scale.assign(3, grid.step);
  } else {
    shape.attributes["POSITION"] = append_float_positions(model, wedges.points);
  }
  if (!wedges.normals.empty())
    shape.attributes["NORMAL"] = append_normals(model, wedges.normals, quantized);
  // glTF numbers the sets from 0 with no gap: a second set alone comes with a first set of
  // corners without values (zeros).
  if (!wedges.uvs.empty() || !wedges.second_uvs.empty()) {
    const double none = std::numeric_limits<double>::quiet_NaN();
    shape.attributes["TEXCOORD_0"] = append_uvs(
        model,
        wedges.uvs.empty() ? std::vector<std::array<double, 2>>(wedges.points.size(), {none, none})
                           : wedges.uvs,
        quantized);
  }
  if (!wedges.second_uvs.empty())
    shape.attributes["TEXCOORD_1"] = append_uvs(model, wedges.second_uvs, quantized);
  if (!wedges.colors.empty())
    shape.attributes["COLOR_0"] = append_colors(model, wedges.colors, quantized);
  if (skinned) {
    add_skin_influences(model, wedges.skins, quantized, shape);
    node.skin = 0;
  }
  tinygltf::Mesh mesh;
  // Quantized, 16-bit indices when every one fits: glTF reserves 65535, a type's largest value.
  mesh.primitives = quantized && wedges.points.size() <= 65535
                        ? primitives_per_material<std::uint16_t>(model, wedges, shape)
                        : primitives_per_material<std::uint32_t>(model, wedges, shape);
  model.meshes.push_back(std::move(mesh));
  node.mesh = int(model.meshes.size() - 1);
  model.nodes.push_back(std::move(node));
}

// Declares `extension` used, and required when `required`, unless it is already.
void declare_extension(tinygltf::Model& model, const std::string& extension, bool required) {
  for (std::vector<std::string>* list : {&model.extensionsUsed, &model.extensionsRequired}) {
    if (list == &model.extensionsRequired && !required) continue;
    if (std::find(list->begin(), list->end(), extension) == list->end()) list->push_back(extension);
  }
}

}  // namespace

Gltf_soup read_gltf(const std::string& path, bool binary, const std::string& asset_root) {
  return std::move(read_levels(path, binary, false, asset_root).front());
}

std::vector<Gltf_soup> read_gltf_levels(const std::string& path, bool binary,
                                        const std::string& asset_root) {
  return read_levels(path, binary, true, asset_root);
}

std::string gltf_bytes(const std::vector<Lod_level>& levels, bool binary, Gltf_encoding encoding,
                       const Material_references& materials, const std::string& output_folder,
                       std::vector<std::string>& left_out) {
  std::vector<Wedge_mesh> wedges;
  // The float bytes keep the mesh's order; the others, meant to be small, gltfpack's.
  for (const Lod_level& level : levels)
    wedges.push_back(encoding == Gltf_encoding::float32 ? wedge_mesh(*level.mesh)
                                                        : cache_ordered(wedge_mesh(*level.mesh)));
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "cgal_policies";
  model.buffers.resize(1);
  // A texture needs texture coordinates to be drawn with (and the spec requires them); every
  // level carries the same kinds of values as the first.
  const std::shared_ptr<const tinygltf::Model> looks =
      materials.gltf ? materials.gltf
                     : obj_material_looks(materials, !wedges.front().uvs.empty(), left_out);
  pass_looks_through(model, *looks, Asset_folder::holding(output_folder), left_out);
  const bool quantized = encoding != Gltf_encoding::float32;
  // Every level carries the same kinds of values as the first.
  const bool skinned = !wedges.front().skins.empty() && !looks->skins.empty();
  if (!wedges.front().skins.empty() && !skinned)
    left_out.push_back("the skin: the input's skeleton is not known, written without it");
  for (const Wedge_mesh& level : wedges) add_level(model, level, quantized, skinned);
  if (quantized) declare_extension(model, "KHR_mesh_quantization", true);
  // The finest level is the scene's, with the skeleton's roots; the others are reached through its
  // MSFT_lod alone.
  model.scenes.emplace_back();
  model.scenes.back().nodes.push_back(0);
  if (skinned)
    for (int root : append_skeleton(model, *looks)) model.scenes.back().nodes.push_back(root);
  model.defaultScene = 0;
  if (levels.size() > 1) {
    tinygltf::Value::Array coarser, coverage;
    for (std::size_t k = 0; k < levels.size(); ++k) {
      if (k > 0) coarser.emplace_back(int(k));
      coverage.emplace_back(levels[k].screen_coverage);
    }
    model.nodes[0].extensions["MSFT_lod"] =
        tinygltf::Value(tinygltf::Value::Object{{"ids", tinygltf::Value(std::move(coarser))}});
    model.nodes[0].extras = tinygltf::Value(
        tinygltf::Value::Object{{"MSFT_screencoverage", tinygltf::Value(coverage)}});
    // A glTF input's looks may declare it already (a material's levels of detail).
    declare_extension(model, "MSFT_lod", false);
  }
  // Every view is in place: the compression moves them into a fallback buffer.
  nlohmann::json compression;
  if (encoding == Gltf_encoding::meshopt) {
    compression = encode_meshopt_views(model);
    declare_extension(model, "EXT_meshopt_compression", true);
  }

  tinygltf::TinyGLTF writer;
  // Every image is a uri or a bufferView already: none to encode.
  writer.SetImageWriter(nullptr, nullptr);
  std::ostringstream bytes;
  writer.WriteGltfSceneToStream(&model, bytes, /*prettyPrint=*/true, binary);
  return encoding == Gltf_encoding::meshopt
             ? with_meshopt_extensions(bytes.str(), binary, compression)
             : bytes.str();
}

}  // namespace io
}  // namespace cgal_policies
