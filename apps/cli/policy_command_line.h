// The options every app that runs a policy reads the same way: --policy NAME, the policy's own
// options (Policy_option: `--name X`, or `--name` for a flag) and --max-normal-angle A, all checked
// against their ranges before any input is read.
#ifndef CGAL_POLICIES_APPS_CLI_POLICY_COMMAND_LINE_H
#define CGAL_POLICIES_APPS_CLI_POLICY_COMMAND_LINE_H

#include "Command_line.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Simplification_options.h>

#include <vector>

namespace apps {

// The values of `options` given in `cli` (a flag given counts 1), taken out of it.
Option_values take_option_values(Command_line& cli, const std::vector<Policy_option>& options);

struct Policy_choice {
  const Policy_entry* policy = nullptr;           // --policy, or the library's default
  bool named = false;                             // --policy was given
  cgal_policies::Simplification_options options;  // its options and the angle filled in
};

// Takes --policy, the policy's options and --max-normal-angle from `cli`; App_error(exit_usage)
// for an unknown policy, Option_error for a value out of range.
Policy_choice take_policy_options(Command_line& cli);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_POLICY_COMMAND_LINE_H
