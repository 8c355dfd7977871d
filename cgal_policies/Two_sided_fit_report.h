// What a pass of Two_sided_fitter did (docs/fitting.md).
#ifndef CGAL_POLICIES_TWO_SIDED_FIT_REPORT_H
#define CGAL_POLICIES_TWO_SIDED_FIT_REPORT_H

#include <cstddef>

namespace cgal_policies {

struct Two_sided_fit_report {
  int rounds = 0;
  std::size_t moves = 0;          // vertex moves made
  std::size_t refused_moves = 0;  // moves a guard refused (normal, self-intersection, bound)
  std::size_t flips = 0;          // edge flips made
  std::size_t refused_flips = 0;  // helpful flips a guard refused
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_TWO_SIDED_FIT_REPORT_H
