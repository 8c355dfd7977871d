// The triangles of one polygon, whatever its shape: files hold quads that are twisted and polygons
// that cross themselves (Blender, MeshLab and gltfpack read them), and every one of them is a
// surface the user wants kept.
#ifndef CGAL_POLICIES_IO_POLYGON_TRIANGULATION_H
#define CGAL_POLICIES_IO_POLYGON_TRIANGULATION_H

#include "Mesh_types.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cgal_policies {
namespace io {

// The triangles of the closed polygon through `corners`, each as three corner positions that turn
// the polygon's way, |corners| - 2 of them:
// - a quad is split along the diagonal whose two triangles face the same way (the one with the
//   larger smallest angle when both or neither do; the diagonal from corner 0 on a tie);
// - a larger polygon that is simple seen along its normal goes to CGAL's triangulate_face;
// - one that crosses itself or has no area, which triangulate_face could loop on
//   (polygon_crossing.h), gets the least-area triangulation of its 3D boundary
//   (triangulate_hole_polyline) when it has at most 500 corners (its time is cubic), and a fan
//   when it has more or that finds none.
std::vector<std::array<std::size_t, 3>> polygon_triangles(const std::vector<Point>& corners);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_POLYGON_TRIANGULATION_H
