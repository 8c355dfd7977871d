#include "gltf_material_library.h"

#include "Io_error.h"
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
  const fs::path folder = fs::absolute(obj).parent_path().lexically_normal();
  const std::string stem = obj.stem().string();
  const std::string library_path = (obj.parent_path() / (stem + ".mtl")).string();
  Gltf_material_library library;
  std::vector<Gltf_material_library::File> images;
  // Each image's map_Kd once known, so that materials sharing an image share its file; empty
  // when it cannot be one.
  std::map<int, std::string> map_of_image;
  const auto diffuse_map = [&](int index) {
    const auto [known, first] = map_of_image.emplace(index, "");
    if (!first) return known->second;
    const tinygltf::Image& image = looks.images[std::size_t(index)];
    if (!image.uri.empty()) {
      known->second = fs::path(image.uri).lexically_relative(folder).string();
    } else if (const std::string type = image_mime_type(image.image); !type.empty()) {
      known->second =
          stem + "_image" + std::to_string(index) + (type == "image/png" ? ".png" : ".jpg");
      images.push_back({(obj.parent_path() / known->second).string(),
                        std::string(image.image.begin(), image.image.end())});
    }
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
      if (image >= 0) written.diffuse_map = diffuse_map(image);
      if (written.diffuse_map.empty())
        library.left_out.push_back(library_path + ": material '" + names[m] +
                                   "': its base colour texture has no PNG or JPEG image; "
                                   "written without it");
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
