// The face target of a run, given as a ratio of the input's faces or as a count, checked when it is
// given and resolved once the input is known.
#ifndef CGAL_POLICIES_APPS_FACE_TARGET_H
#define CGAL_POLICIES_APPS_FACE_TARGET_H

#include "App_error.h"
#include "Command_line.h"

#include <cmath>
#include <cstddef>
#include <optional>

namespace apps {

class Face_target {
 public:
  Face_target() = default;
  // App_error(exit_usage) unless exactly one of the two is given and in range.
  Face_target(std::optional<double> ratio, std::optional<double> faces) : m_ratio(ratio) {
    if (ratio && faces) throw App_error(exit_usage, "give a ratio or --faces, not both");
    if (faces) {
      m_faces = std::size_t(check_whole_number(*faces, 1, kMaxCount, "--faces"));
      return;
    }
    if (!ratio) throw App_error(exit_usage, "give RATIO, --ratio or --faces (see --help)");
    if (!(*ratio > 0 && *ratio <= 1))
      throw App_error(exit_usage, "RATIO or --ratio must be a number in (0, 1]");
  }

  std::size_t of(std::size_t input_faces) const {
    return m_ratio ? std::size_t(std::llround(*m_ratio * double(input_faces))) : m_faces;
  }
  const std::optional<double>& ratio() const { return m_ratio; }

 private:
  std::optional<double> m_ratio;
  std::size_t m_faces = 0;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_FACE_TARGET_H
