// The mesh type every app works on.
#ifndef CGAL_POLICIES_APPS_MESH_TYPES_H
#define CGAL_POLICIES_APPS_MESH_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace apps {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_MESH_TYPES_H
