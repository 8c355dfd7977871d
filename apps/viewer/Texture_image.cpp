#include "Texture_image.h"

#include "io/Io_error.h"

#include <stb_image.h>

#include <algorithm>
#include <limits>
#include <memory>

namespace apps {

namespace {

// The image of stb's `pixels` (three channels), which it takes and frees; Io_error naming
// `source` when stb read none.
Texture_image from_stb(stbi_uc* pixels, int width, int height, const std::string& source) {
  const std::unique_ptr<stbi_uc, void (*)(void*)> owned(pixels, stbi_image_free);
  if (!owned)
    throw cgal_policies::io::Io_error(cgal_policies::io::Io_error::Kind::unreadable_input,
                                      source + ": " + stbi_failure_reason());
  Texture_image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(owned.get(), owned.get() + std::size_t(width) * std::size_t(height) * 3);
  return image;
}

}  // namespace

Texture_image Texture_image::load(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
  return from_stb(pixels, width, height, path);
}

Texture_image Texture_image::decode(const std::vector<unsigned char>& bytes,
                                    const std::string& source) {
  // stb takes an int length: a larger image is refused rather than read in part.
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
    throw cgal_policies::io::Io_error(cgal_policies::io::Io_error::Kind::unreadable_input,
                                      source + ": too large to decode");
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels =
      stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 3);
  return from_stb(pixels, width, height, source);
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
