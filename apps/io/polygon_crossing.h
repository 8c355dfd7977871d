// A guard in front of CGAL's polygon triangulation: triangulate_faces inserts a polygon's edges
// into a constrained triangulation that constructs every crossing between them, and on a polygon
// that crosses itself a crossing can spawn further crossings without end (a fuzzed 7-gon ran for
// 20 minutes; fuzz/regressions/repair). A polygon that crosses itself is bad input anyway.
#ifndef CGAL_POLICIES_IO_POLYGON_CROSSING_H
#define CGAL_POLICIES_IO_POLYGON_CROSSING_H

#include "Mesh_types.h"

#include <vector>

namespace cgal_policies {
namespace io {

// Whether the closed polygon through `corners`, seen along `normal` (the projection CGAL's
// triangulation uses), fails to be simple: two edges that are not neighbours cross or touch, two
// neighbouring edges fold back over each other, or two corners coincide. The predicates are
// exact; consecutive corners on one straight line are allowed.
bool polygon_crosses_itself(const std::vector<Point>& corners, const Kernel::Vector_3& normal);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_POLYGON_CROSSING_H
