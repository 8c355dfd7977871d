// The number of faces of a face graph, exactly: a CGAL::Surface_mesh and a Polyhedron_3 keep it;
// other types (OpenMesh's, whose count includes the faces deleted until the garbage is collected)
// are walked.
#ifndef CGAL_POLICIES_INTERNAL_FACE_COUNT_H
#define CGAL_POLICIES_INTERNAL_FACE_COUNT_H

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <iterator>
#include <type_traits>

namespace cgal_policies {
namespace internal {

template <class Mesh, class = void>
struct Keeps_facet_count : std::false_type {};
template <class Mesh>
struct Keeps_facet_count<Mesh, std::void_t<decltype(std::declval<const Mesh&>().size_of_facets())>>
    : std::true_type {};

template <class Mesh>
std::size_t face_count(const Mesh& mesh) {
  if constexpr (Keeps_facet_count<Mesh>::value) {
    return mesh.size_of_facets();
  } else {
    const auto range = faces(mesh);
    return std::size_t(std::distance(range.begin(), range.end()));
  }
}

template <class Point>
std::size_t face_count(const CGAL::Surface_mesh<Point>& mesh) {
  return mesh.number_of_faces();
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FACE_COUNT_H
