#include "App_error.h"
#include "Snapshot_renderer.h"

#include <cstdio>

namespace apps {

std::pair<int, int> parse_picture_size(const std::string& text) {
  int width = 0, height = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &rest) != 2 || width < 16 ||
      height < 16 || width > 16384 || height > 16384)
    throw App_error(exit_usage, "--size: '" + text + "' is not WxH with 16 <= W, H <= 16384");
  return {width, height};
}

}  // namespace apps
