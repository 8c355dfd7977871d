// CGAL's own policies, run as CGAL ships them (no extra filter), as the baselines
// (docs/evaluation.md).
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

const SMS::internal::Dummy_filter kNoFilter;

template <typename Policies>
Simplify_outcome run_garland_heckbert(Mesh& mesh, const Simplify_settings& settings) {
  const Policies policies(mesh);
  return run_edge_collapse(mesh, settings, policies.get_cost(), policies.get_placement(),
                           kNoFilter);
}

Simplify_outcome run_lindstrom_turk(Mesh& mesh, const Simplify_settings& settings) {
  return run_edge_collapse(mesh, settings, SMS::LindstromTurk_cost<Mesh>(),
                           SMS::LindstromTurk_placement<Mesh>(), kNoFilter);
}

}  // namespace

std::vector<Policy_entry> cgal_baseline_policies() {
  return {
      {"gh",
       "CGAL GarlandHeckbert_plane_policies (classic QEM)",
       {},
       run_garland_heckbert<SMS::GarlandHeckbert_plane_policies<Mesh, Kernel>>},
      {"gh-prob",
       "CGAL GarlandHeckbert_probabilistic_plane_policies",
       {},
       run_garland_heckbert<SMS::GarlandHeckbert_probabilistic_plane_policies<Mesh, Kernel>>},
      {"lt", "CGAL LindstromTurk_cost and LindstromTurk_placement", {}, run_lindstrom_turk},
  };
}

}  // namespace apps
