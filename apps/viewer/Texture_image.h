// An RGB image to texture a mesh with, rows from the top, read with stb_image.
#ifndef CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H
#define CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H

#include <cstdint>
#include <string>
#include <vector>

namespace apps {

struct Texture_image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  // Throws App_error(exit_bad_input, "<path>: <cause>") when the file is not an image stb reads.
  static Texture_image load(const std::string& path);
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_TEXTURE_IMAGE_H
