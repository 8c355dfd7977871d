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
  Face_count_stop_predicate(const Mesh& mesh, std::size_t target) : m_mesh(&mesh), m_target(target) {}
  template <typename FT, typename Profile>
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    return m_mesh->number_of_faces() <= m_target;
  }

 private:
  const Mesh* m_mesh;
  std::size_t m_target;
};

// Reports the face count to the settings' progress callback every 1024 collapses.
class Progress_visitor : public CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Mesh> {
 public:
  Progress_visitor(const Mesh& mesh, const Simplify_settings& settings)
      : m_mesh(&mesh), m_settings(&settings) {}
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile&, Vertex) {
    if (m_settings->on_progress && (++m_collapses & 1023) == 0)
      m_settings->on_progress(m_mesh->number_of_faces());
  }

 private:
  const Mesh* m_mesh;
  const Simplify_settings* m_settings;
  std::size_t m_collapses = 0;
};

template <typename GetCost, typename GetPlacement, typename Filter>
Simplify_outcome run_edge_collapse(Mesh& mesh, const Simplify_settings& settings,
                                   const GetCost& cost, const GetPlacement& placement,
                                   const Filter& filter) {
  const auto start = std::chrono::steady_clock::now();
  CGAL::Surface_mesh_simplification::edge_collapse(
      mesh, Face_count_stop_predicate(mesh, settings.target_faces),
      CGAL::parameters::get_cost(cost)
          .get_placement(placement)
          .filter(filter)
          .visitor(Progress_visitor(mesh, settings)));
  Simplify_outcome outcome;
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.stop_reason =
      mesh.number_of_faces() <= settings.target_faces ? "target_reached" : "no_collapse_left";
  return outcome;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EDGE_COLLAPSE_RUNNER_H
