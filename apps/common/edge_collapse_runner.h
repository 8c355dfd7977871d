// Runs CGAL's edge_collapse with any cost, placement and filter under the apps' common stop
// predicate (a face count), progress visitor and timer, so every policy is measured the same way.
#ifndef CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H
#define CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H

#include "policy_registry.h"

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <chrono>

namespace apps {

// Stops once the mesh has no more than the target number of faces.
class Face_count_stop_predicate {
 public:
  Face_count_stop_predicate(const Mesh& mesh, std::size_t target)
      : m_mesh(&mesh), m_target(target) {}
  template <typename FT, typename Profile>
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    return m_mesh->number_of_faces() <= m_target;
  }

 private:
  const Mesh* m_mesh;
  std::size_t m_target;
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
// their progress callback every 1024 collapses.
class Progress_visitor
    : public CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Mesh> {
 public:
  Progress_visitor(const Mesh& mesh, const Simplify_settings& settings, Pending_collapse& pending)
      : m_mesh(&mesh), m_settings(&settings), m_pending(&pending) {}
  template <typename Profile, typename Cost>
  void OnSelected(const Profile&, const Cost&, std::size_t, std::size_t) {
    m_pending->report(*m_settings);
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile& profile, Vertex kept) {
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
  std::size_t m_collapses = 0;
};

template <typename GetCost, typename GetPlacement, typename Filter>
Simplify_outcome run_edge_collapse(Mesh& mesh, const Simplify_settings& settings,
                                   const GetCost& cost, const GetPlacement& placement,
                                   const Filter& filter) {
  const auto start = std::chrono::steady_clock::now();
  Pending_collapse pending;
  CGAL::Surface_mesh_simplification::edge_collapse(
      mesh, Face_count_stop_predicate(mesh, settings.target_faces),
      CGAL::parameters::get_cost(cost).get_placement(placement).filter(filter).visitor(
          Progress_visitor(mesh, settings, pending)));
  pending.report(settings);
  Simplify_outcome outcome;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.stop_reason =
      mesh.number_of_faces() <= settings.target_faces ? "target_reached" : "no_collapse_left";
  return outcome;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H
