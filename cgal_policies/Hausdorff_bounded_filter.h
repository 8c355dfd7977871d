// Hausdorff_bounded_filter: a CGAL `Filter` that refuses a collapse unless the output stays within
// tau of the input in two-sided Hausdorff distance ([Liu17] §2.3: accept when the best distance
// <= lambda * alpha, lambda = psi(M0) * beta; docs/hausdorff.md). Within Hausdorff_bounded_policies
// it picks among the K + 1 points along the edge and the placement; alone, around any cost and
// placement, it certifies only the placement, against the mesh as it was when built, or against
// another reference that mesh approximates. It decorates a base filter, run first, and must be
// the outermost: what it accepts is taken as collapsed.
// Parameters (alone):
//   tm             the mesh to simplify, also the reference (as it is now) unless one is given
//   reference      the mesh tm must stay within tau of, tm being within tau of it already (the
//                  stitched parts of a partitioned run and their input), with reference_vpm
//   tolerance      tau as a fraction of the diagonal D of the reference's bounding box, > 0
//   base_filter    runs first (default: accepts everything)
//   vpm            tm's vertex point map (default: get(CGAL::vertex_point, tm))
// Usage (alone, bounding any policy to 0.5% of D):
//   cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel> bound(mesh, 0.005);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(c).get_placement(p).filter(bound));
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H

#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/hausdorff_candidates.h>

#include <CGAL/Surface_mesh_simplification/internal/Common.h>
#include <CGAL/assertions.h>

#include <memory>
#include <vector>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits,
          typename BaseFilter = CGAL::Surface_mesh_simplification::internal::Dummy_filter>
class Hausdorff_bounded_filter {
 public:
  using Shared_state = internal::Hausdorff_bounded_state<TriangleMesh>;

  // Within Hausdorff_bounded_policies, which owns `state`.
  Hausdorff_bounded_filter(Shared_state* state, const Hausdorff_bounded_options& options,
                           const BaseFilter& base_filter = BaseFilter())
      : m_state(state),
        m_options(options),
        m_search(true),
        m_flip(options.max_normal_angle_deg),
        m_base_filter(base_filter) {
    CGAL_precondition(state != nullptr);
  }

  // Alone.
  Hausdorff_bounded_filter(TriangleMesh& tm, double tolerance,
                           const BaseFilter& base_filter = BaseFilter())
      : Hausdorff_bounded_filter(tm, tolerance, base_filter, get(CGAL::vertex_point, tm)) {}

  template <typename VertexPointMap>
  Hausdorff_bounded_filter(TriangleMesh& tm, double tolerance, const BaseFilter& base_filter,
                           const VertexPointMap& vpm)
      : Hausdorff_bounded_filter(tm, tm, vpm, tolerance, base_filter, vpm) {}

  // Alone, against `reference`.
  template <typename ReferencePointMap, typename VertexPointMap>
  Hausdorff_bounded_filter(TriangleMesh& tm, const TriangleMesh& reference,
                           const ReferencePointMap& reference_vpm, double tolerance,
                           const BaseFilter& base_filter, const VertexPointMap& vpm)
      : m_owned_state(std::make_shared<Shared_state>(reference, reference_vpm, tm, tolerance,
                                                     Hausdorff_bounded_options())),
        m_state(m_owned_state.get()),
        m_search(false),
        m_base_filter(base_filter) {
    CGAL_precondition(tolerance > 0);
    m_state->attach(tm, vpm);
    m_state->defer_commits();
  }

  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(
      const Profile& profile, internal::Optional<typename Profile::Point> placement) const {
    using Point = typename Profile::Point;
    placement = m_base_filter(profile, placement);
    if (!placement) return placement;
    if (m_options.order == Collapse_order::storage) m_state->scan_order().mark_tried(profile);
    const Eigen::Vector3d preferred = internal::to_eigen(*placement);
    std::vector<Eigen::Vector3d> candidates{preferred};
    if (m_search)
      candidates = internal::collapse_candidates(
          profile, internal::border_case(profile, m_options.border), preferred, m_options.steps);
    const auto acceptable = [&](const Eigen::Vector3d& p) {
      if (!m_state->allows(profile.v0_v1(), p)) return false;
      return !m_search ||
             bool(m_flip(profile, internal::Optional<Point>(internal::to_point<Point>(p))));
    };
    const internal::Optional<Eigen::Vector3d> chosen =
        m_state->choose(profile, candidates, acceptable);
    if (!chosen) return {};
    return internal::to_point<Point>(*chosen);
  }

 private:
  std::shared_ptr<Shared_state> m_owned_state;  // alone only
  Shared_state* m_state;
  Hausdorff_bounded_options m_options;
  bool m_search;
  Bounded_normal_angle_filter<> m_flip;
  BaseFilter m_base_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_FILTER_H
