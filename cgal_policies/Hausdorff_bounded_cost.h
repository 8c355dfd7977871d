// Hausdorff_bounded_cost: the priority of an edge for Hausdorff_bounded_placement (policies.md §3),
// and the keeper of its state while CGAL collapses edges.
//
// - Collapse_order::by_cost: the quadric error of the edge (Classic_quadric_policies), cheap
//   enough to refresh for every edge a collapse touches; the two-sided distance itself is measured
//   by Hausdorff_bounded_filter when the edge is popped.
// - Collapse_order::storage: the edge's place in storage order, once (the paper's single pass).
// - After a collapse it moves the kept vertex to the point the filter chose and attaches the input
//   pieces of the old patch to the new faces.
//
// Models CGAL's `GetCost` concept with `Update_tag`. Built by Hausdorff_bounded_placement, which
// shares its state with it; use it only through get_cost().
//
// Usage:
//   cgal_policies::Hausdorff_bounded_placement<Mesh, Kernel> hausdorff(mesh);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(hausdorff.get_cost()) ...);
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_tracker.h>
#include <cgal_policies/internal/Optional.h>

#include <CGAL/tags.h>

#include <memory>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Hausdorff_bounded_cost {
 public:
  using Update_tag = CGAL::Tag_true;
  using Tracker = internal::Hausdorff_tracker<TriangleMesh>;
  using Quadrics = Classic_quadric_policies<TriangleMesh, GeomTraits>;

  Hausdorff_bounded_cost(std::shared_ptr<Tracker> tracker, const Quadrics& quadrics,
                         Collapse_order order)
      : m_tracker(std::move(tracker)), m_quadrics(quadrics), m_order(order) {}

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm,
                  const GeomTraits& traits) const {
    m_quadrics.initialize(tm, vpm, traits);
    m_tracker->attach_to_itself(tm, vpm);
  }

  template <typename Profile, typename VertexDescriptor>
  void update_after_collapse(const Profile& profile, VertexDescriptor kept) const {
    m_tracker->commit(profile.vertex_point_map(), kept, true);
    m_quadrics.update_after_collapse(profile, kept);
  }

  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    if (m_order == Collapse_order::by_cost) return m_quadrics(profile, placement);
    const internal::Optional<double> order = m_tracker->storage_order(profile);
    if (!order) return {};
    return typename Profile::FT(*order);
  }

 private:
  std::shared_ptr<Tracker> m_tracker;
  Quadrics m_quadrics;
  Collapse_order m_order;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H
