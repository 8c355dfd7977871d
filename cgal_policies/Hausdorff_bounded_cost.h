// Hausdorff_bounded_cost: a CGAL `GetCost` with `Update_tag`, the edge priority of
// Hausdorff_bounded_policies ([Liu17] §2.3; docs/hausdorff.md). by_cost: the edge's quadric error,
// cheap enough to refresh for every edge a collapse touches (the filter measures distances when
// it is popped); storage: its place in storage order, once ([Liu17]'s single pass). Its
// update_after_collapse() applies the filter's choice (Hausdorff_bounded_policies.h says why).
// Parameters:
//   state     the shared state (not null), owned by Hausdorff_bounded_policies
//   quadrics  the quadric state, shared with the placement
//   order     Collapse_order::by_cost or Collapse_order::storage
// Usage: built by Hausdorff_bounded_policies, used through its get_cost():
//   cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> policies(mesh);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost()) /* ... */);
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>
#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Hausdorff_bounded_cost {
 public:
  using Update_tag = CGAL::Tag_true;
  using Shared_state = internal::Hausdorff_bounded_state<TriangleMesh>;
  using Quadrics = Classic_quadric_policies<TriangleMesh, GeomTraits>;

  Hausdorff_bounded_cost(Shared_state* state, const Quadrics& quadrics, Collapse_order order)
      : m_state(state), m_quadrics(quadrics), m_order(order) {
    CGAL_precondition(state != nullptr);
  }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm,
                  const GeomTraits& traits) const {
    m_quadrics.initialize(tm, vpm, traits);
    m_state->attach(tm, vpm);
  }

  template <typename Profile, typename VertexDescriptor>
  void update_after_collapse(const Profile& profile, VertexDescriptor kept) const {
    m_state->commit_collapse(profile.vertex_point_map(), kept);
    m_quadrics.update_after_collapse(profile, kept);
  }

  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    if (m_order == Collapse_order::by_cost) return m_quadrics(profile, placement);
    const internal::Optional<double> order = m_state->scan_order().position(profile);
    if (!order) return {};
    return typename Profile::FT(*order);
  }

 private:
  Shared_state* m_state;
  Quadrics m_quadrics;
  Collapse_order m_order;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_COST_H
