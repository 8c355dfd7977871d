// The policies of cgal_policies::Simplification_pipeline as the command line names them: each
// one's name, summary and options (`--name X`), every option bound to its field of
// cgal_policies::Simplification_options with the library's default and its documented range, so
// that simplify, simplify_bench, mesh_viewer and the fuzzers read and check them the same way.
#ifndef CGAL_POLICIES_APPS_PIPELINE_POLICY_REGISTRY_H
#define CGAL_POLICIES_APPS_PIPELINE_POLICY_REGISTRY_H

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/Simplification_policy.h>

#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace apps {

// One command-line option of a policy; Policy_options_table binds it to the library's struct.
struct Policy_option {
  std::string name;  // the command-line option without its leading "--"
  std::string help;
  double default_value = 0;
  bool is_flag = false;  // given without a value; 1 when present, 0 when absent
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_is_excluded = false;
  bool is_whole = false;  // a whole number
  // Writes a value already checked against the range into the options (a flag: 0 or 1).
  std::function<void(cgal_policies::Simplification_options&, double)> set;
  // Reads it back, for the reports.
  std::function<double(const cgal_policies::Simplification_options&)> get;
};

struct Policy_entry {
  cgal_policies::Simplification_policy policy;
  std::string name;  // cgal_policies::policy_name(policy)
  std::string summary;
  std::vector<Policy_option> options;
};

// Option values by name, as a command line gives them.
using Option_values = std::map<std::string, double>;

// Every policy, in the order of cgal_policies::all_simplification_policies.
const std::vector<Policy_entry>& policy_registry();

// The entry of that name, or nullptr.
const Policy_entry* find_policy(const std::string& name);
const Policy_entry& policy_entry(cgal_policies::Simplification_policy policy);

// "gh|gh-prob|lt|classic|...": for help texts and error messages.
std::string policy_names();

// The suffix of a pipeline that fits its output ("lt+fit").
extern const char* const kFitSuffix;

// "P" or "P+fit": how the tables and pictures name what a run did.
std::string pipeline_name(const cgal_policies::Simplification_options& options);

// Option_error naming the first of `values` outside its option's range (`owner`: whose option it
// is); names not among `options` are left alone.
void check_option_values(const std::string& owner, const std::vector<Policy_option>& options,
                         const Option_values& values);

// The policy's options in `options`, each set to the value `values` gives it, after checking
// every value: Option_error naming the first one outside its option's range. Names that
// are not the policy's are left alone.
void apply_policy_options(const Policy_entry& policy, const Option_values& values,
                          cgal_policies::Simplification_options& options);

// "--name X  help (default D, range)" lines for a help text.
std::string options_help(const std::vector<Policy_option>& options);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_PIPELINE_POLICY_REGISTRY_H
