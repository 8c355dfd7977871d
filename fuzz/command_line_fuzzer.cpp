// Fuzzes simplify's command line (apps::take_simplify_request): the bytes are its arguments,
// separated by NUL or newline. A request must come out checked (every value in its documented
// range), or App_error with exit 2 (usage) or 4 (OUT's folder is missing) and one line.
#include "fuzz_checks.h"

#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/simplify_request.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kMaxArguments = 40;

std::vector<std::string> arguments(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"simplify"};
  std::string current;
  for (std::size_t i = 0; i <= size && args.size() <= kMaxArguments; ++i) {
    if (i == size || data[i] == '\0' || data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += char(data[i]);
    }
  }
  return args;
}

// Written here rather than calling apps::check_policy_options: the request was checked by that
// function, and this oracle is what checks it.
bool in_range(const apps::Policy_option& option, double value) {
  if (option.is_flag) return value == 0 || value == 1;
  const bool above_min = option.min_is_excluded ? value > option.min : value >= option.min;
  return std::isfinite(value) && above_min && value <= option.max &&
         (!option.is_whole || value == std::floor(value));
}

void require_checked(const apps::Simplify_request& request) {
  using fuzz::require;
  const apps::Policy_entry* policy = request.choice.policy;
  require(policy != nullptr, "a policy");
  const apps::Simplify_settings& settings = request.choice.settings;
  for (const apps::Policy_option& option : policy->options) {
    const auto value = settings.options.find(option.name);
    require(value != settings.options.end(), "--" + option.name + " has a value");
    require(in_range(option, value->second), "--" + option.name + " in its range");
  }
  require(settings.max_normal_angle_deg >= 0 && settings.max_normal_angle_deg <= 180,
          "--max-normal-angle in [0, 180]");
  require(std::isfinite(settings.max_error) && settings.max_error >= 0, "--max-error >= 0");
  require(
      settings.time_limit_seconds >= 0 && settings.time_limit_seconds <= apps::kMaxTimeLimitSeconds,
      "--time-limit in [0, 1e9]");
  require(std::isfinite(request.merge_distance) && request.merge_distance >= 0,
          "--merge-distance >= 0");
  require(std::isfinite(request.bound) && request.bound >= 0, "the run's bound >= 0");
  const auto& ratio = request.target.ratio();
  require(ratio ? *ratio > 0 && *ratio <= 1 : request.target.of(0) >= 1,
          "a ratio in (0, 1] or at least one face");
  require(request.smoothing.iterations >= 0 && request.smoothing.iterations <= 10000,
          "--smooth in [0, 10000]");
  require(request.smoothing.rate > 0 && request.smoothing.rate <= 1, "--smooth-rate in (0, 1]");
  require(!request.fit.enabled || (request.fit.rounds >= 1 && request.fit.rounds <= 1000),
          "--fit-rounds in [1, 1000]");
  require(!request.samples || (*request.samples >= 1 && *request.samples <= apps::kMaxCount),
          "--samples in [1, 1e15]");
  require(request.target.ratio() || request.target.of(0) <= apps::kMaxCount, "--faces <= 1e15");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = arguments(data, size);
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  try {
    apps::Command_line cli(int(argv.size()), argv.data());
    require_checked(apps::take_simplify_request(cli));
  } catch (const apps::App_error& error) {
    fuzz::require_one_line_error(
        error, error.code() == apps::exit_bad_output ? apps::exit_bad_output : apps::exit_usage);
  }
  return 0;
}
