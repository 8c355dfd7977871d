#include "Bench_row.h"

#include "pipeline/Pipeline.h"

namespace apps {

Bench_row pipeline_row(const Policy_entry& policy, bool fit) {
  Bench_row row;
  row.name = policy.name + (fit ? kFitSuffix : "");
  row.summary = policy.summary + (fit ? ", then fitted to the input (docs/fitting.md)" : "");
  row.options = policy.options;
  row.run = [&policy, fit](Mesh& mesh, const Bench_settings& settings) {
    cgal_policies::Simplification_options options;
    options.policy = policy.policy;
    options.fit = fit;
    options.target = cgal_policies::Face_target::faces(settings.target_faces);
    if (cgal_policies::runs_edge_collapse(policy.policy))
      options.time_limit_seconds = settings.time_limit_seconds;
    apply_policy_options(policy, settings.options, options);
    const cgal_policies::Simplification_report report = Pipeline(options).run(mesh);
    Bench_run run;
    run.seconds = report.seconds(cgal_policies::Simplification_pass::simplification);
    run.fit_seconds = report.seconds(cgal_policies::Simplification_pass::fit);
    run.fit_flips = report.fit.flips;
    run.stop_reason = report.stop_reason;
    run.attributes_carried = report.attributes_carried;
    return run;
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
