// The policies the apps can run, by the names of policies.md §4, each behind one entry point so
// that simplify, simplify_bench and the viewer drive them all the same way.
#ifndef CGAL_POLICIES_APPS_POLICY_REGISTRY_H
#define CGAL_POLICIES_APPS_POLICY_REGISTRY_H

#include "Mesh_types.h"

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace apps {

struct Policy_option {
  std::string name;  // the command-line option without its leading "--"
  double default_value;
  std::string help;
  bool is_flag = false;  // given without a value; 1 when present, 0 when absent
};

struct Simplify_settings {
  std::size_t target_faces = 0;
  double max_normal_angle_deg = 90;  // flip prevention of our own policies (policies.md §0)
  double max_error = 0;  // two-sided Hausdorff bound, a fraction of the input's diagonal; 0: none
  // The edge-collapse policies stop where they are after this many seconds (0: no limit); the
  // others finish in seconds and do not look at it.
  double time_limit_seconds = 0;
  std::map<std::string, double> options;               // the policy's options, defaults filled in
  std::function<void(std::size_t faces)> on_progress;  // called now and then; may be empty
  // Called after every collapse with the vertex that disappeared and the one that stayed (already
  // at its new point); may be empty. The viewer records collapse sequences through it.
  std::function<void(Mesh::Vertex_index removed, Mesh::Vertex_index kept)> on_collapse;
};

struct Simplify_outcome {
  double seconds = 0;       // the simplification alone
  std::string stop_reason;  // "target_reached", "no_collapse_left" or "time_limit"
};

struct Policy_entry {
  std::string name;
  std::string summary;
  std::vector<Policy_option> options;
  std::function<Simplify_outcome(Mesh&, const Simplify_settings&)> run;
};

const std::vector<Policy_entry>& policy_registry();

// The entry of that name, or nullptr.
const Policy_entry* find_policy(const std::string& name);

// "gh|gh-prob|lt|classic": for help texts and error messages.
std::string policy_names();

// Settings with the policy's option defaults, for callers that set nothing else.
Simplify_settings default_settings(const Policy_entry& policy, std::size_t target_faces);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_POLICY_REGISTRY_H
