// The filter a part of a partitioned run adds to its policy's: no collapse touches a vertex on a
// cut (kLockedVertexMap), so that the parts still meet exactly when they are stitched. A mesh
// without the map passes everything to the wrapped filter.
#ifndef CGAL_POLICIES_INTERNAL_LOCKED_VERTEX_FILTER_H
#define CGAL_POLICIES_INTERNAL_LOCKED_VERTEX_FILTER_H

#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Surface_mesh.h>

#include <optional>

namespace cgal_policies {
namespace internal {

template <class Point, class BaseFilter>
class Locked_vertex_filter {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Lock_map = typename Mesh::template Property_map<typename Mesh::Vertex_index, bool>;

 public:
  Locked_vertex_filter(const Mesh& mesh, const BaseFilter& base)
      : m_lock(find_vertex_map<bool>(mesh, kLockedVertexMap)), m_base(base) {}

  template <class Profile>
  Optional<Point> operator()(const Profile& profile, const Optional<Point>& placement) const {
    if (m_lock && ((*m_lock)[profile.v0()] || (*m_lock)[profile.v1()])) return {};
    return m_base(profile, placement);
  }

 private:
  std::optional<Lock_map> m_lock;
  BaseFilter m_base;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_LOCKED_VERTEX_FILTER_H
