// An OpenGL 3.3 core context without a window or display (OSMesa, software rendering), made current
// on the calling thread, for snapshots in scripts, tests and CI.
#ifndef CGAL_POLICIES_APPS_VIEWER_OFFSCREEN_CONTEXT_H
#define CGAL_POLICIES_APPS_VIEWER_OFFSCREEN_CONTEXT_H

#include "Gl_functions.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace apps {

class Offscreen_context {
 public:
  // Throws std::runtime_error when OSMesa cannot provide the context.
  Offscreen_context(int width, int height);
  ~Offscreen_context();
  Offscreen_context(const Offscreen_context&) = delete;
  Offscreen_context& operator=(const Offscreen_context&) = delete;

  Gl_loader loader() const;
  // The picture, RGB, top row first; call once glFinish returned.
  std::vector<std::uint8_t> rgb_pixels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_OFFSCREEN_CONTEXT_H
