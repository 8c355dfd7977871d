#include "pass_options.h"

#include "App_error.h"

namespace apps {

cgal_policies::Smoothing_options take_smoothing_options(Command_line& cli) {
  cgal_policies::Smoothing_options smoothing;
  // Each pass is linear in the mesh: 10,000 are hours on a large scan, and more never end.
  if (const auto n = cli.take_whole_number("smooth", 0, 10000)) smoothing.iterations = int(*n);
  if (const auto rate = cli.take_number("smooth-rate")) {
    if (!(*rate > 0 && *rate <= 1)) throw App_error(exit_usage, "--smooth-rate must be in (0, 1]");
    smoothing.rate = *rate;
  }
  if (const auto weights = cli.take_value("smooth-weights")) {
    if (*weights == "inverse-distance")
      smoothing.weights = cgal_policies::Smoothing_weights::inverse_distance;
    else if (*weights != "uniform")
      throw App_error(exit_usage, "--smooth-weights must be uniform or inverse-distance");
  }
  if (const auto method = cli.take_value("smooth-method")) {
    if (*method == "taubin")
      smoothing.method = cgal_policies::Smoothing_method::taubin;
    else if (*method != "laplacian")
      throw App_error(exit_usage, "--smooth-method must be laplacian or taubin");
  }
  smoothing.bounded = cli.take_flag("smooth-bounded");
  return smoothing;
}

double take_prepass_factor(Command_line& cli) {
  const double factor = cli.take_number("prepass").value_or(0.0);
  if (!(factor == 0 || (factor >= 1 && factor <= kMaxCount)))
    throw App_error(exit_usage, "--prepass must be 0 (off) or a factor of at least 1");
  return factor;
}

std::string smoothing_help() {
  return "  --smooth N            N passes of Laplacian smoothing after simplifying, 0..10000\n"
         "                        (default 0)\n"
         "  --smooth-rate R       lambda, 0 < R <= 1 (default 0.5)\n"
         "  --smooth-weights W    uniform (default) or inverse-distance\n"
         "  --smooth-method M     laplacian (default) or taubin (lambda, then mu = -0.53)\n"
         "  --smooth-bounded      skip moves that would take the output farther than the\n"
         "                        tolerance (--max-error, or the policy's --tolerance) from IN\n";
}

void take_fit_options(Command_line& cli, bool policy_named,
                      cgal_policies::Simplification_options& options) {
  if (cli.take_flag("fit"))
    options.fit = true;
  else if (policy_named)
    options.fit = false;
  if (const auto rounds = cli.take_whole_number("fit-rounds", 1, 1000)) {
    if (!options.fit) throw App_error(exit_usage, "--fit-rounds goes with --fit");
    options.fit_options.rounds = int(*rounds);
  }
}

std::string fit_help() {
  return "  --fit                 then fit the output to IN in both directions, moving vertices\n"
         "                        and flipping edges (docs/fitting.md); within the run's bound\n"
         "                        when it has one (--max-error, or the policy's --tolerance).\n"
         "                        Without --policy the default pipeline fits; with one, only\n"
         "                        when asked\n"
         "  --fit-rounds N        fit rounds, each followed by a flip round, 1..1000 (default " +
         std::to_string(cgal_policies::Two_sided_fit_options().rounds) + ")\n";
}

}  // namespace apps
