// Hausdorff_bounded_filter: refuses a collapse unless some placement keeps the two-sided Hausdorff
// distance within the tolerance tau = alpha * beta * D (policies.md §3; Liu et al. 2017, seed 003,
// §2.3: lambda = psi(M0) * beta, accept when the best distance <= lambda * alpha).
//
// When an edge is popped it probes the K + 1 points at a constant step along the edge and the
// placement it was given (the quadric optimum), subject to the border rule and the flip check
// (Bounded_normal_angle_filter), and keeps the one with the smallest lower bound of its two-sided
// patch distance that passes the conservative test (refined sample grids plus their covering
// radius one way, input pieces covered by single faces the other way). The chosen point reaches
// the mesh through Hausdorff_bounded_cost::update_after_collapse.
//
// It can also run alone, around any cost and placement, to certify only the placement it is given
// (an error bound for any policy): then nothing else is needed.
//
// Models CGAL's `Filter` concept and decorates a base filter, which runs first. It must be the
// outermost filter: what it accepts is collapsed at once, and it relies on that.
//
// Parameters: see Hausdorff_bounded_options (tolerance as a fraction of the input's diagonal D).
//
// Usage (alone, bounding any policy to 0.5% of D):
//   cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel> bound(mesh, 0.005);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(c).get_placement(p).filter(bound));
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_tracker.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/hausdorff_candidates.h>

#include <CGAL/Surface_mesh_simplification/internal/Common.h>

#include <memory>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits,
          typename BaseFilter = CGAL::Surface_mesh_simplification::internal::Dummy_filter>
class Hausdorff_bounded_filter {
 public:
  using Tracker = internal::Hausdorff_tracker<TriangleMesh>;

  // Probes candidates for Hausdorff_bounded_placement, with which it shares `tracker`.
  Hausdorff_bounded_filter(std::shared_ptr<Tracker> tracker,
                           const Hausdorff_bounded_options& options,
                           const BaseFilter& base_filter = BaseFilter())
      : m_tracker(std::move(tracker)),
        m_options(options),
        m_search(true),
        m_flip(options.max_normal_angle_deg),
        m_base_filter(base_filter) {}

  // Alone: certifies the placement it is given against `tm` as it is now, within
  // tolerance * D of it (a fraction of its bounding-box diagonal).
  Hausdorff_bounded_filter(TriangleMesh& tm, double tolerance,
                           const BaseFilter& base_filter = BaseFilter())
      : m_tracker(std::make_shared<Tracker>(tm, tm, tolerance, Hausdorff_bounded_options())),
        m_search(false),
        m_base_filter(base_filter) {
    m_tracker->attach_to_itself(tm, get(CGAL::vertex_point, tm));
    m_tracker->defer_commits();
  }

  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(
      const Profile& profile, internal::Optional<typename Profile::Point> placement) const {
    using Point = typename Profile::Point;
    placement = m_base_filter(profile, placement);
    if (!placement) return placement;
    if (m_options.order == Collapse_order::storage) m_tracker->mark_tried(profile);
    const Eigen::Vector3d preferred = internal::to_eigen(*placement);
    std::vector<Eigen::Vector3d> candidates{preferred};
    if (m_search)
      candidates = internal::collapse_candidates(
          profile, internal::border_case(profile, m_options.border), preferred, m_options.steps);
    const auto acceptable = [&](const Eigen::Vector3d& p) {
      return !m_search ||
             bool(m_flip(profile, internal::Optional<Point>(internal::to_point<Point>(p))));
    };
    const internal::Optional<Eigen::Vector3d> chosen =
        m_tracker->choose(profile, candidates, acceptable);
    if (!chosen) return {};
    return internal::to_point<Point>(*chosen);
  }

 private:
  std::shared_ptr<Tracker> m_tracker;
  Hausdorff_bounded_options m_options;
  bool m_search;
  Bounded_normal_angle_filter<> m_flip;
  BaseFilter m_base_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H
