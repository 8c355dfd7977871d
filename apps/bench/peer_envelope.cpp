// CGAL's Garland-Heckbert policies inside CGAL's Polyhedral_envelope_filter: a collapse is refused
// when the new triangles leave the envelope of the input at distance epsilon.
#include "bench_peers.h"
#include "common/Policy_options_table.h"
#include "common/edge_collapse_runner.h"
#include "common/mesh_measures.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Polyhedral_envelope_filter.h>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

struct Envelope_options {
  double epsilon = 0.01;  // a fraction of the input's diagonal
};

const Policy_options_table<Envelope_options>& envelope_options() {
  using Table = Policy_options_table<Envelope_options>;
  static const Table table =
      Table().number("envelope-epsilon", &Envelope_options::epsilon, 0, Table::unbounded,
                     "envelope distance of gh-envelope, a fraction of D", true);
  return table;
}

Simplify_outcome run_gh_envelope(Mesh& mesh, const Simplify_settings& settings) {
  const SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(mesh);
  const double epsilon = envelope_options().read(settings.options).epsilon * bbox_diagonal(mesh);
  return run_edge_collapse(mesh, settings, policies.get_cost(), policies.get_placement(),
                           SMS::Polyhedral_envelope_filter<Kernel>(epsilon));
}

}  // namespace

std::vector<Policy_entry> envelope_peers() {
  return {{"gh-envelope", "CGAL GarlandHeckbert_plane_policies with Polyhedral_envelope_filter",
           envelope_options().options(), run_gh_envelope}};
}

}  // namespace apps
