#include "out_of_core_run.h"

#include "io/mesh_io.h"

namespace apps {

bool runs_out_of_core(const cgal_policies::Simplification_options& options) {
  return options.two_sided_bound() == 0 && options.merge_distance == 0 &&
         options.min_component <= 1 && !options.smoothing.bounded;
}

cgal_policies::Simplification_report run_out_of_core(const Pipeline& pipeline,
                                                     const Streamed_mesh_file& source,
                                                     const std::string& input, Mesh& mesh) {
  const cgal_policies::Simplification_report report = pipeline.run_streamed(source, mesh);
  // As the reader of whole files says of a file without faces.
  if (report.input_faces == 0)
    throw Io_error(Io_error::Kind::unreadable_input,
                   input + ": no faces (none, or none left once its equal points are joined)");
  return report;
}

}  // namespace apps
