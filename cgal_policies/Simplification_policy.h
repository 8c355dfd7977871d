// Simplification_policy: the policies Simplification_pipeline runs, by the names the command line,
// the benchmark and the Python module give them (docs/policies.md).
//   gh, gh_probabilistic, lt   CGAL's GarlandHeckbert_plane_policies,
//                              GarlandHeckbert_probabilistic_plane_policies, LindstromTurk
//   classic, curvature, fusion, hausdorff, attributes   this library's edge-collapse policies
//   fast                       Fast_threshold_simplifier, its own flat-array engine
//   flat_lt                    Flat_lindstrom_turk_simplifier: lt's cost and placement, on flat
//                              arrays
#ifndef CGAL_POLICIES_SIMPLIFICATION_POLICY_H
#define CGAL_POLICIES_SIMPLIFICATION_POLICY_H

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace cgal_policies {

enum class Simplification_policy {
  gh,
  gh_probabilistic,
  lt,
  classic,
  curvature,
  fusion,
  fast,
  flat_lt,
  hausdorff,
  attributes
};

// Every policy, in the order the tables list them.
inline constexpr std::array<Simplification_policy, 10> all_simplification_policies = {
    Simplification_policy::gh,        Simplification_policy::gh_probabilistic,
    Simplification_policy::lt,        Simplification_policy::classic,
    Simplification_policy::curvature, Simplification_policy::fusion,
    Simplification_policy::fast,      Simplification_policy::flat_lt,
    Simplification_policy::hausdorff, Simplification_policy::attributes};

inline const char* policy_name(Simplification_policy policy) {
  static constexpr std::array<const char*, all_simplification_policies.size()> names = {
      "gh",     "gh-prob", "lt",      "classic",   "curvature",
      "fusion", "fast",    "flat-lt", "hausdorff", "attributes"};
  return names[std::size_t(policy)];
}

// The policy of that name, or nothing.
inline std::optional<Simplification_policy> policy_named(const std::string& name) {
  for (const Simplification_policy policy : all_simplification_policies)
    if (name == policy_name(policy)) return policy;
  return std::nullopt;
}

// Whether the policy runs inside SMS::edge_collapse, where a max_error bound certifies each
// collapse and the stop predicate watches the clock; the flat-array engines have neither hook.
inline bool runs_edge_collapse(Simplification_policy policy) {
  return policy != Simplification_policy::fast && policy != Simplification_policy::flat_lt;
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SIMPLIFICATION_POLICY_H
