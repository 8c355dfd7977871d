#include "Texture_image.h"

#include "io/Io_error.h"

#include <stb_image.h>

#include <algorithm>
#include <memory>

namespace apps {

Texture_image Texture_image::load(const std::string& path) {
  Texture_image image;
  int channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &image.width, &image.height, &channels, 3), stbi_image_free);
  if (!data)
    throw cgal_policies::io::Io_error(cgal_policies::io::Io_error::Kind::unreadable_input,
                                      path + ": " + stbi_failure_reason());
  image.rgb.assign(data.get(),
                   data.get() + std::size_t(image.width) * std::size_t(image.height) * 3);
  return image;
}

std::array<double, 3> Texture_image::color_at(double u, double v) const {
  // Texel (i, j) has its centre at ((i + 0.5) / width, 1 - (j + 0.5) / height).
  const double x = std::clamp(u * width - 0.5, 0.0, double(width - 1)),
               y = std::clamp((1 - v) * height - 0.5, 0.0, double(height - 1));
  const int i = std::min(int(x), std::max(width - 2, 0)),
            j = std::min(int(y), std::max(height - 2, 0));
  const int i1 = std::min(i + 1, width - 1), j1 = std::min(j + 1, height - 1);
  const double fx = x - i, fy = y - j;
  const auto texel = [&](int column, int row, int channel) {
    return rgb[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * 3 +
               std::size_t(channel)] /
           255.0;
  };
  std::array<double, 3> color{};
  for (int c = 0; c < 3; ++c)
    color[std::size_t(c)] = (1 - fy) * ((1 - fx) * texel(i, j, c) + fx * texel(i1, j, c)) +
                            fy * ((1 - fx) * texel(i, j1, c) + fx * texel(i1, j1, c));
  return color;
}

}  // namespace apps
