// CGAL's Garland-Heckbert policies inside CGAL's Polyhedral_envelope_filter: a collapse is refused
// when the new triangles leave the envelope of the input at distance epsilon.
#include "bench_peers.h"
#include "common/edge_collapse_runner.h"
#include "common/mesh_measures.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Polyhedral_envelope_filter.h>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

Simplify_outcome run_gh_envelope(Mesh& mesh, const Simplify_settings& settings) {
  const SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(mesh);
  const double epsilon = settings.options.at("envelope-epsilon") * bbox_diagonal(mesh);
  return run_edge_collapse(mesh, settings, policies.get_cost(), policies.get_placement(),
                           SMS::Polyhedral_envelope_filter<Kernel>(epsilon));
}

}  // namespace

std::vector<Policy_entry> envelope_peers() {
  return {{"gh-envelope",
           "CGAL GarlandHeckbert_plane_policies with Polyhedral_envelope_filter",
           {{"envelope-epsilon", 0.01, "envelope distance of gh-envelope"}},
           run_gh_envelope}};
}

}  // namespace apps
