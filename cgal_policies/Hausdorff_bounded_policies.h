// Hausdorff_bounded_policies: edge collapses that keep the output within tau = alpha * beta * D (D
// the input's bounding-box diagonal; [Liu17]'s lambda * alpha, lambda = psi(M0) * beta) of the
// input in two-sided Hausdorff distance, after [Liu17] §2.2-2.3 (docs/hausdorff.md). A popped
// edge's merged vertex is probed at K + 1 points at a constant step along the edge and at the
// quadric optimum; the certified one with the smallest lower bound wins, else the edge is refused.
// Global reference bounds the whole output; local ([Liu17]'s literal rule) lets errors accumulate.
// Models CGAL's `GetCost`, `GetPlacement` and `Filter` (get_cost(), get_placement(),
// get_filter()), which share m_state: this object must outlive the run.
// Parameters (Hausdorff_bounded_options):
//   beta                  tolerance factor, a fraction of D, > 0 (default 0.005)
//   alpha                 simplification coefficient, in (0, 1] (default 1)
//   steps                 K, the number of steps along the edge, >= 1 (default 10)
//   reference             Hausdorff_reference::global (default) or local
//   order                 Collapse_order::by_cost (default) or storage ([Liu17]'s single pass)
//   border                Border_rule::slide (default) or lock
//   max_normal_angle_deg  largest turn of a face normal, in degrees (default 90)
//   border_weight         weight of the border planes of the quadric, >= 0 (default 1000)
//   max_refinement        sample grids are refined up to 2^n steps per edge, >= 0 (default 5)
// Usage:
//   cgal_policies::Hausdorff_bounded_options options;
//   options.beta = 0.01;  // 1% of the diagonal
//   cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> policies(mesh, options);
//   SMS::edge_collapse(mesh, stop,
//                      CGAL::parameters::get_cost(policies.get_cost())
//                          .get_placement(policies.get_placement())
//                          .filter(policies.get_filter()));
//
// The choose / collapse / commit protocol (docs/hausdorff.md) under CGAL 5.5's SMS::edge_collapse:
// 1. initialize(), on the cost: every input face becomes a piece attached to itself.
// 2. Every edge whose cost is computed: get_placement() gives the quadric optimum restricted by the
//    border rule, get_cost() ranks it; this runs around every collapse, so it must stay cheap.
// 3. An edge is popped: get_filter() certifies the best candidate, holds it in m_state (the point,
//    and the new faces the old patch's pieces go to) and returns it.
// 4. CGAL collapses that edge at once (so the filter must be the outermost) and puts the kept
//    vertex at the PLACEMENT's point: the point a filter returns only means "accepted".
// 5. After OnCollapsed, the cost's update_after_collapse() moves the kept vertex to the chosen
//    point and attaches the pieces, before CGAL recomputes the costs around it.
// A choice no collapse follows is dropped by the next one. The HausdorffBoundedProtocol tests fail
// if CGAL changes this order.
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_POLICIES_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_POLICIES_H

#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Hausdorff_bounded_cost.h>
#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/Hausdorff_bounded_placement.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Hausdorff_bounded_policies {
 public:
  using Shared_state = internal::Hausdorff_bounded_state<TriangleMesh>;
  using Get_cost = Hausdorff_bounded_cost<TriangleMesh, GeomTraits>;
  using Get_placement = Hausdorff_bounded_placement<TriangleMesh, GeomTraits>;
  using Filter = Hausdorff_bounded_filter<TriangleMesh, GeomTraits>;

  explicit Hausdorff_bounded_policies(TriangleMesh& tm,
                                      const Hausdorff_bounded_options& options = {})
      : Hausdorff_bounded_policies(tm, options, get(CGAL::vertex_point, tm)) {}

  // `vpm`: tm's vertex point map, the one edge_collapse is given.
  template <typename VertexPointMap>
  Hausdorff_bounded_policies(TriangleMesh& tm, const Hausdorff_bounded_options& options,
                             const VertexPointMap& vpm)
      : Hausdorff_bounded_policies(tm, tm, vpm, options) {}

  // Against `reference` (vertex points reference_vpm) rather than tm as edge_collapse starts: tm
  // approximates it within tau already (the stitched parts of a partitioned run and their input);
  // in global mode the output stays within tau of the reference, whose diagonal is D.
  template <typename ReferencePointMap>
  Hausdorff_bounded_policies(TriangleMesh& tm, const TriangleMesh& reference,
                             const ReferencePointMap& reference_vpm,
                             const Hausdorff_bounded_options& options)
      : m_state(reference, reference_vpm, tm, options.alpha * options.beta, options),
        m_quadrics(tm, Quadric_options{options.border_weight, Face_weighting::unit}),
        m_cost(&m_state, m_quadrics, options.order),
        m_placement(m_quadrics, options.border),
        m_filter(&m_state, options) {
    CGAL_precondition(options.beta > 0);
    CGAL_precondition(options.alpha > 0 && options.alpha <= 1);
    CGAL_precondition(options.steps >= 1);
    CGAL_precondition(options.max_refinement >= 0);
    CGAL_precondition(options.border_weight >= 0);
  }

  // The cost and the filter point to m_state.
  Hausdorff_bounded_policies(const Hausdorff_bounded_policies&) = delete;
  Hausdorff_bounded_policies& operator=(const Hausdorff_bounded_policies&) = delete;

  const Get_cost& get_cost() const { return m_cost; }
  const Get_placement& get_placement() const { return m_placement; }
  const Filter& get_filter() const { return m_filter; }

  // tau, in the mesh's units.
  double tolerance() const { return m_state.tolerance(); }

  // Lets the filter pick only points the seam rules of `carrier` (a Corner_attribute_carrier of
  // the mesh) allow. Call before edge_collapse, with the carrier's Seam_keeping_placement and
  // Seam_keeping_filter around these policies (edge_collapse_runner.h).
  template <typename Carrier>
  void keep_seams_with(const Carrier& carrier) {
    m_state.set_candidate_rule([&carrier](auto edge, const Eigen::Vector3d& p) {
      return carrier.allows(edge, internal::to_point<typename Carrier::Mesh::Point>(p));
    });
  }

 private:
  Shared_state m_state;
  Classic_quadric_policies<TriangleMesh, GeomTraits> m_quadrics;  // shared by cost and placement
  Get_cost m_cost;
  Get_placement m_placement;
  Filter m_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_POLICIES_H
