// glTF files built with tinygltf's API for the tests of the io layer and of simplify: accessors of
// any component type, images, one mesh of several primitives under a node, and a two-primitive
// square, bare or with materials and images.
#ifndef CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H
#define CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
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
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(T));
    a.componentType = component_type;
    a.type = type;
    a.normalized = normalized;
    a.count = values.size() / std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
  }
  // An image of these bytes, in a bufferView of its own, with a texture of its own; returns the
  // texture.
  int held_image(const std::string& bytes, const std::string& mime_type) {
    tinygltf::Image image;
    image.bufferView = view(bytes.data(), bytes.size());
    image.mimeType = mime_type;
    return texture(std::move(image));
  }
  // An image of its own file, or of a data URI, with a texture of its own; returns the texture.
  int image_at(const std::string& uri) {
    tinygltf::Image image;
    image.uri = uri;
    return texture(std::move(image));
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
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(nullptr, nullptr);  // each image as the model holds it: a view or a uri
    writer.WriteGltfSceneToStream(&model, file, false, path.extension() == ".glb");
  }
  tinygltf::Model model;

 private:
  int view(const void* bytes, std::size_t size) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView buffer_view;
    buffer_view.buffer = 0;
    buffer_view.byteOffset = data.size();
    buffer_view.byteLength = size;
    const auto* first = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), first, first + size);
    data.resize((data.size() + 3) / 4 * 4);
    model.bufferViews.push_back(buffer_view);
    return int(model.bufferViews.size() - 1);
  }
  int texture(tinygltf::Image image) {
    model.images.push_back(std::move(image));
    model.textures.emplace_back();
    model.textures.back().source = int(model.images.size() - 1);
    return int(model.textures.size() - 1);
  }
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

// A strip of eight triangles, x in [0, 4] and y in [0, 1], skinned by two joints whose weights
// vary linearly along it, 1 - x / 4 and x / 4 (JOINTS_0 u8, WEIGHTS_0 float, exact in float). Its
// node (0) is moved by 100 along x, which glTF ignores for a skinned mesh. The joints: "root"
// (node 1, at the origin, the skin's skeleton and a root of the scene) holds "tip" (node 2,
// moved by 4 along x); their inverse bind matrices are the identity and a move by -4 along x.
inline Gltf_builder skinned_strip() {
  Gltf_builder b;
  std::vector<float> points, weights;
  std::vector<std::uint8_t> joints;
  std::vector<std::uint16_t> indices;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 1; ++y) {
      points.insert(points.end(), {float(x), float(y), 0});
      joints.insert(joints.end(), {0, 1, 0, 0});
      weights.insert(weights.end(), {1 - float(x) / 4, float(x) / 4, 0, 0});
    }
  for (std::uint16_t x = 0; x < 4; ++x) {
    const std::uint16_t low = std::uint16_t(2 * x), high = std::uint16_t(2 * x + 1);
    indices.insert(indices.end(), {low, std::uint16_t(low + 2), high, high, std::uint16_t(low + 2),
                                   std::uint16_t(high + 2)});
  }
  tinygltf::Primitive strip = triangles(
      b.accessor(points, kFloat, TINYGLTF_TYPE_VEC3),
      b.accessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR), -1, -1);
  strip.attributes["JOINTS_0"] =
      b.accessor(joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4);
  strip.attributes["WEIGHTS_0"] = b.accessor(weights, kFloat, TINYGLTF_TYPE_VEC4);
  b.place({strip}, {100, 0, 0});
  b.model.nodes[0].skin = 0;
  b.model.nodes.resize(3);
  b.model.nodes[1].name = "root";
  b.model.nodes[1].children = {2};
  b.model.nodes[2].name = "tip";
  b.model.nodes[2].translation = {4, 0, 0};
  b.model.scenes[0].nodes = {0, 1};
  tinygltf::Skin skin;
  skin.joints = {1, 2};
  skin.skeleton = 1;
  skin.inverseBindMatrices =
      b.accessor(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1,  // root
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -4, 0, 0, 1},
                 kFloat, TINYGLTF_TYPE_MAT4);
  b.model.skins.push_back(skin);
  return b;
}

// Any bytes: the reader and the writer never decode an image.
inline const std::string kImageBytes = std::string("\x89PNG\r\n\x1a\n", 8) + "not decoded";
inline const std::string kJpegBytes = std::string("\xff\xd8\xff\xe0", 4) + "not decoded";
inline const std::string kJpegDataUri = "data:image/jpeg;base64,/9j/4G5vdCBkZWNvZGVk";  // of those

// two_primitive_square() with three images, each the source of the texture of its index: a PNG in
// a bufferView (kImageBytes), the file tex/skin.png and a JPEG in a data URI (kJpegBytes). Its
// first primitive's material, "paint", has base colour (0.5, 0.25, 1) and alpha 0.5, which its
// alphaMode OPAQUE ignores, and texture `paint_texture`; its second's, unnamed, baseColorFactor
// (0.2, 0.4, 0.6, 0.5), alphaMode BLEND, and the file's texture; a third material, "unused", that
// no primitive has, texture `unused_texture`.
inline Gltf_builder textured_square(int paint_texture, int unused_texture) {
  Gltf_builder b = two_primitive_square();
  b.held_image(kImageBytes, "image/png");
  b.image_at("tex/skin.png");
  b.image_at(kJpegDataUri);
  std::vector<tinygltf::Material>& materials = b.model.materials;
  materials.resize(3);
  materials[0].pbrMetallicRoughness.baseColorFactor = {0.5, 0.25, 1, 0.5};
  materials[0].pbrMetallicRoughness.baseColorTexture.index = paint_texture;
  materials[1].pbrMetallicRoughness.baseColorFactor = {0.2, 0.4, 0.6, 0.5};
  materials[1].alphaMode = "BLEND";
  materials[1].pbrMetallicRoughness.baseColorTexture.index = 1;
  materials[2].name = "unused";
  materials[2].pbrMetallicRoughness.baseColorTexture.index = unused_texture;
  return b;
}

}  // namespace gltf_fixtures

#endif  // CGAL_POLICIES_TESTS_APPS_GLTF_BUILDER_H
