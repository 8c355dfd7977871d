// What the GPU draws of one mesh: interleaved vertices (position, smooth normal, colour, texture
// coordinate) in the frame where the original is centred at the origin with a bounding-box
// diagonal of 1, and the triangles' indices. Optional per-vertex values colour it as a heat map; a
// mesh with texture coordinates or colours gets a vertex per corner, so that seams keep both sides'
// values.
#ifndef CGAL_POLICIES_APPS_VIEWER_RENDER_MESH_H
#define CGAL_POLICIES_APPS_VIEWER_RENDER_MESH_H

#include "Collapse_replay.h"

#include <array>
#include <cstdint>
#include <vector>

namespace apps {

// Maps a mesh into the unit frame of the original, so that both panes line up.
struct Mesh_frame {
  Point center = CGAL::ORIGIN;
  double scale = 1;  // 1 / bounding-box diagonal

  static Mesh_frame of(const Indexed_mesh& original);
};

struct Render_mesh {
  static constexpr int kFloatsPerVertex = 11;
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
};

// The colour of the surface without a heat map.
constexpr std::array<float, 3> kSurfaceColor = {0.78f, 0.80f, 0.84f};

// Blue (0) through cyan, green and yellow to red (1); `t` is clamped.
std::array<float, 3> heat_color(double t);

// `values` (by vertex index, may be empty) are coloured from 0 to `max_value`.
Render_mesh make_render_mesh(const Indexed_mesh& mesh, const Mesh_frame& frame,
                             const std::vector<double>& values = {}, double max_value = 0);

// The faces of `mesh` with its corners' texture coordinates (cgal_policies::Corner_attributes;
// v turned to run downwards, as the image's rows) and colours (the surface colour where there is
// none); needs a texture coordinate or a colour map.
Render_mesh make_corner_render_mesh(const Mesh& mesh, const Mesh_frame& frame);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_RENDER_MESH_H
