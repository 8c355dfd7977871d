#include "obj_material_looks.h"

#include "material_texture.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

namespace cgal_policies {
namespace io {
namespace {

// Embeds `map`'s file in `looks` as an image, its bytes as the file holds them, with a texture
// of its own, and returns that texture's index; -1, and the line saying why in `left_out`, when
// there is nothing to embed.
int embedded_texture(const Diffuse_map& map, tinygltf::Model& looks,
                     std::vector<std::string>& left_out) {
  const auto leave_out = [&](const std::string& cause) {
    left_out.push_back(map.library + ": texture " + Asset_folder::quoted(map.file) + " " + cause +
                       "; written without it");
    return -1;
  };
  if (!map.refusal.empty()) return leave_out(map.refusal);
  if (!std::filesystem::is_regular_file(map.path)) return leave_out("does not exist");
  std::ifstream file(map.path, std::ios::binary);
  if (!file) return leave_out("cannot be read");
  tinygltf::Image image;
  image.image.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  image.mimeType = image_mime_type(image.image);
  if (image.mimeType.empty()) return leave_out("is neither a PNG nor a JPEG image");
  image.name = std::filesystem::path(map.file).stem().string();
  looks.images.push_back(std::move(image));
  if (looks.samplers.empty()) {
    // OBJ viewers repeat a texture and filter it through mipmaps.
    looks.samplers.emplace_back();
    looks.samplers[0].magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    looks.samplers[0].minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  }
  tinygltf::Texture texture;
  texture.sampler = 0;
  texture.source = int(looks.images.size() - 1);
  looks.textures.push_back(texture);
  return int(looks.textures.size() - 1);
}

}  // namespace

std::shared_ptr<const tinygltf::Model> obj_material_looks(const Material_references& materials,
                                                          bool textured,
                                                          std::vector<std::string>& left_out) {
  auto looks = std::make_shared<tinygltf::Model>();
  const std::vector<std::optional<Diffuse_map>> maps =
      textured ? diffuse_maps(materials)
               : std::vector<std::optional<Diffuse_map>>(materials.names.size());
  std::map<std::string, int> texture_of_file;  // by path, so that each file is embedded once
  for (std::size_t m = 0; m < materials.names.size(); ++m) {
    tinygltf::Material material;
    material.name = materials.names[m];
    if (const std::optional<Diffuse_map>& map = maps[m]) {
      // A refused file has no path: it is known by its line.
      const std::string key = map->refusal.empty() ? map->path : map->library + '\n' + map->file;
      const auto [known, first] = texture_of_file.emplace(key, -1);
      if (first) known->second = embedded_texture(*map, *looks, left_out);
      material.pbrMetallicRoughness.baseColorTexture.index = known->second;
    }
    looks->materials.push_back(std::move(material));
  }
  return looks;
}

}  // namespace io
}  // namespace cgal_policies
