// An RGB image to texture a mesh with, rows from the top, read with stb_image.
#ifndef CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H
#define CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace apps {

struct Texture_image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  // Throws Io_error (unreadable input, "<path>: <cause>") when the file is not an image stb reads.
  static Texture_image load(const std::string& path);
  // The image whose file's bytes are `bytes` (a glTF file holds its images so); throws as load,
  // naming `source`.
  static Texture_image decode(const std::vector<unsigned char>& bytes, const std::string& source);

  // The colour (red, green, blue in [0, 1]) at texture coordinates (u, v), v = 0 being the bottom
  // row, filtered as the renderer draws it: bilinear between texel centres, clamped at the edges.
  std::array<double, 3> color_at(double u, double v) const;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H
