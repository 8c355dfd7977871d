// The viewer's side-by-side picture rendered without a window (Offscreen_context.h) and written as
// a PNG: for `mesh_viewer --snapshot`, and for any app that wants pictures in its reports.
#ifndef CGAL_POLICIES_APPS_VIEWER_SNAPSHOT_H
#define CGAL_POLICIES_APPS_VIEWER_SNAPSHOT_H

#include "Scene_renderer.h"
#include "Texture_image.h"
#include "io/mesh_io.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace apps {

struct Snapshot_settings {
  int width = 1600, height = 800;  // pixels; each mesh gets one half
  View_options view;
  bool heat_map = false;  // colour `simplified` by its distance to `original`
  std::string left_caption, right_caption;
  // Drawn on each mesh that has texture coordinates (cgal_policies::Corner_attributes), but for a
  // heat map.
  std::optional<Texture_image> texture;
};

// Face samples per direction for the viewer's error figures: a tenth of the apps' default keeps
// them interactive (mesh_error gives the reference figures).
constexpr std::size_t kViewerErrorSamples = 20000;

// The texture a mesh read with its corner attributes is drawn with, when it has texture
// coordinates: from an OBJ file, the diffuse map its materials name (diffuse_texture_file), with
// Io_error (unreadable input) when that file is missing or is not an image, so that an app says so
// before any work; from a glTF file, the image of the base colour texture of the first material
// that has one (base_color_image, gltf_material_library.h), embedded or a file, and when stb cannot
// decode that image (WebP, KTX2), none and a line in `left_out` ("material '<name>': ...; drawn
// without it"): the file itself was read, and an untextured mesh is still worth showing.
std::optional<Texture_image> texture_to_draw(const Mesh& mesh, const Material_references& materials,
                                             std::vector<std::string>& left_out);

// Gives `pane` the mesh's corners with their texture (when `texture` is given and the mesh has
// texture coordinates), or else with their colours; false, and the pane left as it was, when the
// mesh has neither.
bool show_corner_values(Scene_renderer& renderer, Scene_renderer::Pane pane, const Mesh& mesh,
                        const Mesh_frame& frame, const Texture_image* texture);

// The left pane's title for level `level` of a file of `levels` levels of detail (0 the finest):
// "original" when it has one, "level k of 0-n" otherwise, n its coarsest.
std::string level_title(std::size_t level, std::size_t levels);

// Captions both panes: under `original_title` and `policy_name` the face and vertex counts, and
// under the latter the two-sided error of `simplified` (kViewerErrorSamples samples).
void caption_snapshot(const Mesh& original, const Mesh& simplified, const std::string& policy_name,
                      Snapshot_settings& settings,
                      const std::string& original_title = level_title(0, 1));

// Throws Io_error (unwritable output) when the PNG cannot be written (no partial file is left), and
// std::runtime_error when no offscreen OpenGL 3.3 context is available.
void write_snapshot(const Mesh& original, const Mesh& simplified, const Snapshot_settings& settings,
                    const std::string& png_path);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_SNAPSHOT_H
