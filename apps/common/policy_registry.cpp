#include "policy_registry.h"

#include "App_error.h"
#include "Json_object.h"
#include "policy_entries.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace apps {
namespace {

std::string range_text(const Policy_option& o) {
  const bool has_min = std::isfinite(o.min), has_max = std::isfinite(o.max);
  const std::string kind = o.is_whole ? "a whole number" : "a number";
  const std::string min = Json_object::format_number(o.min);
  const std::string max = Json_object::format_number(o.max);
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

std::string policy_names() {
  std::string names;
  for (const Policy_entry& p : policy_registry()) names += (names.empty() ? "" : "|") + p.name;
  return names;
}

Simplify_settings default_settings(const Policy_entry& policy, std::size_t target_faces) {
  Simplify_settings settings;
  settings.target_faces = target_faces;
  for (const Policy_option& o : policy.options) settings.options[o.name] = o.default_value;
  return settings;
}

const char* corner_attributes_word(bool input_had_them, const Simplify_outcome& outcome) {
  if (!input_had_them) return "none";
  if (!outcome.attributes_carried)
    throw std::logic_error("a policy of the registry did not carry the corner attributes");
  return "carried";
}

void check_policy_options(const Policy_entry& policy, const Option_values& values) {
  for (const Policy_option& o : policy.options) {
    const auto it = values.find(o.name);
    if (it != values.end() && !in_range(o, it->second))
      throw App_error(exit_usage, "--" + o.name + " must be " + range_text(o) + " (" + policy.name +
                                      "), not " + Json_object::format_number(it->second));
  }
}

std::string policy_options_help(const Policy_entry& policy) {
  std::string text;
  for (const Policy_option& o : policy.options) {
    text += "      --" + o.name + (o.is_flag ? "" : " X") + "  " + o.help;
    if (!o.is_flag)
      text +=
          " (default " + Json_object::format_number(o.default_value) + "; " + range_text(o) + ")";
    text += '\n';
  }
  return text;
}

}  // namespace apps
