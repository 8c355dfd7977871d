// The out-of-core run of `simplify --out-of-core` and of simplify_bench's out-of-core rows
// (docs/scale.md): what the pipeline's run_streamed allows, and the run on a file read in passes
// or the cut of a job from it.
#ifndef CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H
#define CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H

#include "io/Streamed_mesh_file.h"
#include "pipeline/Pipeline.h"

#include <cstddef>
#include <filesystem>
#include <string>

namespace apps {

// Whether run_streamed takes these options: it never holds the input whole, which a bound (the
// hausdorff policy, --max-error), merging, small components and bounded smoothing need.
bool runs_out_of_core(const cgal_policies::Simplification_options& options);

// pipeline.run_streamed(source, mesh); throws Io_error (unreadable input) when `input`, the file
// of `source`, has no faces left once its equal points are joined.
cgal_policies::Simplification_report run_out_of_core(const Pipeline& pipeline,
                                                     const Streamed_mesh_file& source,
                                                     const std::string& input, Mesh& mesh);

// pipeline.cut_streamed(source, folder): a partitioned job's cut of a file read in passes, for the
// job's tasks in `folder`; the number of parts. Throws Io_error as run_out_of_core does.
std::size_t cut_out_of_core(const Pipeline& pipeline, const Streamed_mesh_file& source,
                            const std::string& input, const std::filesystem::path& folder);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H
