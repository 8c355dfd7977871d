// A polygon soup made into a triangle soup that a mesh can be built from, every corner keeping its
// texture coordinates, normal and colour, and every face its material (Corner_tables): the
// repairs that a file from another tool needs do not cost it its attributes.
#ifndef CGAL_POLICIES_IO_SOUP_REPAIR_H
#define CGAL_POLICIES_IO_SOUP_REPAIR_H

#include "Mesh_types.h"
#include "soup_readers.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// Splits every polygon of more than three corners into triangles (polygon_triangles), in place,
// each triangle taking its polygon's corner entries and material; drops the faces of fewer than
// three corners. Appends one phrase per change to `repairs`.
void triangulate_polygons(const std::vector<Point>& points,
                          std::vector<std::vector<std::size_t>>& polygons, Corner_tables* corners,
                          std::vector<std::string>& repairs);

// Repairs a triangle soup that is not an oriented manifold mesh, with CGAL's soup functions where
// they keep track of the corners: merges points that are exactly equal, drops degenerate
// triangles (a point twice) and duplicates (the same three points; the first is kept), removes
// unused points, then orients the triangles consistently, which splits the points where the soup
// is not manifold. Each triangle keeps its corners' entries and its material, turned with it.
// Appends one phrase per repair to `repairs`.
void repair_triangle_soup(std::vector<Point>& points,
                          std::vector<std::vector<std::size_t>>& polygons, Corner_tables* corners,
                          std::vector<std::string>& repairs);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_SOUP_REPAIR_H
