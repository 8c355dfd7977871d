// Records the collapses a policy performs, in order, so that the viewer shows the mesh at any face
// count by replaying them (Collapse_replay.h) instead of simplifying again.
#ifndef CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H
#define CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H

#include "common/policy_registry.h"

#include <cstddef>
#include <vector>

namespace apps {

struct Collapse_record {
  Mesh::Vertex_index removed, kept;
  Point kept_point;  // where `kept` moved
  double seconds;    // since the policy started
};

struct Collapse_history {
  // Empty when the policy does not run through the edge-collapse visitor: the viewer then
  // simplifies straight to each target instead of replaying.
  std::vector<Collapse_record> collapses;
  std::size_t input_faces = 0, final_faces = 0;
  Simplify_outcome outcome;
};

// Runs `policy` on a copy of `input` (which must hold no garbage) down to settings.target_faces,
// recording every collapse; settings.on_progress is kept.
Collapse_history record_collapses(const Mesh& input, const Policy_entry& policy,
                                  Simplify_settings settings);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H
