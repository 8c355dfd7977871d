// A mesh file read in passes, never whole, for Simplification_pipeline::run_streamed
// (`simplify --out-of-core`, docs/scale.md): binary PLY of either byte order, and OBJ. Points and
// triangles only: a polygon of n corners is n - 2 triangles fanned from its first corner, and
// texture coordinates, normals, colours and materials are skipped.
#ifndef CGAL_POLICIES_IO_STREAMED_MESH_FILE_H
#define CGAL_POLICIES_IO_STREAMED_MESH_FILE_H

#include "ply_header.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace cgal_policies {
namespace io {

class Streamed_mesh_file {
 public:
  // Reads a PLY's header. Throws Io_error (unreadable input, "<path>: <cause>") when the file
  // cannot be opened, is neither a PLY nor an OBJ, is an ASCII PLY, or has no vertex x, y, z or no
  // face vertex_indices.
  explicit Streamed_mesh_file(std::string path);

  // The faces a PLY's header declares; 0 for an OBJ, which declares none.
  std::size_t declared_faces() const;

  // Calls f(x, y, z) for each vertex, in order. Throws Io_error on a coordinate that is not finite
  // and on a file that ends early.
  void for_each_point(const std::function<void(double, double, double)>& f) const;

  // Calls f(a, b, c) for each triangle, after for_each_point. Throws Io_error on a corner that
  // names no vertex and on a file that ends early.
  void for_each_triangle(
      const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& f) const;

 private:
  void for_each_ply_point(const std::function<void(double, double, double)>& f) const;
  void for_each_ply_triangle(
      const std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>& f) const;
  void for_each_obj_line(const std::function<void(std::size_t, std::string_view)>& f) const;

  std::string m_path;
  bool m_obj = false;
  Ply_header m_header;
  mutable std::size_t m_points = 0;  // counted by for_each_point
};

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_STREAMED_MESH_FILE_H
