// How Simplification_pipeline runs an edge-collapse policy: CGAL's SMS::edge_collapse under a
// Face_count_stop_predicate (target, time limit, interruption), the pipeline's visitor wrapped in
// Attribute_carrying_visitor, the seam rules around the policy's placement and filter, and, with
// max_error, Hausdorff_bounded_filter outermost, so that every policy keeps the same bound.
#ifndef CGAL_POLICIES_INTERNAL_RUN_EDGE_COLLAPSE_H
#define CGAL_POLICIES_INTERNAL_RUN_EDGE_COLLAPSE_H

#include <cgal_policies/Attribute_carrying_visitor.h>
#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Seam_keeping_filter.h>
#include <cgal_policies/Seam_keeping_placement.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Locked_vertex_filter.h>
#include <cgal_policies/internal/Pipeline_visitor.h>
#include <cgal_policies/internal/Policy_outcome.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cstddef>
#include <functional>
#include <type_traits>

namespace cgal_policies {
namespace internal {

// Who keeps a max_error bound in a run.
enum class Error_bound_keeper {
  runner,  // the runner wraps the policy's filter in Hausdorff_bounded_filter
  policy   // the policy bounds its error itself (hausdorff)
};

// With options.max_error > 0 and the runner keeping the bound, every placement the policy proposes
// is certified against the input, in both directions, and the collapse refused otherwise; the run
// then ends at the target or when no collapse keeps the bound (error_bound_reached). The input is
// `reference` when given (the mesh a partitioned run cut into the parts that `mesh` stitches),
// else the mesh as it is now. The seam rules wrap every policy's placement and filter, and pass
// everything through when there is nothing to carry (one instantiation of edge_collapse per policy
// either way). `with_carrier` gets the carrier before the run when there is something to carry,
// for a policy that solves the values or picks the point itself.
template <class Point, class GetCost, class GetPlacement, class Filter>
Policy_outcome run_edge_collapse(
    CGAL::Surface_mesh<Point>& mesh, std::size_t target_faces,
    const Simplification_options& options, const GetCost& cost, const GetPlacement& base_placement,
    const Filter& base_filter, Error_bound_keeper keeper = Error_bound_keeper::runner,
    // Point comes from the mesh alone (enable_if_t: not deduced here), so a lambda converts.
    const std::function<void(Corner_attribute_carrier<std::enable_if_t<true, Point>>&)>&
        with_carrier = {},
    const CGAL::Surface_mesh<std::enable_if_t<true, Point>>* reference = nullptr) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Carrier = Corner_attribute_carrier<Point>;
  Carrier carrier(mesh);
  Carrier* const carried = carrier.active() ? &carrier : nullptr;
  if (carried && with_carrier) with_carrier(*carried);
  const Seam_keeping_placement<Point, GetPlacement> placement(base_placement, carried);
  using Filter_keeping_seams = Seam_keeping_filter<Point, Locked_vertex_filter<Point, Filter>>;
  const Filter_keeping_seams filter(Locked_vertex_filter<Point, Filter>(mesh, base_filter),
                                    carried);
  Pending_collapse pending;
  const Face_count_stop_predicate<Mesh> stop(mesh, target_faces, options.time_limit_seconds,
                                             options.interrupted);
  using Visitor = Attribute_carrying_visitor<Point, Pipeline_visitor<Point>>;
  const auto collapse = [&](const auto& outer_filter) {
    CGAL::Surface_mesh_simplification::edge_collapse(
        mesh, stop,
        CGAL::parameters::get_cost(cost)
            .get_placement(placement)
            .filter(outer_filter)
            .visitor(
                Visitor(carried, Pipeline_visitor<Point>(mesh, target_faces, options, pending))));
  };
  const bool bounded = options.max_error > 0;
  // Outermost: the bound commits what it accepts, so no later check may refuse it (its header).
  if (bounded && keeper == Error_bound_keeper::runner) {
    const Mesh& input = reference ? *reference : mesh;
    collapse(Hausdorff_bounded_filter<Mesh, Kernel, Filter_keeping_seams>(
        mesh, input, input.points(), options.max_error, filter, mesh.points()));
  } else {
    collapse(filter);
  }
  pending.report(options);
  Policy_outcome outcome;
  outcome.attributes_carried = carried != nullptr;
  // Unless the predicate stopped the run, the queue ran dry (possibly right at the target).
  if (stop.reason())
    outcome.stop_reason = *stop.reason();
  else if (mesh.number_of_faces() <= target_faces)
    outcome.stop_reason = Stop_reason::target_reached;
  else
    outcome.stop_reason =
        bounded ? Stop_reason::error_bound_reached : Stop_reason::no_collapse_left;
  return outcome;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_EDGE_COLLAPSE_H
