// CGAL's Garland-Heckbert policies inside CGAL's Polyhedral_envelope_filter: a collapse is refused
// when the new triangles leave the envelope of the input at distance epsilon. A peer, not one of
// this suite's pipelines: it runs through the same edge-collapse runner, so that its stop
// predicate, time limit and timing are theirs.
#include "bench_peers.h"
#include "cli/Stopwatch.h"
#include "evaluation/surface_error.h"

#include <cgal_policies/internal/run_edge_collapse.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Polyhedral_envelope_filter.h>

#include <limits>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

constexpr double kDefaultEpsilon = 0.01;  // a fraction of the input's diagonal

Policy_option epsilon_option() {
  Policy_option option;
  option.name = "envelope-epsilon";
  option.help = "envelope distance of gh-envelope, a fraction of D";
  option.default_value = kDefaultEpsilon;
  option.min = 0;
  option.min_is_excluded = true;
  return option;
}

Bench_run run_gh_envelope(Mesh& mesh, const Bench_settings& settings) {
  const SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(mesh);
  const auto given = settings.options.find("envelope-epsilon");
  const double epsilon =
      (given == settings.options.end() ? kDefaultEpsilon : given->second) * bbox_diagonal(mesh);
  cgal_policies::Simplification_options options;
  options.time_limit_seconds = settings.time_limit_seconds;
  const Stopwatch watch;
  const cgal_policies::internal::Policy_outcome outcome =
      cgal_policies::internal::run_edge_collapse(mesh, settings.target_faces, options,
                                                 policies.get_cost(), policies.get_placement(),
                                                 SMS::Polyhedral_envelope_filter<Kernel>(epsilon));
  Bench_run run;
  run.seconds = watch.seconds();
  run.stop_reason = outcome.stop_reason;
  run.attributes_carried = outcome.attributes_carried;
  return run;
}

}  // namespace

std::vector<Bench_row> envelope_peers() {
  return {{"gh-envelope",
           "CGAL GarlandHeckbert_plane_policies with Polyhedral_envelope_filter",
           {epsilon_option()},
           run_gh_envelope}};
}

}  // namespace apps
