// The policies the apps can run, each behind one entry point so that simplify, simplify_bench and
// the viewer drive them all the same way (docs/evaluation.md names them).
#ifndef CGAL_POLICIES_APPS_POLICY_REGISTRY_H
#define CGAL_POLICIES_APPS_POLICY_REGISTRY_H

#include "Mesh_types.h"
#include "Stop_reason.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace apps {

// One command-line option of a policy; Policy_options_table fills it from the library's struct.
struct Policy_option {
  std::string name;  // the command-line option without its leading "--"
  std::string help;
  double default_value = 0;
  bool is_flag = false;  // given without a value; 1 when present, 0 when absent
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_is_excluded = false;
  bool is_whole = false;  // a whole number
};

// Option values by name, as given on a command line; checked by check_policy_options.
using Option_values = std::map<std::string, double>;

struct Simplify_settings {
  std::size_t target_faces = 0;
  double max_normal_angle_deg = 90;  // flip prevention of our own policies (docs/quadric_core.md)
  double max_error = 0;  // two-sided Hausdorff bound, a fraction of the input's diagonal; 0: none
  // The edge-collapse policies stop where they are after this many seconds (0: no limit); the
  // others (Policy_entry::takes_time_limit) finish in seconds and do not look at it.
  double time_limit_seconds = 0;
  Option_values options;                               // the policy's options, defaults filled in
  std::function<void(std::size_t faces)> on_progress;  // called now and then; may be empty
  // Called after every collapse with the vertex that disappeared and the one that stayed (already
  // at its new point); may be empty. The viewer records collapse sequences through it.
  std::function<void(Mesh::Vertex_index removed, Mesh::Vertex_index kept)> on_collapse;
};

struct Simplify_outcome {
  double seconds = 0;  // the simplification alone
  Stop_reason stop_reason = Stop_reason::no_collapse_left;
  double fit_seconds = 0;           // the fitting pass after it, when there is one (fitting.h)
  std::size_t fit_flips = 0;        // the edges that pass flipped
  bool attributes_carried = false;  // the corner attributes were carried through the collapses
};

struct Policy_entry {
  using Run = std::function<Simplify_outcome(Mesh&, const Simplify_settings&)>;

  Policy_entry(std::string its_name, std::string its_summary,
               std::vector<Policy_option> its_options, Run its_run)
      : name(std::move(its_name)),
        summary(std::move(its_summary)),
        options(std::move(its_options)),
        run(std::move(its_run)) {}

  std::string name;
  std::string summary;
  std::vector<Policy_option> options;
  Run run;
  bool takes_error_bound = true;  // whether --max-error can bound it
  bool takes_time_limit = true;   // whether it stops at Simplify_settings::time_limit_seconds
  // Its own two-sided bound in these settings (a fraction of the input's diagonal); empty or 0
  // when it keeps none.
  std::function<double(const Simplify_settings&)> own_bound;
};

const std::vector<Policy_entry>& policy_registry();

// The entry of that name, or nullptr.
const Policy_entry* find_policy(const std::string& name);

// "gh|gh-prob|lt|classic": for help texts and error messages.
std::string policy_names();

// The JSON's word for a run's corner attributes: "carried" when the input had texture coordinates,
// normals or colours (every policy of the registry carries them through its collapses), "none"
// when it had none.
const char* corner_attributes_word(bool input_had_them, const Simplify_outcome& outcome);

// Settings with the policy's option defaults, for callers that set nothing else.
Simplify_settings default_settings(const Policy_entry& policy, std::size_t target_faces);

// App_error(exit_usage) naming the first value of `values` outside its option's range.
void check_policy_options(const Policy_entry& policy, const Option_values& values);

// "--name X  help (default D, range)" lines for a help text.
std::string policy_options_help(const Policy_entry& policy);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_POLICY_REGISTRY_H
