// Draws the viewer's picture with OpenGL 3.3 core: the original mesh in the left pane and the
// simplified one in the right pane under one camera, flat or smooth shaded, textured when given an
// image, with an optional wireframe, a caption per pane and, with the heat map, a colour legend.
// The window and the offscreen snapshots draw through the same code, so they show the same picture.
#ifndef CGAL_POLICIES_APPS_VIEWER_SCENE_RENDERER_H
#define CGAL_POLICIES_APPS_VIEWER_SCENE_RENDERER_H

#include "Gl_functions.h"
#include "Orbit_camera.h"
#include "Render_mesh.h"
#include "Texture_image.h"

#include <array>
#include <cstddef>
#include <string>

namespace apps {

struct View_options {
  bool flat_shading = false;
  bool wireframe = false;
};

struct Scene_captions {
  std::string left, right;  // one or more lines each
  double legend_max = -1;   // the heat map's top value; no legend when negative
  std::string legend_unit;  // appended to the legend's numbers
};

// "title\nF faces, V vertices", the first lines of a pane's caption.
std::string mesh_caption(const std::string& title, std::size_t faces, std::size_t vertices);

// The background colour, exact in every pixel the meshes and captions leave free.
constexpr std::array<unsigned char, 3> kBackground = {255, 255, 255};

class Scene_renderer {
 public:
  enum Pane { left = 0, right = 1 };

  // Needs a current OpenGL 3.3 core context, which must outlive the renderer.
  explicit Scene_renderer(const Gl_functions& gl);
  ~Scene_renderer();
  Scene_renderer(const Scene_renderer&) = delete;
  Scene_renderer& operator=(const Scene_renderer&) = delete;

  void set_mesh(Pane pane, const Render_mesh& mesh);
  // The pane's mesh takes its surface colour from `image` at its texture coordinates; none: from
  // its vertices' colours.
  void set_texture(Pane pane, const Texture_image* image);
  // Draws the two panes side by side in the columns [scene_left, width) of the framebuffer; the
  // columns left of them are cleared only (the window's control panel sits there).
  void draw(int width, int height, const Orbit_camera& camera, const View_options& options,
            const Scene_captions& captions, int scene_left = 0);

 private:
  struct Gpu_mesh {
    GLuint vertex_array = 0, vertex_buffer = 0, index_buffer = 0, texture = 0;
    GLsizei index_count = 0;
    bool textured = false;
  };

  void draw_mesh(const Gpu_mesh& mesh, const Eigen::Matrix4f& model_view,
                 const Eigen::Matrix4f& projection, const View_options& options);
  void draw_overlay(int width, int height, int scene_left, const Scene_captions& captions);

  const Gl_functions& m_gl;
  GLuint m_mesh_program = 0, m_overlay_program = 0;
  std::array<Gpu_mesh, 2> m_meshes;
  GLuint m_overlay_array = 0, m_overlay_buffer = 0;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_SCENE_RENDERER_H
