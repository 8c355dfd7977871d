// The edge-collapse visitor of Simplification_pipeline: it reports every collapse to the options'
// on_collapse once the policies have updated after it (a cost's update_after_collapse may still
// move the kept vertex after OnCollapsed: the report waits for the next selected edge, the next
// collapse or the end of the run), and the progress every 1024 collapses. The corner attributes
// ride on Attribute_carrying_visitor, which wraps it.
#ifndef CGAL_POLICIES_INTERNAL_PIPELINE_VISITOR_H
#define CGAL_POLICIES_INTERNAL_PIPELINE_VISITOR_H

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>

#include <algorithm>
#include <cstddef>
#include <optional>

namespace cgal_policies {
namespace internal {

// The collapse seen but not reported yet. Outlives the run, since edge_collapse copies the visitor.
struct Pending_collapse {
  bool active = false;
  CGAL::SM_Vertex_index removed, kept;

  void report(const Simplification_options& options) {
    if (!active) return;
    active = false;
    options.on_collapse(removed, kept);
  }
};

// How far a simplification from `start` to `target` faces is at `faces`, in [0, 1].
inline double simplification_done(std::size_t start, std::size_t target, std::size_t faces) {
  if (start <= target) return 1;
  const std::size_t removed = start - (std::min)(faces, start);
  return (std::min)(1.0, double(removed) / double(start - target));
}

template <class Point>
class Pipeline_visitor : public CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<
                             CGAL::Surface_mesh<Point>> {
 public:
  using Mesh = CGAL::Surface_mesh<Point>;

  Pipeline_visitor(const Mesh& mesh, std::size_t target, const Simplification_options& options,
                   Pending_collapse& pending)
      : m_mesh(&mesh),
        m_start(mesh.number_of_faces()),
        m_target(target),
        m_options(&options),
        m_pending(&pending),
        m_lock(find_vertex_map<bool>(mesh, kLockedVertexMap)),
        m_origin(find_vertex_map<CGAL::SM_Vertex_index>(mesh, kOriginVertexMap)) {}

  template <class Profile, class OptionalCost>
  void OnSelected(const Profile&, const OptionalCost&, std::size_t, std::size_t) {
    m_pending->report(*m_options);
  }
  template <class Profile, class Vertex>
  void OnCollapsed(const Profile& profile, Vertex kept) {
    const Vertex removed = kept == profile.v0() ? profile.v1() : profile.v0();
    // A part's locked vertex goes only in a collapse of zero length, which CGAL makes without the
    // filter (Locked_vertex_filter.h): the vertex kept, at the same point, stands for it.
    if (m_lock && (*m_lock)[removed]) {
      (*m_lock)[kept] = true;
      (*m_origin)[kept] = (*m_origin)[removed];
    }
    m_pending->report(*m_options);  // collapses of zero-length edges come without a selection
    if (m_options->on_collapse) *m_pending = {true, removed, kept};
    if (m_options->progress && (++m_collapses & 1023) == 0) {
      const std::size_t faces = m_mesh->number_of_faces();
      m_options->progress(Simplification_pass::simplification,
                          simplification_done(m_start, m_target, faces), faces);
    }
  }

 private:
  const Mesh* m_mesh;
  std::size_t m_start, m_target;
  const Simplification_options* m_options;
  Pending_collapse* m_pending;
  // A part of a partitioned run's (part_vertex_maps.h); none otherwise.
  std::optional<typename Mesh::template Property_map<CGAL::SM_Vertex_index, bool>> m_lock;
  std::optional<typename Mesh::template Property_map<CGAL::SM_Vertex_index, CGAL::SM_Vertex_index>>
      m_origin;
  std::size_t m_collapses = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PIPELINE_VISITOR_H
