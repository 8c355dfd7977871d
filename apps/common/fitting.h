// The fitting pass as a post-process of any policy (docs/fitting.md): its command-line options, the
// run through cgal_policies::Two_sided_fitter, and "P+fit" entries for the benchmark and viewer.
#ifndef CGAL_POLICIES_APPS_FITTING_H
#define CGAL_POLICIES_APPS_FITTING_H

#include "Command_line.h"
#include "Mesh_types.h"
#include "policy_registry.h"

#include <cgal_policies/Two_sided_fit_report.h>

#include <optional>
#include <string>

namespace apps {

struct Fit_request {
  bool enabled = false;
  int rounds = 0;  // take_fit_options fills in the library's default
};

// Takes --fit and --fit-rounds N; App_error(exit_usage) when malformed.
Fit_request take_fit_options(Command_line& cli);

// The lines of the help text that describe those options.
std::string fit_help();

// The two-sided bound a run keeps (a fraction of the input's diagonal): --max-error, else the
// policy's own bound option; 0 when it has none.
double two_sided_bound(const Policy_entry& policy, const Simplify_settings& settings);

struct Fit_outcome {
  cgal_policies::Two_sided_fit_report report;
  double seconds = 0;
};

// Fits `mesh` to `original`, within `bound` when it is positive.
Fit_outcome fit_to_input(Mesh& mesh, const Mesh& original, int rounds, double max_normal_angle_deg,
                         double bound);

// "P+fit": runs `policy`, then fits its output to the mesh it was given, within the run's bound.
// The outcome's seconds stay the simplification's; the pass's are in fit_seconds.
Policy_entry with_fit(const Policy_entry& policy);

// The suffix of those entries' names.
extern const char* const kFitSuffix;

// P for a "P+fit" name; nothing for any other name.
std::optional<std::string> fitted_base(const std::string& name);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_FITTING_H
