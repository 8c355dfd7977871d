// Reading and writing meshes for every app: OBJ, OFF, PLY and STL, polygon soups repaired,
// polygons triangulated, and atomic writes that never leave a partial file or touch the input.
#ifndef CGAL_POLICIES_APPS_MESH_IO_H
#define CGAL_POLICIES_APPS_MESH_IO_H

#include "Mesh_types.h"

#include <cstddef>
#include <string>
#include <vector>

namespace apps {

struct Read_report {
  std::vector<std::string> repairs;  // what was repaired, one phrase each; empty when nothing was
};

bool has_supported_mesh_extension(const std::string& path);

// Reads a triangle mesh; throws App_error(exit_bad_input, "<path>: <cause>") when it cannot.
Mesh read_triangle_mesh(const std::string& path, Read_report* report = nullptr);

// The reader's second half: checks the soup (faces, finite points, indices in range); builds the
// mesh directly when the soup is a clean triangle mesh, otherwise repairs it when it is not a
// polygon mesh as it stands, and triangulates. Errors name `source`, as above.
Mesh triangle_mesh_from_soup(const std::string& source, std::vector<Point>& points,
                             std::vector<std::vector<std::size_t>>& polygons,
                             Read_report* report = nullptr);

// Throws App_error(exit_usage) when `output` cannot be a mesh file or would overwrite `input`,
// App_error(exit_bad_output) when its folder does not exist.
void check_output_path(const std::string& input, const std::string& output, bool force);

// Writes by extension with full precision, all or nothing (write_atomically); throws
// App_error(exit_bad_output) and leaves no file behind when that fails.
void write_mesh_atomically(const Mesh& mesh, const std::string& path);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_MESH_IO_H
