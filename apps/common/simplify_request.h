// What a `simplify` command line asks for, read and checked whole before any input is read: the
// policy and its options, the target, the passes before and after, the files and the report.
#ifndef CGAL_POLICIES_APPS_SIMPLIFY_REQUEST_H
#define CGAL_POLICIES_APPS_SIMPLIFY_REQUEST_H

#include "Command_line.h"
#include "Face_target.h"
#include "fitting.h"
#include "policy_command_line.h"
#include "smoothing.h"

#include <cstddef>
#include <optional>
#include <string>

namespace apps {

struct Simplify_request {
  Policy_choice choice;  // choice.settings.target_faces stays 0 until the input is read
  Face_target target;
  double bound = 0;  // the run's two-sided bound (two_sided_bound), kept by smoothing and fitting
  double merge_distance = 0;
  std::size_t min_component = 0;
  bool drop_small_pieces = false;
  Smoothing_request smoothing;
  Fit_request fit;
  std::optional<std::size_t> samples;  // --samples of --measure
  bool json = false, measure = false, force = false, quiet = false;
  std::string input, output;
};

// Takes every option of simplify but --help and the snapshot's, then IN OUT [RATIO]; App_error
// with exit_usage (bad command line) or exit_bad_output (OUT's folder is missing) otherwise.
Simplify_request take_simplify_request(Command_line& cli);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_SIMPLIFY_REQUEST_H
