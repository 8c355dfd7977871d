// How the tests run a policy of the registry: through the apps' pipeline (apps/pipeline/), the
// policy alone (no fitting pass) with its defaults, down to a face count.
#ifndef CGAL_POLICIES_TESTS_SUPPORT_PIPELINE_RUNS_H
#define CGAL_POLICIES_TESTS_SUPPORT_PIPELINE_RUNS_H

#include "evaluation/surface_error.h"
#include "pipeline/Pipeline.h"
#include "pipeline/policy_registry.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace pipeline_runs {

// The mean two-sided error of `mesh` against `original`, 50,000 samples a direction.
inline double mean_error(const apps::Mesh& original, const apps::Mesh& mesh) {
  return apps::measure_mesh_error(original, mesh, 50000).mean();
}

// Every policy of the registry by name, for parameterised tests.
inline std::vector<std::string> policy_names() {
  std::vector<std::string> names;
  for (const apps::Policy_entry& p : apps::policy_registry()) names.push_back(p.name);
  return names;
}

// The options of the named policy alone down to `target` faces.
inline cgal_policies::Simplification_options policy_alone(const std::string& policy,
                                                          std::size_t target) {
  const apps::Policy_entry* entry = apps::find_policy(policy);
  if (!entry) throw std::invalid_argument("no policy " + policy);
  cgal_policies::Simplification_options options;
  options.policy = entry->policy;
  options.fit = false;
  options.target = cgal_policies::Face_target::faces(target);
  return options;
}

// Simplifies `mesh` in place (left compact) with those options.
inline cgal_policies::Simplification_report simplify(apps::Mesh& mesh, const std::string& policy,
                                                     std::size_t target) {
  return apps::Pipeline(policy_alone(policy, target)).run(mesh);
}

// The stages of a partitioned job cut into `parts` parts in `folder` (Simplification_pipeline::
// run_part, stitch), the parts of each stage in reverse order (any order will do), then its
// result into `mesh`; its number of stages.
inline int run_job_stages(const apps::Pipeline& pipeline, std::size_t parts,
                          const std::filesystem::path& folder, apps::Mesh& mesh,
                          cgal_policies::Simplification_report& report) {
  int stage = 0;
  for (;; ++stage) {
    for (std::size_t c = parts; c-- > 0;) pipeline.run_part(folder, stage, c);
    if (!pipeline.stitch(folder, stage)) break;
  }
  report = pipeline.result(folder, mesh);
  return stage + 1;
}

// The tasks of a partitioned job on `mesh` in `folder`: cut, then run_job_stages.
inline int run_as_job(const cgal_policies::Simplification_options& options, apps::Mesh& mesh,
                      const std::filesystem::path& folder,
                      cgal_policies::Simplification_report& report) {
  const apps::Pipeline pipeline(options);
  return run_job_stages(pipeline, pipeline.cut(mesh, folder), folder, mesh, report);
}

}  // namespace pipeline_runs

#endif  // CGAL_POLICIES_TESTS_SUPPORT_PIPELINE_RUNS_H
