#include "snapshot.h"

#include "Offscreen_context.h"
#include "Surface_distance.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/atomic_write.h"
#include "io/gltf_material_library.h"
#include "io/material_texture.h"

#include <cgal_policies/Corner_attributes.h>

#include <stb_image_write.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace apps {

namespace {

// texture_to_draw's glTF half.
std::optional<Texture_image> base_color_texture(const tinygltf::Model& looks,
                                                const std::vector<std::string>& names,
                                                std::vector<std::string>& left_out) {
  for (std::size_t m = 0; m < names.size() && m < looks.materials.size(); ++m) {
    if (looks.materials[m].pbrMetallicRoughness.baseColorTexture.index < 0) continue;
    const std::string material = "material '" + names[m] + "': its base colour texture ";
    const int index = base_color_image(looks, m);
    if (index < 0) {
      left_out.push_back(material + "has no PNG or JPEG image; drawn without it");
      return std::nullopt;
    }
    // An image file is named by its absolute path; an image the file held keeps its bytes.
    const tinygltf::Image& image = looks.images[std::size_t(index)];
    try {
      return image.uri.empty()
                 ? Texture_image::decode(image.image, "image " + std::to_string(index))
                 : Texture_image::load(image.uri);
    } catch (const Io_error& e) {
      left_out.push_back(material + "cannot be decoded (" + e.what() + "); drawn without it");
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Texture_image> texture_to_draw(const Mesh& mesh, const Material_references& materials,
                                             std::vector<std::string>& left_out) {
  if (!cgal_policies::Corner_attributes<Point>(mesh).uvs) return std::nullopt;
  if (materials.gltf) return base_color_texture(*materials.gltf, materials.names, left_out);
  const std::optional<std::string> file = diffuse_texture_file(materials);
  if (!file) return std::nullopt;
  return Texture_image::load(*file);
}

bool show_corner_values(Scene_renderer& renderer, Scene_renderer::Pane pane, const Mesh& mesh,
                        const Mesh_frame& frame, const Texture_image* texture) {
  const cgal_policies::Corner_attributes<Point> attributes(mesh);
  const bool textured = texture && attributes.uvs;
  if (!textured && !attributes.colors) return false;
  renderer.set_mesh(pane, make_corner_render_mesh(mesh, frame));
  if (textured) renderer.set_texture(pane, texture);
  return true;
}

std::string level_title(std::size_t level, std::size_t levels) {
  if (levels == 1) return "original";
  return "level " + std::to_string(level) + " of 0-" + std::to_string(levels - 1);
}

void caption_snapshot(const Mesh& original, const Mesh& simplified, const std::string& policy_name,
                      Snapshot_settings& settings, const std::string& original_title) {
  const Mesh_error error = measure_mesh_error(original, simplified, kViewerErrorSamples);
  char figures[128];
  std::snprintf(figures, sizeof figures, "\nHausdorff %.3f%%, mean %.3f%% of the diagonal",
                100 * error.hausdorff / error.bbox_diagonal,
                100 * error.mean_a_to_b / error.bbox_diagonal);
  settings.left_caption =
      mesh_caption(original_title, original.number_of_faces(), original.number_of_vertices());
  settings.right_caption =
      mesh_caption(policy_name, simplified.number_of_faces(), simplified.number_of_vertices()) +
      figures;
}

void write_snapshot(const Mesh& original, const Mesh& simplified, const Snapshot_settings& settings,
                    const std::string& png_path) {
  Mesh compact = simplified;
  compact.collect_garbage();
  const Indexed_mesh left = Indexed_mesh::from_mesh(original);
  const Indexed_mesh right = Indexed_mesh::from_mesh(compact);
  const Mesh_frame frame = Mesh_frame::of(left);

  Scene_captions captions;
  captions.left = settings.left_caption;
  captions.right = settings.right_caption;
  std::vector<double> errors;
  if (settings.heat_map) {
    std::vector<double> cache;
    errors = Surface_distance(original).vertex_distances(right, cache);
    for (double& e : errors) e *= 100 * frame.scale;  // percent of the diagonal
    captions.legend_max = errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end());
    captions.legend_unit = "% diag";
  }

  Offscreen_context context(settings.width, settings.height);
  const Gl_functions gl(context.loader());
  std::vector<std::uint8_t> pixels;
  {
    Scene_renderer renderer(gl);
    const Texture_image* texture = settings.texture ? &*settings.texture : nullptr;
    if (!show_corner_values(renderer, Scene_renderer::left, original, frame, texture))
      renderer.set_mesh(Scene_renderer::left, make_render_mesh(left, frame));
    if (settings.heat_map ||
        !show_corner_values(renderer, Scene_renderer::right, compact, frame, texture)) {
      renderer.set_mesh(Scene_renderer::right,
                        make_render_mesh(right, frame, errors, captions.legend_max));
    }
    renderer.draw(settings.width, settings.height, Orbit_camera(), settings.view, captions);
    gl.Finish();
    pixels = context.rgb_pixels();
  }

  write_atomically(png_path, [&](const std::string& temporary) {
    return stbi_write_png(temporary.c_str(), settings.width, settings.height, 3, pixels.data(),
                          settings.width * 3) != 0;
  });
}

}  // namespace apps
