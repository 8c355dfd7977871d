// The command-line options of the passes around the policy (docs/pipeline.md): smoothing and the
// fitting pass, read into cgal_policies::Simplification_options.
#ifndef CGAL_POLICIES_APPS_CLI_PASS_OPTIONS_H
#define CGAL_POLICIES_APPS_CLI_PASS_OPTIONS_H

#include "Command_line.h"

#include <cgal_policies/Simplification_options.h>

#include <string>

namespace apps {

// Takes --smooth N, --smooth-rate R, --smooth-weights uniform|inverse-distance,
// --smooth-method laplacian|taubin and --smooth-bounded; App_error(exit_usage) when malformed.
cgal_policies::Smoothing_options take_smoothing_options(Command_line& cli);

// The lines of the help text that describe those options.
std::string smoothing_help();

// Takes --prepass K (Simplification_options::prepass_factor): 0 when absent; App_error(exit_usage)
// unless K is 0 or at least 1.
double take_prepass_factor(Command_line& cli);

// Takes --fit and --fit-rounds N into `options`. A command line that names a policy runs it alone
// unless --fit is given; one that names none keeps the library's default pipeline, fit included.
// App_error(exit_usage) when malformed.
void take_fit_options(Command_line& cli, bool policy_named,
                      cgal_policies::Simplification_options& options);

// The lines of the help text that describe those options.
std::string fit_help();

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_PASS_OPTIONS_H
