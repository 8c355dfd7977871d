// Fuzzes simplify's command line (apps::take_simplify_request): the bytes are its arguments,
// separated by NUL or newline. A request must come out checked (every value in its documented
// range), or App_error or Option_error with exit 2 (usage), or Io_error with exit 4 (OUT's folder
// is missing), and one line.
#include "fuzz_checks.h"

#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/simplify_request.h"
#include "io/Io_error.h"
#include "pipeline/Option_error.h"

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

// Written here rather than calling apps::check_option_values: the request was checked by that
// function, and this oracle is what checks it.
bool in_range(const apps::Policy_option& option, double value) {
  if (option.is_flag) return value == 0 || value == 1;
  const bool above_min = option.min_is_excluded ? value > option.min : value >= option.min;
  return std::isfinite(value) && above_min && value <= option.max &&
         (!option.is_whole || value == std::floor(value));
}

void require_checked(const apps::Simplify_request& request) {
  using fuzz::require;
  const apps::Policy_entry* policy = request.policy;
  require(policy != nullptr && policy->policy == request.options.policy, "a policy");
  const cgal_policies::Simplification_options& settings = request.options;
  for (const apps::Policy_option& option : policy->options)
    require(in_range(option, option.get(settings)), "--" + option.name + " in its range");
  require(settings.max_normal_angle_deg >= 0 && settings.max_normal_angle_deg <= 180,
          "--max-normal-angle in [0, 180]");
  require(std::isfinite(settings.max_error) && settings.max_error >= 0, "--max-error >= 0");
  require(
      settings.time_limit_seconds >= 0 && settings.time_limit_seconds <= apps::kMaxTimeLimitSeconds,
      "--time-limit in [0, 1e9]");
  require(std::isfinite(settings.merge_distance) && settings.merge_distance >= 0,
          "--merge-distance >= 0");
  const double bound = settings.two_sided_bound();
  require(std::isfinite(bound) && bound >= 0, "the run's bound >= 0");
  require(!settings.smoothing.bounded || bound > 0, "--smooth-bounded with a bound");
  const cgal_policies::Face_target& target = settings.target;
  require(target.is_ratio() ? target.ratio_value() > 0 && target.ratio_value() <= 1
                            : target.face_count() >= 1,
          "a ratio in (0, 1] or at least one face");
  require(settings.smoothing.iterations >= 0 && settings.smoothing.iterations <= 10000,
          "--smooth in [0, 10000]");
  require(settings.smoothing.rate > 0 && settings.smoothing.rate <= 1, "--smooth-rate in (0, 1]");
  require(
      !settings.fit || (settings.fit_options.rounds >= 1 && settings.fit_options.rounds <= 1000),
      "--fit-rounds in [1, 1000]");
  require(!request.samples || (*request.samples >= 1 && *request.samples <= apps::kMaxCount),
          "--samples in [1, 1e15]");
  require(target.is_ratio() || target.face_count() <= apps::kMaxCount, "--faces <= 1e15");
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
    fuzz::require(error.code() == apps::exit_usage,
                  "exit code " + std::to_string(error.code()) + " for '" + error.what() + "'");
    fuzz::require_one_line(error.what());
  } catch (const apps::Option_error& error) {
    fuzz::require_one_line(error.what());
  } catch (const cgal_policies::io::Io_error& error) {
    fuzz::require(error.kind() == cgal_policies::io::Io_error::Kind::unwritable_output,
                  std::string("only OUT's folder is checked: ") + error.what());
    fuzz::require_one_line(error.what());
  }
  return 0;
}
