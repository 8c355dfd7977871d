// Whether a mesh type is a CGAL::Surface_mesh: the parts that keep their state in its property
// maps (corner attributes, the pipeline, the partitioned runs) take no other type.
#ifndef CGAL_POLICIES_INTERNAL_IS_SURFACE_MESH_H
#define CGAL_POLICIES_INTERNAL_IS_SURFACE_MESH_H

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <type_traits>

namespace cgal_policies {
namespace internal {

template <class Mesh>
struct Is_surface_mesh : std::false_type {};
template <class Point>
struct Is_surface_mesh<CGAL::Surface_mesh<Point>> : std::true_type {};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_IS_SURFACE_MESH_H
