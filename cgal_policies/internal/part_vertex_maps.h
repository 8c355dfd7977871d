// The vertex property maps of a part of a partitioned run (Mesh_parts.h), which the policies, the
// fast engine and the fitter read.
#ifndef CGAL_POLICIES_INTERNAL_PART_VERTEX_MAPS_H
#define CGAL_POLICIES_INTERNAL_PART_VERTEX_MAPS_H

#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/Surface_mesh.h>

#include <optional>
#include <string>

namespace cgal_policies {
namespace internal {

// bool: the vertex is on a cut, so no collapse and no fitting move may touch it.
inline const std::string kLockedVertexMap = "v:cgal_policies_locked";
// The vertex of the whole mesh that a part's vertex stands for; property maps follow
// collect_garbage(), so the parts may be simplified in place.
inline const std::string kOriginVertexMap = "v:cgal_policies_origin";

// The vertex map of that name and type, when the mesh has it.
template <class T, class Point>
std::optional<typename CGAL::Surface_mesh<Point>::template Property_map<CGAL::SM_Vertex_index, T>>
find_vertex_map(const CGAL::Surface_mesh<Point>& mesh, const std::string& name) {
  return find_property_map<CGAL::SM_Vertex_index, T>(mesh, name);
}

// Adds both maps to `part`: each vertex v stands for origin_of(v), locked when locked(v).
template <class Point, class OriginOf, class Locked>
void add_part_vertex_maps(CGAL::Surface_mesh<Point>& part, const OriginOf& origin_of,
                          const Locked& locked) {
  using Vertex = CGAL::SM_Vertex_index;
  auto lock = part.template add_property_map<Vertex, bool>(kLockedVertexMap, false).first;
  auto origin = part.template add_property_map<Vertex, Vertex>(kOriginVertexMap).first;
  for (const Vertex v : part.vertices()) {
    origin[v] = origin_of(v);
    lock[v] = locked(v);
  }
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PART_VERTEX_MAPS_H
