// glTF files built with tinygltf's API for the tests of the io layer and of simplify: accessors of
// any component type, one mesh of several primitives under a node, and a two-primitive square.
#ifndef CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H
#define CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace gltf_fixtures {

namespace fs = std::filesystem;

class Gltf_builder {
 public:
  Gltf_builder() {
    model.buffers.resize(1);
    model.asset.version = "2.0";
  }
  template <class T>
  int accessor(const std::vector<T>& values, int component_type, int type,
               bool normalized = false) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    data.insert(data.end(), bytes, bytes + view.byteLength);
    data.resize((data.size() + 3) / 4 * 4);
    model.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = int(model.bufferViews.size() - 1);
    a.componentType = component_type;
    a.type = type;
    a.normalized = normalized;
    a.count = values.size() / std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
  }
  // One mesh of these primitives, under one node moved by `translation`.
  void place(std::vector<tinygltf::Primitive> primitives, std::vector<double> translation) {
    model.meshes.emplace_back();
    model.meshes.back().primitives = std::move(primitives);
    model.nodes.emplace_back();
    model.nodes.back().mesh = 0;
    model.nodes.back().translation = std::move(translation);
    model.scenes.emplace_back();
    model.scenes.back().nodes = {0};
    model.defaultScene = 0;
  }
  void write(const fs::path& path) const {
    std::ofstream file(path, std::ios::binary);
    tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, file, false, path.extension() == ".glb");
  }
  tinygltf::Model model;
};

inline tinygltf::Primitive triangles(int position, int indices, int uv, int material) {
  tinygltf::Primitive p;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  p.attributes["POSITION"] = position;
  if (uv >= 0) p.attributes["TEXCOORD_0"] = uv;
  p.indices = indices;
  p.material = material;
  return p;
}

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// The unit square as two primitives that share no vertex: the first indexed by u16 with float
// texture coordinates (x, y) / 2 and normalized u8 RGB colours, the second without indices or
// colours, with normalized u16 texture coordinates that agree at (0, 0) and differ at (1, 1), so
// that the diagonal is a seam.
inline Gltf_builder two_primitive_square() {
  Gltf_builder b;
  const int first =
      b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  const int first_indices =
      b.accessor(std::vector<std::uint16_t>{0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                 TINYGLTF_TYPE_SCALAR);
  const int first_uvs =
      b.accessor(std::vector<float>{0, 0, 0.5f, 0, 0.5f, 0.5f}, kFloat, TINYGLTF_TYPE_VEC2);
  const int second =
      b.accessor(std::vector<float>{0, 0, 0, 1, 1, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  const int second_uvs =
      b.accessor(std::vector<std::uint16_t>{0, 0, 52428, 52428, 0, 65535},
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC2, true);
  tinygltf::Primitive colored = triangles(first, first_indices, first_uvs, 0);
  colored.attributes["COLOR_0"] =
      b.accessor(std::vector<std::uint8_t>{0, 51, 255, 0, 51, 255, 0, 51, 255},
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC3, true);
  b.model.materials.resize(2);
  b.model.materials[0].name = "paint";
  b.place({colored, triangles(second, -1, second_uvs, 1)}, {10, 0, 0});
  return b;
}

// Any bytes: the reader and the writer never decode an image.
inline const std::string kImageBytes = std::string("\x89PNG\r\n\x1a\n", 8) + "not decoded";

}  // namespace gltf_fixtures

#endif  // CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H
