// How simplify --snapshot draws its picture without knowing the viewer: an interface here, one
// implementation in the viewer's offscreen renderer (apps/viewer/offscreen_snapshot_renderer.cpp)
// and one for builds without OpenGL (no_snapshot_renderer.cpp); a tool links one of the two.
#ifndef CGAL_POLICIES_APPS_CLI_SNAPSHOT_RENDERER_H
#define CGAL_POLICIES_APPS_CLI_SNAPSHOT_RENDERER_H

#include "app_types.h"
#include "io/mesh_io.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace apps {

class Snapshot_renderer {
 public:
  virtual ~Snapshot_renderer() = default;
  // Before any work: reads what the picture needs of the input, the texture its materials name;
  // Io_error (unreadable input) when that file is missing or is not an image. Returns what the
  // picture will be drawn without, a line each (a glTF image that cannot be decoded).
  virtual std::vector<std::string> prepare(const Mesh& input,
                                           const Material_references& materials) = 0;
  // Draws `input` beside `output`, captioned with `name` and its two-sided error, into `png`, all
  // or nothing: Io_error when it cannot be written, std::runtime_error without an OpenGL context.
  virtual void write(const Mesh& input, const Mesh& output, const std::string& name,
                     const std::string& png) = 0;
};

// This build's renderer, drawing `width` x `height` pixels; nullptr when it was built without.
std::unique_ptr<Snapshot_renderer> make_snapshot_renderer(int width, int height);

// Whether this build has a renderer (make_snapshot_renderer gives one), without making it.
bool snapshots_in_this_build();

// --size's "WxH", 16 to 16384 pixels each; App_error(exit_usage) otherwise.
std::pair<int, int> parse_picture_size(const std::string& text);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_SNAPSHOT_RENDERER_H
