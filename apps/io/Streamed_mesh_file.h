// A mesh file read in passes, never whole, for Simplification_pipeline::run_streamed
// (`simplify --out-of-core`, docs/scale.md): binary PLY of either byte order, and OBJ. A polygon of
// n corners is n - 2 triangles fanned from its first corner. When asked, its corners' values come
// with its triangles: an OBJ's texture coordinates, normals, colours (per point) and materials, a
// PLY's per-vertex texture coordinates, normals and colours, as the reader of whole files takes
// them (soup_readers.h); the tables they are taken from are held in memory.
#ifndef CGAL_POLICIES_IO_STREAMED_MESH_FILE_H
#define CGAL_POLICIES_IO_STREAMED_MESH_FILE_H

#include "mesh_io.h"
#include "ply_header.h"

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/Streamed_corners.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

class Streamed_mesh_file {
 public:
  using Kinds = Corner_attributes<Point>::Kinds;
  using Corners = internal::Streamed_corners<Point>;
  using Triangle_function =
      std::function<void(std::uint32_t, std::uint32_t, std::uint32_t, const Corners&)>;

  // Reads a PLY's header. Throws Io_error (unreadable input, "<path>: <cause>") when the file
  // cannot be opened, is neither a PLY nor an OBJ, is an ASCII PLY, or has no vertex x, y, z or no
  // face vertex_indices. With `drop`, no corner has values.
  explicit Streamed_mesh_file(std::string path,
                              Corner_attribute_reading attributes = Corner_attribute_reading::drop);

  // The faces a PLY's header declares; 0 for an OBJ, which declares none.
  std::size_t declared_faces() const;

  // Calls f(x, y, z) for each vertex, in order, and keeps the tables of the corners' values.
  // Throws Io_error on a coordinate or a value that is not finite and on a file that ends early.
  void for_each_point(const std::function<void(double, double, double)>& f) const;

  // After for_each_point: the kinds of values the corners carry, and an OBJ's materials (its
  // libraries resolved against its folder, those outside the asset folder left out with a line in
  // `left_out`, as read_triangle_mesh does with `asset_root`; the names its faces use).
  Kinds corner_kinds() const;
  // Whether the corners carry values (texture coordinates, normals or colours; a material is the
  // triangle's), after for_each_point.
  bool has_corner_values() const;
  Material_references materials(const std::string& asset_root,
                                std::vector<std::string>& left_out) const;

  // Calls f(a, b, c, corners) for each triangle, after for_each_point. Throws Io_error on a corner
  // that names no vertex, or a texture coordinate or normal not read before it, and on a file that
  // ends early.
  void for_each_triangle(const Triangle_function& f) const;

 private:
  void for_each_obj_point(const std::function<void(double, double, double)>& f) const;
  void for_each_ply_point(const std::function<void(double, double, double)>& f) const;
  void for_each_obj_triangle(const Triangle_function& f) const;
  void for_each_ply_triangle(const Triangle_function& f) const;
  void for_each_obj_line(const std::function<void(std::size_t, std::string_view)>& f) const;
  // The values of the corner at point v: the point's own (PLY, OBJ colours), and an OBJ corner's
  // entries of the uv and normal tables (kNoEntry for none).
  Corner_attributes<Point>::Values corner_values(std::uint32_t v, std::size_t uv,
                                                 std::size_t normal) const;

  std::string m_path;
  bool m_obj = false;
  bool m_keep = false;  // the corners' values
  Ply_header m_header;
  mutable std::size_t m_points = 0;  // counted by for_each_point
  // Filled by for_each_point when kept: the tables of texture coordinates and normals (an OBJ's
  // vt and vn, or a PLY's per vertex), colours per point, and the OBJ's materials.
  mutable Kinds m_kinds;
  mutable std::vector<std::array<double, 2>> m_uvs;
  mutable std::vector<std::array<double, 3>> m_normals;
  mutable std::vector<std::array<double, 4>> m_colors;
  mutable std::vector<std::string> m_material_libraries, m_material_names;
};

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_STREAMED_MESH_FILE_H
