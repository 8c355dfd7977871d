// Hausdorff_bounded_placement: a CGAL `GetPlacement`, where CGAL's queue puts the merged vertex for
// Hausdorff_bounded_policies ([Liu17] §2.2; docs/hausdorff.md): the quadric optimum restricted by
// the border rule (a border vertex stays, a border edge slides along itself, other border pairs
// and locked borders refuse). Only a proposal: the collapse ends where the filter chose.
// Parameters:
//   quadrics  the quadric state, shared with the cost that orders the queue
//   border    Border_rule::slide (default) or Border_rule::lock
// Usage (the quadric optimum kept off the border, without the bound):
//   cgal_policies::Classic_quadric_policies<Mesh, Kernel> quadrics(mesh);
//   cgal_policies::Hausdorff_bounded_placement<Mesh, Kernel> placement(quadrics);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(quadrics).get_placement(placement));
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/hausdorff_candidates.h>
#include <cgal_policies/internal/mesh_geometry.h>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Hausdorff_bounded_placement {
 public:
  using Quadrics = Classic_quadric_policies<TriangleMesh, GeomTraits>;

  explicit Hausdorff_bounded_placement(const Quadrics& quadrics,
                                       Border_rule border = Border_rule::slide)
      : m_quadrics(quadrics), m_border(border) {}

  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const internal::Optional<typename Profile::Point> optimum = m_quadrics(profile);
    if (!optimum) return {};
    const internal::Optional<Eigen::Vector3d> p = internal::restrict_to_border_case(
        profile, internal::border_case(profile, m_border), internal::to_eigen(*optimum));
    if (!p) return {};
    return internal::to_point<typename Profile::Point>(*p);
  }

 private:
  Quadrics m_quadrics;
  Border_rule m_border;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H
