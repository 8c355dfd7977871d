// What a `simplify` command line asks for, read and checked whole before any input is read: the
// pipeline's options (policy, target, passes), the files and the report.
#ifndef CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H
#define CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H

#include "Command_line.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Simplification_options.h>

#include <cstddef>
#include <optional>
#include <string>

namespace apps {

struct Simplify_request {
  cgal_policies::Simplification_options options;
  const Policy_entry* policy = nullptr;  // options.policy's entry
  std::optional<std::size_t> samples;    // --samples of --measure
  bool json = false, measure = false, force = false, quiet = false;
  std::string input, output;
};

// Takes every option of simplify but --help and the snapshot's, then IN OUT [RATIO]; App_error
// with exit_usage (bad command line) or Io_error (OUT's folder is missing) otherwise.
Simplify_request take_simplify_request(Command_line& cli);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H
