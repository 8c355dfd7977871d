#include "out_of_core_run.h"

#include "io/mesh_io.h"

namespace apps {
namespace {

// As the reader of whole files says of a file without faces.
Io_error no_faces(const std::string& input) {
  return Io_error(Io_error::Kind::unreadable_input,
                  input + ": no faces (none, or none left once its equal points are joined)");
}

}  // namespace

bool runs_out_of_core(const cgal_policies::Simplification_options& options) {
  return options.two_sided_bound() == 0 && options.merge_distance == 0 &&
         options.min_component <= 1 && !options.smoothing.bounded;
}

cgal_policies::Simplification_report run_out_of_core(const Pipeline& pipeline,
                                                     const Streamed_mesh_file& source,
                                                     const std::string& input, Mesh& mesh) {
  const cgal_policies::Simplification_report report = pipeline.run_streamed(source, mesh);
  if (report.input_faces == 0) throw no_faces(input);
  return report;
}

std::size_t cut_out_of_core(const Pipeline& pipeline, const Streamed_mesh_file& source,
                            const std::string& input, const std::filesystem::path& folder) {
  const std::size_t parts = pipeline.cut_streamed(source, folder);
  if (parts == 0) throw no_faces(input);
  return parts;
}

}  // namespace apps
