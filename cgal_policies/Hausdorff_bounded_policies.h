// Hausdorff_bounded_policies: edge collapses that keep the simplified surface within a tolerance
// of the original, in both directions, after [Liu17] §2.2-2.3 (docs/hausdorff.md).
//
// - Tolerance tau = alpha * beta * D, D the diagonal of the input's bounding box ([Liu17]'s
//   lambda * alpha with lambda = psi(M0) * beta).
// - A popped edge's merged vertex is probed at K + 1 points at a constant step along the edge and
//   at the quadric optimum; of those certified within tau, the one with the smallest lower bound
//   of its two-sided patch distance wins, else the edge is refused.
// - Hausdorff_reference::global measures candidates against the input, so the output's two-sided
//   Hausdorff distance to the input never exceeds tau; local is [Liu17]'s literal rule, against
//   the current patch, so errors accumulate.
//
// Models CGAL's `GetCost` (get_cost()), `GetPlacement` (get_placement()) and `Filter`
// (get_filter()) concepts, which share m_state: this object must outlive the run.
//
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
//
// Usage:
//   cgal_policies::Hausdorff_bounded_options options;
//   options.beta = 0.01;  // 1% of the diagonal
//   cgal_policies::Hausdorff_bounded_policies<Mesh, Kernel> policies(mesh, options);
//   SMS::edge_collapse(mesh, stop,
//                      CGAL::parameters::get_cost(policies.get_cost())
//                          .get_placement(policies.get_placement())
//                          .filter(policies.get_filter()));
//
// The choose / collapse / commit protocol (docs/hausdorff.md, "The choose / collapse / commit
// protocol"), as SMS::edge_collapse calls the three in CGAL 5.5:
// 1. initialize(), on the cost: every input face becomes a piece attached to itself.
// 2. Whenever an edge's cost is computed: get_placement() gives the quadric optimum restricted by
//    the border rule, which get_cost() ranks. It runs for every edge around every collapse, so it
//    must stay cheap: the certified search is left to the filter.
// 3. An edge is popped: get_filter() certifies the best candidate and keeps it pending in m_state
//    (the point, and the new faces the old patch's pieces go to), and returns it.
// 4. CGAL collapses that edge at once, the filter being the last check (so it must be the
//    outermost filter), and puts the kept vertex at the PLACEMENT's point: the point a filter
//    returns only means "accepted".
// 5. OnCollapsed, then the cost's update_after_collapse(): it moves the kept vertex to the point
//    the filter chose and attaches the pieces. This is the first hook after the collapse and runs
//    before CGAL computes the costs around the kept vertex again, so they see the vertex where it
//    ends. A choice no collapse follows (a filter asked directly) is dropped by the next one.
// tests/hausdorff_filter_test.cpp (HausdorffBoundedProtocol) fails if CGAL changes this order.
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
      : m_state(tm, vpm, tm, options.alpha * options.beta, options),
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

 private:
  Shared_state m_state;
  Classic_quadric_policies<TriangleMesh, GeomTraits> m_quadrics;  // shared by cost and placement
  Get_cost m_cost;
  Get_placement m_placement;
  Filter m_filter;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_POLICIES_H
