#include "gltf_images.h"

#include "material_texture.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <type_traits>

namespace cgal_policies {
namespace io {

void remove_images(tinygltf::Model& looks, const std::vector<bool>& removed) {
  // Each image's new index; -1 for one removed.
  std::vector<int> index_of(looks.images.size(), -1);
  std::vector<tinygltf::Image> kept;
  for (std::size_t i = 0; i < looks.images.size(); ++i)
    if (!removed[i]) {
      index_of[i] = int(kept.size());
      kept.push_back(std::move(looks.images[i]));
    }
  looks.images = std::move(kept);
  const auto new_index = [&](int image) {
    return image >= 0 && std::size_t(image) < index_of.size() ? index_of[std::size_t(image)] : -1;
  };
  std::vector<bool> blank(looks.textures.size(), false);  // textures left without an image
  for (std::size_t t = 0; t < looks.textures.size(); ++t) {
    tinygltf::Texture& texture = looks.textures[t];
    if (texture.source >= 0) {
      texture.source = new_index(texture.source);
      blank[t] = texture.source < 0;
    }
    // The image extensions (EXT_texture_webp, KHR_texture_basisu, ...) name theirs as `source`.
    for (auto extension = texture.extensions.begin(); extension != texture.extensions.end();) {
      const tinygltf::Value& value = extension->second;
      if (!value.IsObject() || !value.Has("source")) {
        ++extension;
        continue;
      }
      const int source = new_index(value.Get("source").GetNumberAsInt());
      if (source < 0) {
        extension = texture.extensions.erase(extension);
        continue;
      }
      tinygltf::Value::Object object = value.Get<tinygltf::Value::Object>();
      object["source"] = tinygltf::Value(source);
      extension->second = tinygltf::Value(std::move(object));
      ++extension;
    }
  }
  for (tinygltf::Material& material : looks.materials)
    for_each_texture(material, [&](auto& info) {
      if (info.index >= 0 && std::size_t(info.index) < blank.size() &&
          blank[std::size_t(info.index)])
        info = std::decay_t<decltype(info)>();
    });
}

Image_file read_image_file(const std::string& path) {
  Image_file image;
  std::error_code failed;
  if (!std::filesystem::is_regular_file(path, failed)) {
    image.failure = "does not exist";
    return image;
  }
  std::ifstream file(path, std::ios::binary);
  image.bytes.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  if (!file.good() && !file.eof()) image.failure = "cannot be read";
  image.mime_type = image_mime_type(image.bytes);
  if (image.failure.empty() && image.mime_type.empty())
    image.failure = "is neither a PNG nor a JPEG image";
  if (!image.failure.empty()) image.bytes.clear();
  return image;
}

}  // namespace io
}  // namespace cgal_policies
