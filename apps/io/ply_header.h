// The header of a PLY file: its format, its elements and their properties, as the readers of
// the whole file (soup_readers.h) and of a file streamed in passes (Streamed_mesh_file.h) take it.
#ifndef CGAL_POLICIES_IO_PLY_HEADER_H
#define CGAL_POLICIES_IO_PLY_HEADER_H

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

// The header at the start of `bytes`, a file of `file_size` bytes (an element count above that is
// a forged one). Throws Io_error (unreadable input, "<source>: <cause>").
Ply_header parse_ply_header(const std::string& source, std::string_view bytes,
                            std::size_t file_size);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_PLY_HEADER_H
