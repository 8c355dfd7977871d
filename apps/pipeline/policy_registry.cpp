#include "policy_registry.h"

#include "Option_error.h"
#include "policy_entries.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace apps {
namespace {

// Ten significant digits, as the JSON reports print numbers.
std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string range_text(const Policy_option& o) {
  const bool has_min = std::isfinite(o.min), has_max = std::isfinite(o.max);
  const std::string kind = o.is_whole ? "a whole number" : "a number";
  const std::string min = number_text(o.min);
  const std::string max = number_text(o.max);
  if (has_min && has_max)
    return kind + " in " + (o.min_is_excluded ? "(" : "[") + min + ", " + max + "]";
  if (has_min) return kind + (o.min_is_excluded ? " above " : " of at least ") + min;
  if (has_max) return kind + " of at most " + max;
  return kind;
}

bool in_range(const Policy_option& o, double value) {
  if (o.is_flag) return value == 0 || value == 1;
  if (o.is_whole && value != std::floor(value)) return false;
  const bool above_min = o.min_is_excluded ? value > o.min : value >= o.min;
  return above_min && value <= o.max;
}

}  // namespace

const std::vector<Policy_entry>& policy_registry() {
  static const std::vector<Policy_entry> registry = [] {
    std::vector<Policy_entry> all;
    for (auto&& group :
         {cgal_baseline_policies(), classic_policies(), curvature_policies(), fusion_policies(),
          fast_policies(), hausdorff_policies(), attribute_policies()})
      all.insert(all.end(), group.begin(), group.end());
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].policy != cgal_policies::all_simplification_policies[i])
        throw std::logic_error("the registry is not in the library's order of the policies");
    return all;
  }();
  return registry;
}

const Policy_entry* find_policy(const std::string& name) {
  const auto& registry = policy_registry();
  const auto it = std::find_if(registry.begin(), registry.end(),
                               [&](const Policy_entry& p) { return p.name == name; });
  return it == registry.end() ? nullptr : &*it;
}

const Policy_entry& policy_entry(cgal_policies::Simplification_policy policy) {
  return policy_registry()[std::size_t(policy)];
}

std::string policy_names() {
  std::string names;
  for (const Policy_entry& p : policy_registry()) names += (names.empty() ? "" : "|") + p.name;
  return names;
}

const char* const kFitSuffix = "+fit";

std::string pipeline_name(const cgal_policies::Simplification_options& options) {
  return std::string(cgal_policies::policy_name(options.policy)) + (options.fit ? kFitSuffix : "");
}

void check_option_values(const std::string& owner, const std::vector<Policy_option>& options,
                         const Option_values& values) {
  for (const Policy_option& o : options) {
    const auto it = values.find(o.name);
    if (it != values.end() && !in_range(o, it->second))
      throw Option_error("--" + o.name + " must be " + range_text(o) + " (" + owner + "), not " +
                         number_text(it->second));
  }
}

void apply_policy_options(const Policy_entry& policy, const Option_values& values,
                          cgal_policies::Simplification_options& options) {
  check_option_values(policy.name, policy.options, values);
  for (const Policy_option& o : policy.options) {
    const auto it = values.find(o.name);
    if (it != values.end()) o.set(options, it->second);
  }
}

std::string options_help(const std::vector<Policy_option>& options) {
  std::string text;
  for (const Policy_option& o : options) {
    text += "      --" + o.name + (o.is_flag ? "" : " X") + "  " + o.help;
    if (!o.is_flag)
      text += " (default " + number_text(o.default_value) + "; " + range_text(o) + ")";
    text += '\n';
  }
  return text;
}

}  // namespace apps
