// The options every app that runs a policy reads the same way: --policy NAME, the policy's own
// options (Policy_option: `--name X`, or `--name` for a flag) and --max-normal-angle A, all checked
// against their ranges before any input is read.
#ifndef CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H
#define CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H

#include "App_error.h"
#include "Command_line.h"
#include "policy_registry.h"

#include <string>
#include <vector>

namespace apps {

struct Policy_choice {
  const Policy_entry* policy = nullptr;
  Simplify_settings settings;  // options filled in, target_faces left at 0
};

// The values of `options` given in `cli` (a flag given counts 1), taken out of it.
inline Option_values take_option_values(Command_line& cli,
                                        const std::vector<Policy_option>& options) {
  Option_values values;
  for (const Policy_option& o : options) {
    if (o.is_flag) {
      if (cli.take_flag(o.name)) values[o.name] = 1;
    } else if (const auto value = cli.take_number(o.name)) {
      values[o.name] = *value;
    }
  }
  return values;
}

// Takes the options from `cli`; App_error(exit_usage) for an unknown policy or a value out of
// range.
inline Policy_choice take_policy_options(Command_line& cli, const std::string& default_policy) {
  Policy_choice choice;
  const std::string name = cli.take_value("policy").value_or(default_policy);
  choice.policy = find_policy(name);
  if (!choice.policy)
    throw App_error(exit_usage, "unknown policy '" + name + "' (" + policy_names() + ")");
  choice.settings = default_settings(*choice.policy, 0);
  const double angle = cli.take_number("max-normal-angle").value_or(90.0);
  if (!(angle >= 0 && angle <= 180))
    throw App_error(exit_usage, "--max-normal-angle must be a number in [0, 180] (degrees)");
  choice.settings.max_normal_angle_deg = angle;
  const Option_values given = take_option_values(cli, choice.policy->options);
  check_policy_options(*choice.policy, given);
  for (const auto& [option, value] : given) choice.settings.options[option] = value;
  return choice;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H
