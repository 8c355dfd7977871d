// The header of a PLY file: its format, its elements and their properties, as the readers of
// the whole file (soup_readers.h) and of a file streamed in passes (Streamed_mesh_file.h) take it.
#ifndef CGAL_POLICIES_IO_PLY_HEADER_H
#define CGAL_POLICIES_IO_PLY_HEADER_H

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace cgal_policies {
namespace io {

// A scalar type of PLY: its two names in headers, its size in a binary body, and its decoder
// (from the file's bytes in the machine's order); doubles hold every value of each exactly.
struct Ply_type {
  const char* name;
  const char* sized_name;
  std::size_t size;
  double (*decode)(const unsigned char*);
  double full_intensity;  // the value of a colour channel at its brightest
};

struct Ply_property {
  std::string name;
  const Ply_type* type = nullptr;
  const Ply_type* count_type = nullptr;  // set for a list, whose items are of `type`
};

struct Ply_element {
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

enum class Ply_format { ascii, little_endian, big_endian };

struct Ply_header {
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements;
  std::size_t body = 0;  // where the data starts
};

// The properties of a vertex element's row that hold its point (x, y, z), normal (nx, ny, nz),
// texture coordinates (s, t; u, v; texture_u, texture_v or texture_s, texture_t) and colour (red,
// green, blue and maybe alpha, or the same with "diffuse_"): their indices among its properties,
// -1 for none. A normal or colour that lacks a channel (alpha aside) has normal[0] or color[0]
// -1, texture coordinates that lack one uv[0] -1.
struct Ply_vertex_row;
struct Ply_vertex_slots {
  int xyz[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1}, uv[2] = {-1, -1},
      color[4] = {-1, -1, -1, -1};

  // Puts the value of property p, of type `type`, in its place in `row`: a colour channel divided
  // by its type's full intensity.
  void place(int p, double value, const Ply_type& type, Ply_vertex_row& row) const;
  // What of the row's normal, texture coordinates and colour (those it has) is not finite, as
  // "its normal is not finite"; empty when all are.
  std::string non_finite(const Ply_vertex_row& row) const;
};
Ply_vertex_slots ply_vertex_slots(const Ply_element& vertex);

// The values of one row of a vertex element.
struct Ply_vertex_row {
  double xyz[3] = {0, 0, 0}, normal[3] = {0, 0, 0}, uv[2] = {0, 0};
  std::array<double, 4> color{0, 0, 0, 1};  // opaque unless the file says otherwise
};

// The header at the start of `bytes`, a file of `file_size` bytes (an element count above that is
// a forged one). Throws Io_error (unreadable input, "<source>: <cause>").
Ply_header parse_ply_header(const std::string& source, std::string_view bytes,
                            std::size_t file_size);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_PLY_HEADER_H
