// The choice a Hausdorff-bounded filter certified for an edge about to collapse, kept until the
// collapse is reported (docs/hausdorff.md, "The choose / collapse / commit protocol").
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_PENDING_CHOICE_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_PENDING_CHOICE_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_attachment.h>
#include <cgal_policies/internal/Hausdorff_patch.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <boost/property_map/property_map.hpp>

#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Hausdorff_pending_choice {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

 public:
  bool active() const { return m_active; }
  void drop() { m_active = false; }

  // Moving v0 and v1 (the same vertex for one move) to `point`, certified with `covers`.
  void hold(const Hausdorff_patch<face_descriptor>& patch, vertex_descriptor v0,
            vertex_descriptor v1, const Eigen::Vector3d& point, const Reference_sample& distance,
            std::vector<Piece_cover> covers) {
    m_active = true;
    m_point = point;
    m_distance = distance;
    m_v0 = v0;
    m_v1 = v1;
    m_faces = patch.faces;
    m_removed = patch.removed;
    m_covers = std::move(covers);
  }

  template <typename VertexPointMap>
  void move_vertex(const VertexPointMap& vpm, vertex_descriptor kept) const {
    put(vpm, kept, to_point<typename boost::property_traits<VertexPointMap>::value_type>(m_point));
  }

  // Records the change in `attachment`, once; the pieces only with the global reference.
  void commit(Hausdorff_attachment<TriangleMesh>& attachment, Hausdorff_reference reference) {
    if (!m_active) return;
    m_active = false;
    attachment.set_sample(m_v0, m_distance);
    attachment.set_sample(m_v1, m_distance);
    if (reference == Hausdorff_reference::local) return;  // no pieces to follow
    attachment.reattach(m_faces, m_removed, m_covers);
  }

 private:
  bool m_active = false;
  Eigen::Vector3d m_point;
  Reference_sample m_distance;
  vertex_descriptor m_v0, m_v1;
  std::vector<face_descriptor> m_faces, m_removed;
  std::vector<Piece_cover> m_covers;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_PENDING_CHOICE_H
