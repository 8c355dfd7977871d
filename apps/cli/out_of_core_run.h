// The out-of-core run of `simplify --out-of-core` and of simplify_bench's out-of-core rows
// (docs/scale.md): what the pipeline's run_streamed allows, and the run on a file read in passes.
#ifndef CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H
#define CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H

#include "io/Streamed_mesh_file.h"
#include "pipeline/Pipeline.h"

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

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_OUT_OF_CORE_RUN_H
