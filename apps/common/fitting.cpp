#include "fitting.h"

#include "App_error.h"
#include "Stopwatch.h"

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Two_sided_fitter.h>

#include <cmath>
#include <vector>

namespace apps {
namespace {

using Attributes = cgal_policies::Corner_attributes<Point>;
using Carrier = cgal_policies::Corner_attribute_carrier<Point>;

// After a fit that moved only the vertices on no seam, and flipped nothing: each moved vertex
// takes the values at the point of its old star (`before`) nearest its new point, as a collapse's
// kept vertex does (docs/attributes.md), unless that would turn a texture triangle around it over.
void carry_corner_values(Mesh& mesh, const Mesh& before) {
  const Attributes attributes(mesh), old(before);
  for (const auto v : mesh.vertices()) {
    if (mesh.point(v) == before.point(v)) continue;
    std::vector<Mesh::Face_index> star;
    for (const auto f : CGAL::faces_around_target(before.halfedge(v), before))
      if (f != Mesh::null_face()) star.push_back(f);
    const Attributes::Values value = Carrier::values_nearest(before, old, star, mesh.point(v));
    bool keeps_orientation = true;
    for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
      if (mesh.is_border(h) || !attributes.uvs) continue;
      const auto& b = (*attributes.uvs)[mesh.next(h)];
      const auto& c = (*attributes.uvs)[mesh.prev(h)];
      const double was = Attributes::uv_area((*attributes.uvs)[h], b, c),
                   now = Attributes::uv_area(value.uv, b, c);
      keeps_orientation =
          keeps_orientation && !(std::isfinite(was) && was != 0 && !(was * now > 0));
    }
    if (!keeps_orientation) continue;
    for (const auto h : CGAL::halfedges_around_target(v, mesh))
      if (!mesh.is_border(h)) attributes.set_values(h, value);
  }
}

}  // namespace

const char* const kFitSuffix = "+fit";

std::optional<std::string> fitted_base(const std::string& name) {
  const std::string suffix = kFitSuffix;
  if (name.size() <= suffix.size() ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  return name.substr(0, name.size() - suffix.size());
}

Fit_request take_fit_options(Command_line& cli) {
  Fit_request request;
  request.enabled = cli.take_flag("fit");
  request.rounds = cgal_policies::Two_sided_fit_options().rounds;
  if (const auto rounds = cli.take_whole_number("fit-rounds", 1, 1000)) {
    if (!request.enabled) throw App_error(exit_usage, "--fit-rounds goes with --fit");
    request.rounds = int(*rounds);
  }
  return request;
}

std::string fit_help() {
  return "  --fit                 then fit the output to IN in both directions, moving vertices\n"
         "                        and flipping edges (docs/fitting.md); within the run's bound\n"
         "                        when it has one (--max-error, or the policy's --tolerance)\n"
         "  --fit-rounds N        fit rounds, each followed by a flip round, 1..1000 (default " +
         std::to_string(cgal_policies::Two_sided_fit_options().rounds) + ")\n";
}

double two_sided_bound(const Policy_entry& policy, const Simplify_settings& settings) {
  if (settings.max_error > 0) return settings.max_error;
  return policy.own_bound ? policy.own_bound(settings) : 0.0;
}

Fit_outcome fit_to_input(Mesh& mesh, const Mesh& original, int rounds, double max_normal_angle_deg,
                         double bound) {
  const Stopwatch watch;
  cgal_policies::Two_sided_fit_options options;
  options.rounds = rounds;
  options.max_normal_angle_deg = max_normal_angle_deg;
  options.tolerance = bound;
  Fit_outcome outcome;
  if (!Attributes(mesh).any_corner_values()) {
    outcome.report = cgal_policies::Two_sided_fitter<Mesh>(original, options).fit(mesh);
    outcome.seconds = watch.seconds();
    return outcome;
  }
  // Corner values: the seams stay where they are, no edge flips (a flip would hand corners to
  // other vertices), and every moved vertex takes the values where it went.
  options.flips = false;
  const Mesh before = mesh;
  const Carrier seams(mesh);
  outcome.report =
      cgal_policies::Two_sided_fitter<Mesh>(original, options).fit(mesh, [&](Mesh::Vertex_index v) {
        return seams.seam_edges_at(v) > 0;
      });
  carry_corner_values(mesh, before);
  outcome.seconds = watch.seconds();
  return outcome;
}

Policy_entry with_fit(const Policy_entry& policy) {
  Policy_entry fitted = policy;
  fitted.name = policy.name + kFitSuffix;
  fitted.summary = policy.summary + ", then fitted to the input (docs/fitting.md)";
  fitted.run = [policy](Mesh& mesh, const Simplify_settings& settings) {
    const Mesh original = mesh;
    Simplify_outcome outcome = policy.run(mesh, settings);
    mesh.collect_garbage();
    const Fit_outcome fit =
        fit_to_input(mesh, original, cgal_policies::Two_sided_fit_options().rounds,
                     settings.max_normal_angle_deg, two_sided_bound(policy, settings));
    outcome.fit_seconds = fit.seconds;
    outcome.fit_flips = fit.report.flips;
    return outcome;
  };
  return fitted;
}

}  // namespace apps
