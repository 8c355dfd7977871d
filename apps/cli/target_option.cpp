#include "target_option.h"

#include "App_error.h"
#include "Command_line.h"

#include <cstddef>

namespace apps {

cgal_policies::Face_target face_target(std::optional<double> ratio, std::optional<double> faces) {
  if (ratio && faces) throw App_error(exit_usage, "give a ratio or --faces, not both");
  if (faces)
    return cgal_policies::Face_target::faces(
        std::size_t(check_whole_number(*faces, 1, kMaxCount, "--faces")));
  if (!ratio) throw App_error(exit_usage, "give RATIO, --ratio or --faces (see --help)");
  if (!(*ratio > 0 && *ratio <= 1))
    throw App_error(exit_usage, "RATIO or --ratio must be a number in (0, 1]");
  return cgal_policies::Face_target::ratio(*ratio);
}

}  // namespace apps
