// Records the collapses a policy performs, in order, so that the viewer shows the mesh at any face
// count by replaying them (Collapse_replay.h) instead of simplifying again.
#ifndef CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H
#define CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H

#include "app_types.h"

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/Simplification_report.h>

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
  cgal_policies::Simplification_report report;
};

// Runs the pipeline of `options` on a copy of `input` (which must hold no garbage) down to its
// target, recording every collapse; options.progress is kept.
Collapse_history record_collapses(const Mesh& input, cgal_policies::Simplification_options options);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_COLLAPSE_RECORDER_H
