// The options every app that runs a policy reads the same way: --policy NAME, the policy's own
// options (Policy_option: `--name X`, or `--name` for a flag) and --max-normal-angle A.
#ifndef CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H
#define CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H

#include "App_error.h"
#include "Command_line.h"
#include "policy_registry.h"

#include <string>

namespace apps {

struct Policy_choice {
  const Policy_entry* policy = nullptr;
  Simplify_settings settings;  // options filled in, target_faces left at 0
};

// Takes the options from `cli`; App_error(exit_usage) for an unknown policy.
inline Policy_choice take_policy_options(Command_line& cli, const std::string& default_policy) {
  Policy_choice choice;
  const std::string name = cli.take_value("policy").value_or(default_policy);
  choice.policy = find_policy(name);
  if (!choice.policy)
    throw App_error(exit_usage, "unknown policy '" + name + "' (" + policy_names() + ")");
  choice.settings = default_settings(*choice.policy, 0);
  choice.settings.max_normal_angle_deg = cli.take_number("max-normal-angle").value_or(90.0);
  for (const Policy_option& o : choice.policy->options) {
    if (o.is_flag) {
      if (cli.take_flag(o.name)) choice.settings.options[o.name] = 1;
    } else if (const auto value = cli.take_number(o.name)) {
      choice.settings.options[o.name] = *value;
    }
  }
  return choice;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_POLICY_COMMAND_LINE_H
