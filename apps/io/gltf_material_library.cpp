#include "gltf_material_library.h"

#include "Asset_folder.h"
#include "Io_error.h"
#include "gltf_images.h"
#include "material_texture.h"
#include "obj_writer.h"

#include <tiny_gltf.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <system_error>

namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {

int base_color_image(const tinygltf::Model& looks, std::size_t material) {
  const int texture = looks.materials[material].pbrMetallicRoughness.baseColorTexture.index;
  if (texture < 0 || std::size_t(texture) >= looks.textures.size()) return -1;
  const int image = looks.textures[std::size_t(texture)].source;
  return image >= 0 && std::size_t(image) < looks.images.size() ? image : -1;
}

Gltf_material_library gltf_material_library(const tinygltf::Model& looks,
                                            const std::vector<std::string>& names,
                                            const std::vector<bool>& used,
                                            const std::string& path) {
  const fs::path obj(path);
  const Asset_folder folder = Asset_folder::holding(fs::absolute(obj).parent_path());
  const std::string stem = obj.stem().string();
  const std::string library_path = (obj.parent_path() / (stem + ".mtl")).string();
  Gltf_material_library library;
  std::vector<Gltf_material_library::File> images;
  // Each image's map_Kd once known, so that materials sharing an image share its file; an empty
  // map when it cannot be one, and why when it is a file that cannot be read.
  struct Map {
    std::string file, failure;
  };
  std::map<int, Map> map_of_image;
  const auto diffuse_map = [&](int index) {
    const auto [known, first] = map_of_image.emplace(index, Map());
    if (!first) return known->second;
    const tinygltf::Image& image = looks.images[std::size_t(index)];
    Image_file bytes{image.image, image_mime_type(image.image), ""};
    if (!image.uri.empty()) {
      // A file in the library's folder is named; any other is copied beside it.
      if (const Asset_folder::Resolved inside = folder.check(image.uri); inside.refusal.empty()) {
        known->second.file = inside.path.lexically_relative(folder.root()).string();
        return known->second;
      }
      bytes = read_image_file(image.uri);
      if (!bytes.failure.empty()) known->second.failure = "'" + image.uri + "' " + bytes.failure;
    }
    if (bytes.mime_type.empty() || !bytes.failure.empty()) return known->second;
    known->second.file = stem + "_image" + std::to_string(index) +
                         (bytes.mime_type == "image/png" ? ".png" : ".jpg");
    images.push_back({(obj.parent_path() / known->second.file).string(),
                      std::string(bytes.bytes.begin(), bytes.bytes.end())});
    return known->second;
  };
  std::vector<Mtl_material> materials;
  for (std::size_t m = 0; m < names.size() && m < looks.materials.size(); ++m) {
    if (!used[m]) continue;
    const tinygltf::Material& material = looks.materials[m];
    Mtl_material written{names[m], {1, 1, 1}, 1, ""};
    const std::vector<double>& factor = material.pbrMetallicRoughness.baseColorFactor;
    if (factor.size() == 4) {
      written.diffuse = {factor[0], factor[1], factor[2]};
      if (material.alphaMode != "OPAQUE") written.opacity = factor[3];
    }
    if (material.pbrMetallicRoughness.baseColorTexture.index >= 0) {
      const int image = base_color_image(looks, m);
      const Map map = image >= 0 ? diffuse_map(image) : Map();
      written.diffuse_map = map.file;
      if (written.diffuse_map.empty())
        library.left_out.push_back(library_path + ": material '" + names[m] + "': " +
                                   (map.failure.empty()
                                        ? "its base colour texture has no PNG or JPEG image"
                                        : "the image of its base colour texture, " + map.failure) +
                                   "; written without it");
    }
    materials.push_back(std::move(written));
  }
  if (materials.empty()) return library;
  library.files.push_back({library_path, mtl_text(materials)});
  library.files.insert(library.files.end(), images.begin(), images.end());
  return library;
}

void check_no_image_of(const tinygltf::Model& looks, const std::vector<std::string>& files) {
  for (const std::string& file : files)
    for (const tinygltf::Image& image : looks.images) {
      std::error_code missing;  // a file that does not exist overwrites nothing
      if (!image.uri.empty() && fs::equivalent(file, image.uri, missing))
        throw Io_error(Io_error::Kind::unwritable_output,
                       file + ": refusing to overwrite an image of the input");
    }
}

}  // namespace io
}  // namespace cgal_policies
