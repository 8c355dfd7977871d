#include "Texture_image.h"

#include "common/App_error.h"

#include <stb_image.h>

#include <memory>

namespace apps {

Texture_image Texture_image::load(const std::string& path) {
  Texture_image image;
  int channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &image.width, &image.height, &channels, 3), stbi_image_free);
  if (!data) throw App_error(exit_bad_input, path + ": " + stbi_failure_reason());
  image.rgb.assign(data.get(),
                   data.get() + std::size_t(image.width) * std::size_t(image.height) * 3);
  return image;
}

}  // namespace apps
