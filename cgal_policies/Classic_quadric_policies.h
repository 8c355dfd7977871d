// Classic_quadric_policies: the quadric error metric of Garland & Heckbert (1997) as the QEM
// tutorial [QEM-tutorial] describes it (docs/quadric_core.md).
//
// - Cost of collapsing (v0, v1) to x: x~^T (Q0 + Q1) x~, where Q_v sums the planes of the faces
//   around v and, on a border, planes through each border edge perpendicular to its face.
// - Placement: the quadric's minimiser when A is well conditioned and the point stays within two
//   edge lengths of the edge; else the best point of the edge; else the best of v0, v1, midpoint.
// - The merged vertex keeps Q0 + Q1.
//
// Models CGAL's `GetCost` and `GetPlacement` concepts (one object, as CGAL's
// GarlandHeckbert_plane_policies). Its state lives in a dynamic vertex property, so the mesh gains
// no visible property; `Update_tag` makes `edge_collapse` call `initialize` and
// `update_after_collapse`. Pair it with a flip filter such as Bounded_normal_angle_filter.
//
// Parameters: Quadric_options (border weight, unit or area face weights).
//
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
