// Classic_quadric_policies: the quadric error metric of [GH97] as [QEM-tutorial] describes it
// (docs/quadric_core.md): collapsing (v0, v1) to x costs x~^T (Q0 + Q1) x~, Q_v summing the planes
// of v's faces and border edges, x being the shared placement chain's point; the merged vertex
// keeps Q0 + Q1. Models CGAL's `GetCost` and `GetPlacement` in one object with `Update_tag`, as
// GarlandHeckbert_plane_policies (state in a dynamic vertex property); pair it with a flip filter
// such as Bounded_normal_angle_filter. Parameters: Quadric_options.
// Usage:
//   cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh);
//   SMS::edge_collapse(mesh, stop,
//                      CGAL::parameters::get_cost(policies.get_cost())
//                          .get_placement(policies.get_placement()));
#ifndef CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H
#define CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H

#include <cgal_policies/Quadric_options.h>
#include <cgal_policies/internal/Quadric_policy_base.h>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Classic_quadric_policies
    : public internal::Quadric_policy_base<
          TriangleMesh, GeomTraits, Classic_quadric_policies<TriangleMesh, GeomTraits>, false> {
  using Base =
      internal::Quadric_policy_base<TriangleMesh, GeomTraits, Classic_quadric_policies, false>;

 public:
  explicit Classic_quadric_policies(TriangleMesh& tm, const Quadric_options& options = {})
      : Base(tm, options) {}
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H
