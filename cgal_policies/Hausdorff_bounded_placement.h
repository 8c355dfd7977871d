// Hausdorff_bounded_placement: edge collapses that keep the simplified surface within a tolerance
// of the original, after Liu et al. 2017 (seed 003, §2.2-2.3) as policies.md §3 specifies it.
//
// - Tolerance tau = alpha * beta * D, D the input's bounding-box diagonal (the paper's lambda *
// alpha
//   with lambda = psi(M0) * beta).
// - For a popped edge, the merged vertex is probed at K + 1 points at a constant step along the
//   edge and at the quadric optimum; the candidate with the smallest two-sided patch distance that
//   is certified within tau wins, otherwise the edge is refused (Hausdorff_bounded_filter).
// - Reference::global (default): candidates are measured against the ORIGINAL surface (an AABB
//   tree of the input one way, input pieces that follow the faces of the current mesh the other
//   way), so the output's two-sided Hausdorff distance to the input never exceeds tau.
//   Reference::local: the paper's literal rule, against the current patch; errors accumulate.
// - Order: by the quadric error through CGAL's queue (default), or the paper's single pass over
//   the edges in storage order. Border vertices slide along the border or are locked; flips are
//   refused.
//
// This class is the placement CGAL queues edges with (the quadric optimum, restricted by the
// border rule); it owns the shared state and hands out the cost and filter that go with it.
// Models CGAL's `GetPlacement` concept; get_cost() models `GetCost`, get_filter() `Filter`.
//
// Parameters (Hausdorff_bounded_options): beta 0.005 (fraction of D), alpha 1, steps K 10,
// reference global, order by_cost, border slide, max_normal_angle_deg 90, border_weight 1000.
//
// Usage:
//   cgal_policies::Hausdorff_bounded_options options;
//   options.beta = 0.01;  // 1% of the diagonal
//   cgal_policies::Hausdorff_bounded_placement<Mesh, Kernel> hausdorff(mesh, options);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(hausdorff.get_cost())
//                                      .get_placement(hausdorff.get_placement())
//                                      .filter(hausdorff.get_filter()));
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Hausdorff_bounded_cost.h>
#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_tracker.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/hausdorff_candidates.h>

#include <memory>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Hausdorff_bounded_placement {
  using Tracker = internal::Hausdorff_tracker<TriangleMesh>;
  using Quadrics = Classic_quadric_policies<TriangleMesh, GeomTraits>;

 public:
  using Get_placement = Hausdorff_bounded_placement;
  using Get_cost = Hausdorff_bounded_cost<TriangleMesh, GeomTraits>;
  using Filter = Hausdorff_bounded_filter<TriangleMesh, GeomTraits>;

  explicit Hausdorff_bounded_placement(TriangleMesh& tm,
                                       const Hausdorff_bounded_options& options = {})
      : m_options(options),
        m_tracker(std::make_shared<Tracker>(tm, tm, options.alpha * options.beta, options)),
        m_quadrics(tm, Quadric_options{options.border_weight, Face_weighting::unit}),
        m_cost(m_tracker, m_quadrics, options.order),
        m_filter(m_tracker, options) {}

  const Get_placement& get_placement() const { return *this; }
  const Get_cost& get_cost() const { return m_cost; }
  const Filter& get_filter() const { return m_filter; }

  // tau, in the mesh's units.
  double tolerance() const { return m_tracker->tolerance(); }

  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const internal::Optional<typename Profile::Point> optimum = m_quadrics(profile);
    if (!optimum) return {};
    const internal::Optional<Eigen::Vector3d> p = internal::restrict_to_border_case(
        profile, internal::border_case(profile, m_options.border), internal::to_eigen(*optimum));
    if (!p) return {};
    return internal::to_point<typename Profile::Point>(*p);
  }

 private:
  Hausdorff_bounded_options m_options;
  std::shared_ptr<Tracker> m_tracker;
  Quadrics m_quadrics;
  Get_cost m_cost;
  Filter m_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_PLACEMENT_H
