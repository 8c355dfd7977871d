// The interactive mesh_viewer: a GLFW window with the original and the simplified mesh side by
// side (Scene_renderer.h) and a Dear ImGui panel (policy, its options, the target face count,
// shading, wireframe, error heat map, live figures). Each policy's collapses are recorded once in
// the background (collapse_recorder.h), so the target slider replays them at once. A mesh with a
// texture or colours is drawn with them, and so are the results that carry them. A file with levels
// of detail shows one at a time in the left pane, and the panel simplifies the level shown: the
// panel's slider, PageUp/PageDown or [ ] step through them.
#ifndef CGAL_POLICIES_APPS_VIEWER_VIEWER_WINDOW_H
#define CGAL_POLICIES_APPS_VIEWER_VIEWER_WINDOW_H

#include "Scene_renderer.h"
#include "Texture_image.h"
#include "pipeline/policy_registry.h"

#include <cstddef>
#include <string>
#include <vector>

namespace apps {

struct Viewer_start {
  std::string title;  // shown in the window's title and the panel
  const Policy_entry* policy = nullptr;
  cgal_policies::Simplification_options options;  // the policy's, the angle, the fit
  double ratio = 0.1;  // initial target, as a fraction of the input's faces
  View_options view;
  bool heat_map = false;
  // Drawn on the meshes that have texture coordinates; must outlive the window.
  const Texture_image* texture = nullptr;
  std::size_t level = 0;  // the level of detail shown first
};

// Shows `levels`, a file's levels of detail, finest first (one for most files; io/mesh_io.h,
// read_lod_chain). Returns once the window is closed; throws std::runtime_error when no window can
// be opened.
void run_viewer_window(const std::vector<Mesh>& levels, const Viewer_start& start);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_VIEWER_WINDOW_H
