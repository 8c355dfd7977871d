// The state the Hausdorff-bounded cost, filter and move guard share (docs/hausdorff.md), as
// Polyhedral_envelope is Polyhedral_envelope_filter's. choose() certifies a collapse,
// commit_collapse() applies it once CGAL collapsed the edge, try_move() does both for one vertex.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_BOUNDED_STATE_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_BOUNDED_STATE_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_attachment.h>
#include <cgal_policies/internal/Hausdorff_certifier.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Hausdorff_patch.h>
#include <cgal_policies/internal/Hausdorff_pending_choice.h>
#include <cgal_policies/internal/Storage_scan_order.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/assertions.h>

#include <functional>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Hausdorff_bounded_state {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

 public:
  // `input` is the reference and `tracked` the mesh that changes (it may be the same one).
  template <typename InputMesh, typename InputPointMap>
  Hausdorff_bounded_state(const InputMesh& input, const InputPointMap& input_vpm,
                          TriangleMesh& tracked, double tolerance_fraction,
                          const Hausdorff_bounded_options& options)
      : m_options(options),
        m_input(input, input_vpm, tolerance_fraction, global()),
        m_attachment(tracked),
        m_scan_order(tracked),
        m_certifier(m_input, options.reference, options.max_refinement),
        m_tracks_its_input(static_cast<const void*>(&input) == static_cast<const void*>(&tracked)) {
  }

  Hausdorff_bounded_state(const Hausdorff_bounded_state&) = delete;
  Hausdorff_bounded_state& operator=(const Hausdorff_bounded_state&) = delete;

  double tolerance() const { return m_input.tolerance(); }
  double diagonal() const { return m_input.diagonal(); }
  const Storage_scan_order<TriangleMesh>& scan_order() const { return m_scan_order; }

  // Ties `tm`, the tracked mesh as a run starts, to the input: every face its own piece when tm
  // is the input; else, in global mode, as an approximation of it (the stitched parts of a
  // partitioned run, already within the tolerance).
  template <typename VertexPointMap>
  void attach(const TriangleMesh& tm, const VertexPointMap& vpm) {
    m_pending.drop();
    if (m_tracks_its_input || !global())
      m_attachment.attach_to_itself(tm, vpm, global());
    else
      m_attachment.attach_to_approximation(tm, vpm, m_input, m_options.max_refinement);
    m_scan_order.record(tm);
  }

  template <typename VertexPointMap>
  void attach_to_approximation(const TriangleMesh& tm, const VertexPointMap& vpm) {
    m_pending.drop();
    m_attachment.attach_to_approximation(tm, vpm, m_input, m_options.max_refinement);
  }

  // Alone, a filter's collapses go unreported: commit a choice when the next one is asked for.
  void defer_commits() { m_deferred_commits = true; }

  // A rule every candidate point of a collapse must also pass (the seam rules of a corner
  // attribute carrier); none by default.
  using Candidate_rule = std::function<bool(halfedge_descriptor edge, const Eigen::Vector3d& p)>;
  void set_candidate_rule(Candidate_rule rule) { m_candidate_rule = std::move(rule); }
  bool allows(halfedge_descriptor edge, const Eigen::Vector3d& p) const {
    return !m_candidate_rule || m_candidate_rule(edge, p);
  }

  // The best-ranked of `candidates` certified within the tolerance, after `acceptable` (the flip
  // check); it stays pending until commit_collapse().
  template <typename Profile, typename Acceptable>
  Optional<Eigen::Vector3d> choose(const Profile& profile,
                                   const std::vector<Eigen::Vector3d>& candidates,
                                   const Acceptable& acceptable) {
    // A choice still pending was not collapsed, unless nothing calls commit_collapse().
    if (m_deferred_commits)
      m_pending.commit(m_attachment, m_options.reference);
    else
      m_pending.drop();
    const auto patch = make_patch(profile.surface_mesh(), profile.vertex_point_map(), profile.v0(),
                                  profile.v1(), m_attachment, m_options.reference);
    if (is_frozen(patch, m_attachment)) return {};
    const std::vector<Ranked_candidate> ranked = m_certifier.rank(
        patch, candidates, to_eigen(profile.p0()), m_attachment.sample(profile.v0()).triangle,
        to_eigen(profile.p1()), m_attachment.sample(profile.v1()).triangle, acceptable);
    for (const Ranked_candidate& r : ranked) {
      std::vector<Piece_cover> covers;
      if (!m_certifier.certify(patch, candidates[r.index], r.distance, covers)) continue;
      m_pending.hold(patch, profile.v0(), profile.v1(), candidates[r.index], r.distance,
                     std::move(covers));
      return candidates[r.index];
    }
    return {};
  }

  template <typename VertexPointMap>
  void commit_collapse(const VertexPointMap& vpm, vertex_descriptor kept) {
    if (!m_pending.active()) return;
    m_pending.move_vertex(vpm, kept);
    m_pending.commit(m_attachment, m_options.reference);
  }

  // True, and the pieces attached again, when moving v to p keeps the bound; the caller moves v.
  template <typename VertexPointMap>
  bool try_move(const TriangleMesh& tm, const VertexPointMap& vpm, vertex_descriptor v,
                const Eigen::Vector3d& p) {
    m_pending.commit(m_attachment, m_options.reference);
    const auto patch = make_patch(tm, vpm, v, v, m_attachment, m_options.reference);
    if (is_frozen(patch, m_attachment)) return false;
    const Reference_sample d = m_certifier.sample(patch, p, m_attachment.sample(v).triangle);
    std::vector<Piece_cover> covers;
    if (d.distance > tolerance() || !m_certifier.certify(patch, p, d, covers)) return false;
    m_pending.hold(patch, v, v, p, d, std::move(covers));
    m_pending.commit(m_attachment, m_options.reference);
    return true;
  }

  // True, and the pieces attached again, when `faces`, whose connectivity changed with no corner
  // moving (an edge flip already made), keep the bound; the caller undoes the change otherwise.
  template <typename VertexPointMap>
  bool try_reshape(
      const TriangleMesh& tm, const VertexPointMap& vpm,
      const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces) {
    CGAL_precondition(global());
    m_pending.commit(m_attachment, m_options.reference);
    const auto patch = make_reshaped_patch(tm, vpm, faces, m_attachment);
    if (is_frozen(patch, m_attachment)) return false;
    std::vector<Piece_cover> covers;
    if (!m_certifier.certify(patch, Eigen::Vector3d::Zero(), Reference_sample{}, covers))
      return false;
    m_attachment.reattach(patch.faces, {}, covers);
    return true;
  }

 private:
  bool global() const { return m_options.reference == Hausdorff_reference::global; }

  Hausdorff_bounded_options m_options;
  Hausdorff_input_surface m_input;
  Hausdorff_attachment<TriangleMesh> m_attachment;
  Storage_scan_order<TriangleMesh> m_scan_order;
  Hausdorff_certifier m_certifier;
  Hausdorff_pending_choice<TriangleMesh> m_pending;
  bool m_tracks_its_input;  // the input is the tracked mesh itself
  bool m_deferred_commits = false;
  Candidate_rule m_candidate_rule;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_BOUNDED_STATE_H
