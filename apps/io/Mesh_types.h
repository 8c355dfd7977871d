// The mesh type the io layer reads and writes: CGAL's Surface_mesh on the Epick kernel, with the
// corner attributes of cgal_policies/Corner_attributes.h.
#ifndef CGAL_POLICIES_IO_MESH_TYPES_H
#define CGAL_POLICIES_IO_MESH_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace cgal_policies {
namespace io {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MESH_TYPES_H
