// The OBJ, OFF and PLY readers of the apps: strict parsers of the whole file in memory, without
// iostreams, that give a polygon soup or one error line. CGAL 5.5's own OFF and PLY readers have
// undefined behaviour on some malformed files (fuzz/regressions/read_off, read_ply), and Debian
// packages no PLY or OFF library short of assimp's whole-scene importer. Debian's tinyobjloader
// reads a coordinate it cannot parse ("inf") as 0 and keeps faces whose indices are out of
// range, with a warning; CGAL's OBJ reader parses through iostreams, which made most of the
// reading time of a large file.
#ifndef CGAL_POLICIES_IO_SOUP_READERS_H
#define CGAL_POLICIES_IO_SOUP_READERS_H

#include "Mesh_types.h"

#include <cgal_policies/Corner_attributes.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cgal_policies {
namespace io {

// What an OBJ (or PLY) file's corners and faces carry besides their points: its tables of texture
// coordinates, normals and colours (red, green, blue, alpha in [0, 1]), and of a glTF file's
// second texture coordinates and skin influences too, and for each polygon the table entry of each
// corner (kNoEntry
// where the corner names none; the lists are empty when no corner names one); its material
// libraries as the file names them, the material names its faces use, and each polygon's material
// (an index into the names, or kNoMaterial; empty when no face has one).
struct Corner_tables {
  static constexpr std::size_t kNoEntry = std::size_t(-1);
  static constexpr std::uint32_t kNoMaterial = std::uint32_t(-1);
  std::vector<std::array<double, 2>> uvs;
  std::vector<Kernel::Vector_3> normals;
  std::vector<std::array<double, 4>> colors;
  std::vector<std::array<double, 2>> second_uvs;
  std::vector<Corner_attributes<Point>::Skin_influences> skins;
  std::vector<std::vector<std::size_t>> polygon_uvs, polygon_normals, polygon_colors,
      polygon_second_uvs, polygon_skins;
  std::vector<std::string> material_libraries, material_names;
  std::vector<std::uint32_t> polygon_materials;
};

struct Polygon_soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  Corner_tables corners;  // OBJ and PLY
};

// OBJ: points from "v" lines (x y z; then a w, skipped, or a colour r g b [a], kept as a per-point
// entry of the corner tables, NaN for points without one), polygons from "f"
// lines, whose corners may name a texture coordinate ("vt u v") and a normal ("vn x y z") as
// v/vt, v//vn or v/vt/vn, each counted from 1 or back from the last one read when negative;
// "mtllib" and "usemtl" lines. Other lines are skipped. Throws
// Io_error (unreadable input, "<source>: line N: <cause>"), or "<source>: face F: <cause>" for an
// entry that is out of range.
Polygon_soup parse_obj(const std::string& source, std::string_view bytes);

// An OBJ index: counted from 1, or back from the last of the `so_far` entries read when negative.
// The entry counted from 0; nothing when it is not a whole number, is 0 or counts back too far.
std::optional<std::size_t> obj_index(std::string_view token, std::size_t so_far);

// OFF with an optional ST, C or N prefix (texture coordinates, colours and normals are skipped)
// and # comments. Throws Io_error (unreadable input, "<source>: <cause>").
Polygon_soup parse_off(const std::string& source, std::string_view bytes);

// PLY, ASCII or binary of either byte order: x, y, z of the "vertex" element, of any scalar type,
// and its normal (nx, ny, nz), texture coordinates (s, t; u, v; texture_u, texture_v or
// texture_s, texture_t) and colour (red, green, blue and maybe alpha, or the same with "diffuse_";
// an integer channel is scaled by its type's largest value, a float one kept) when it has them, as
// per-vertex entries of the corner tables; faces from
// the "face" element's vertex_indices (or vertex_index) list, or from the "tristrips" element's
// list, where -1 restarts the strip. Other elements and properties are skipped. Throws
// Io_error (unreadable input, "<source>: <cause>").
Polygon_soup parse_ply(const std::string& source, std::string_view bytes);

// A PLY file's points and triangles, these as one list of three point indices a triangle: the
// reader's fast path for large scans, which as polygons cost an allocation a face.
struct Ply_triangles {
  std::vector<Point> points;
  std::vector<std::size_t> corners;
};

// What parse_ply reads, as Ply_triangles, without the vertices' normals, texture coordinates and
// colours; nothing when a face is not a triangle, or when `values_wanted` and the vertices carry
// such values. Throws as parse_ply does.
std::optional<Ply_triangles> parse_ply_triangles(const std::string& source, std::string_view bytes,
                                                 bool values_wanted);

// Formats that store attributes per vertex (PLY, glTF) split a vertex on a seam into one vertex
// per side, at the same point. This joins the points that are exactly equal into one, numbered in
// the order of their first appearance, and renumbers the polygons; the corner tables keep naming
// the entries of the split vertices, so every corner keeps its values and the seam becomes corners
// that disagree. Call it after the corner tables are complete.
void join_equal_points(Polygon_soup& soup);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_SOUP_READERS_H
