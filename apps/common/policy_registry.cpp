#include "policy_registry.h"

#include "policy_entries.h"

#include <algorithm>

namespace apps {

const std::vector<Policy_entry>& policy_registry() {
  static const std::vector<Policy_entry> registry = [] {
    std::vector<Policy_entry> all;
    for (auto&& group : {cgal_baseline_policies(), classic_policies(), curvature_policies(),
                         fusion_policies(), fast_policies(), hausdorff_policies()})
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

}  // namespace apps
