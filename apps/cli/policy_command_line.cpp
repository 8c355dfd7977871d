#include "policy_command_line.h"

#include "App_error.h"

#include <string>

namespace apps {

Option_values take_option_values(Command_line& cli, const std::vector<Policy_option>& options) {
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

Policy_choice take_policy_options(Command_line& cli) {
  Policy_choice choice;
  const std::optional<std::string> name = cli.take_value("policy");
  choice.named = bool(name);
  choice.policy = name ? find_policy(*name) : &policy_entry(choice.options.policy);
  if (!choice.policy)
    throw App_error(exit_usage, "unknown policy '" + *name + "' (" + policy_names() + ")");
  choice.options.policy = choice.policy->policy;
  const double angle = cli.take_number("max-normal-angle").value_or(90.0);
  if (!(angle >= 0 && angle <= 180))
    throw App_error(exit_usage, "--max-normal-angle must be a number in [0, 180] (degrees)");
  choice.options.max_normal_angle_deg = angle;
  apply_policy_options(*choice.policy, take_option_values(cli, choice.policy->options),
                       choice.options);
  return choice;
}

}  // namespace apps
