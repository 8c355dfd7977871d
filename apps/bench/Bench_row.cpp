#include "Bench_row.h"

#include "cli/App_error.h"
#include "cli/out_of_core_run.h"
#include "pipeline/Pipeline.h"

namespace apps {
namespace {

Bench_run bench_run(const cgal_policies::Simplification_report& report) {
  Bench_run run;
  run.seconds = report.seconds(cgal_policies::Simplification_pass::simplification);
  run.fit_seconds = report.seconds(cgal_policies::Simplification_pass::fit);
  run.fit_flips = report.fit.flips;
  run.stop_reason = report.stop_reason;
  run.attributes_carried = report.attributes_carried;
  run.input_faces = report.input_faces;
  run.input_vertices = report.input_vertices;
  return run;
}

}  // namespace

Bench_row pipeline_row(const Policy_entry& policy, bool fit) {
  Bench_row row;
  row.name = policy.name + (fit ? kFitSuffix : "");
  row.summary = policy.summary + (fit ? ", then fitted to the input (docs/fitting.md)" : "");
  row.options = policy.options;
  row.uses_threads = true;
  const auto options_of = [&policy, fit](const Bench_settings& settings) {
    cgal_policies::Simplification_options options;
    options.policy = policy.policy;
    options.fit = fit;
    options.threads = settings.threads;
    options.target = cgal_policies::Face_target::faces(settings.target_faces);
    if (cgal_policies::runs_edge_collapse(policy.policy))
      options.time_limit_seconds = settings.time_limit_seconds;
    apply_policy_options(policy, settings.options, options);
    if (options.two_sided_bound() == 0) options.prepass_factor = settings.prepass_factor;
    return options;
  };
  row.run = [options_of](Mesh& mesh, const Bench_settings& settings) {
    return bench_run(Pipeline(options_of(settings)).run(mesh));
  };
  // The policy's defaults decide whether it needs the input whole (hausdorff's bound does).
  if (runs_out_of_core(options_of(Bench_settings())))
    row.run_out_of_core = [options_of](const std::string& input, Mesh& result,
                                       const Bench_settings& settings) {
      const cgal_policies::Simplification_options options = options_of(settings);
      if (!runs_out_of_core(options))
        throw App_error(exit_usage, "out of core, the options given set a bound, which needs " +
                                        input + " whole");
      const Streamed_mesh_file source(input);
      return bench_run(run_out_of_core(Pipeline(options), source, input, result));
    };
  return row;
}

std::optional<std::string> fitted_base(const std::string& name) {
  const std::string suffix = kFitSuffix;
  if (name.size() <= suffix.size() ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  return name.substr(0, name.size() - suffix.size());
}

}  // namespace apps
