// Runs CGAL's edge_collapse with any cost, placement and filter under the apps' common stop
// predicate (a face count), progress visitor and timer, so every policy is measured the same way,
// bounds any policy's two-sided Hausdorff error when the settings ask for it (--max-error), and
// carries the mesh's corner attributes through the collapses, keeping their seams.
#ifndef CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H
#define CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H

#include "Stopwatch.h"
#include "policy_registry.h"

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Hausdorff_bounded_filter.h>
#include <cgal_policies/Seam_keeping_filter.h>
#include <cgal_policies/Seam_keeping_placement.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <chrono>
#include <functional>
#include <optional>

namespace apps {

// Stops once the mesh has no more than the target number of faces, or once the deadline has passed
// when there is one (a time limit of 0 sets none), and records which of the two stopped the run
// when given somewhere to record it.
class Face_count_stop_predicate {
 public:
  using Clock = std::chrono::steady_clock;

  Face_count_stop_predicate(const Mesh& mesh, std::size_t target, double time_limit_seconds = 0,
                            std::optional<Stop_reason>* reason = nullptr)
      : m_mesh(&mesh), m_target(target), m_has_deadline(time_limit_seconds > 0), m_reason(reason) {
    if (m_has_deadline)
      m_deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(time_limit_seconds));
  }
  template <typename FT, typename Profile>
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    std::optional<Stop_reason> reason;
    if (m_mesh->number_of_faces() <= m_target)
      reason = Stop_reason::target_reached;
    else if (m_has_deadline && Clock::now() >= m_deadline)
      reason = Stop_reason::time_limit;
    if (reason && m_reason) *m_reason = reason;
    return bool(reason);
  }

 private:
  const Mesh* m_mesh;
  std::size_t m_target;
  bool m_has_deadline;
  Clock::time_point m_deadline;
  std::optional<Stop_reason>* m_reason;
};

using Attribute_carrier = cgal_policies::Corner_attribute_carrier<Point>;

// Who keeps a --max-error bound in a run.
enum class Error_bound_keeper {
  runner,  // the runner wraps the policy's filter in Hausdorff_bounded_filter
  policy   // the policy bounds its error itself (hausdorff)
};

// The collapse the visitor has seen but not reported yet: a cost's update_after_collapse may still
// move the kept vertex after OnCollapsed. Outlives the run, since edge_collapse copies the visitor.
struct Pending_collapse {
  bool active = false;
  Mesh::Vertex_index removed, kept;

  void report(const Simplify_settings& settings) {
    if (!active) return;
    active = false;
    settings.on_collapse(removed, kept);
  }
};

// Reports every collapse to the settings' collapse callback once the policies have updated after
// it (at the next selected edge, the next collapse or the end of the run), and the face count to
// their progress callback every 1024 collapses; gives each collapse to the attribute carrier.
class Progress_visitor
    : public CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Mesh> {
 public:
  Progress_visitor(const Mesh& mesh, const Simplify_settings& settings, Pending_collapse& pending,
                   Attribute_carrier* carrier)
      : m_mesh(&mesh), m_settings(&settings), m_pending(&pending), m_carrier(carrier) {}
  void OnStarted(Mesh&) {
    if (m_carrier) m_carrier->started();
  }
  template <typename Profile, typename Cost>
  void OnSelected(const Profile&, const Cost&, std::size_t, std::size_t) {
    m_pending->report(*m_settings);
  }
  template <typename Profile, typename Placement>
  void OnCollapsing(const Profile& profile, const Placement& placement) {
    if (m_carrier && placement) m_carrier->collapsing(profile, *placement);
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile& profile, Vertex kept) {
    if (m_carrier) m_carrier->collapsed(kept);
    m_pending->report(*m_settings);  // collapses of zero-length edges come without a selection
    if (m_settings->on_collapse)
      *m_pending = {true, kept == profile.v0() ? profile.v1() : profile.v0(), kept};
    if (m_settings->on_progress && (++m_collapses & 1023) == 0)
      m_settings->on_progress(m_mesh->number_of_faces());
  }

 private:
  const Mesh* m_mesh;
  const Simplify_settings* m_settings;
  Pending_collapse* m_pending;
  Attribute_carrier* m_carrier;  // null when no attribute is carried
  std::size_t m_collapses = 0;
};

// With settings.max_error > 0, every placement the policy proposes is certified against the mesh
// as it is now (the input), in both directions, and the collapse refused otherwise; the run then
// ends at the target or when no collapse keeps the bound (error_bound_reached). The seam rules
// wrap every policy's placement and filter, and pass everything through when there is nothing to
// carry (one instantiation of edge_collapse per policy either way). `with_carrier` gets the carrier
// before the run when there is something to carry, for a policy that solves the values or picks the
// point itself.
template <typename GetCost, typename GetPlacement, typename Filter>
Simplify_outcome run_edge_collapse(
    Mesh& mesh, const Simplify_settings& settings, const GetCost& cost,
    const GetPlacement& base_placement, const Filter& base_filter,
    Error_bound_keeper keeper = Error_bound_keeper::runner,
    const std::function<void(Attribute_carrier&)>& with_carrier = {}) {
  const Stopwatch watch;
  Attribute_carrier carrier(mesh);
  Attribute_carrier* const carried = carrier.active() ? &carrier : nullptr;
  if (carried && with_carrier) with_carrier(*carried);
  const cgal_policies::Seam_keeping_placement<Point, GetPlacement> placement(base_placement,
                                                                             carried);
  using Filter_keeping_seams = cgal_policies::Seam_keeping_filter<Point, Filter>;
  const Filter_keeping_seams filter(base_filter, carried);
  Pending_collapse pending;
  std::optional<Stop_reason> stopped;
  const Face_count_stop_predicate stop(mesh, settings.target_faces, settings.time_limit_seconds,
                                       &stopped);
  const auto collapse = [&](const auto& outer_filter) {
    CGAL::Surface_mesh_simplification::edge_collapse(
        mesh, stop,
        CGAL::parameters::get_cost(cost)
            .get_placement(placement)
            .filter(outer_filter)
            .visitor(Progress_visitor(mesh, settings, pending, carried)));
  };
  // Outermost: the bound commits what it accepts, so no later check may refuse it (its header).
  if (settings.max_error > 0 && keeper == Error_bound_keeper::runner)
    collapse(cgal_policies::Hausdorff_bounded_filter<Mesh, Kernel, Filter_keeping_seams>(
        mesh, settings.max_error, filter));
  else
    collapse(filter);
  pending.report(settings);
  Simplify_outcome outcome;
  outcome.seconds = watch.seconds();
  outcome.attributes_carried = carried != nullptr;
  // Unless the predicate stopped the run, the queue ran dry (possibly right at the target).
  if (!stopped && mesh.number_of_faces() <= settings.target_faces)
    stopped = Stop_reason::target_reached;
  outcome.stop_reason = stopped                  ? *stopped
                        : settings.max_error > 0 ? Stop_reason::error_bound_reached
                                                 : Stop_reason::no_collapse_left;
  return outcome;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H
