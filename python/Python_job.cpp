#include "Python_job.h"

#include "simplify_report.h"

#include "cli/out_of_core_run.h"
#include "io/Streamed_mesh_file.h"
#include "pipeline/Pipeline.h"

namespace cgal_policies {
namespace python {
Python_job::Python_job(std::filesystem::path folder, apps::Pipeline_request request)
    : m_folder(std::move(folder)), m_request(std::move(request)) {}

std::size_t Python_job::cut(const Python_mesh& mesh) const {
  py::gil_scoped_release released;
  io::Mesh copy = mesh.mesh;
  return apps::Pipeline(m_request.options).cut(copy, m_folder);
}

std::size_t Python_job::cut_file(const std::filesystem::path& path) const {
  if (!apps::runs_out_of_core(m_request.options))
    throw py::value_error(
        "a mesh file is cut in passes, never held whole, which max_error, the hausdorff policy, "
        "merge_distance, min_component and smooth_bounded need");
  py::gil_scoped_release released;
  return apps::cut_out_of_core(apps::Pipeline(m_request.options),
                               io::Streamed_mesh_file(path.string()), path.string(), m_folder);
}

void Python_job::run_part(int stage, std::size_t c) const {
  py::gil_scoped_release released;
  apps::Pipeline(m_request.options).run_part(m_folder, stage, c);
}

bool Python_job::stitch(int stage) const {
  py::gil_scoped_release released;
  return apps::Pipeline(m_request.options).stitch(m_folder, stage);
}

std::pair<Python_mesh, py::dict> Python_job::result(const Python_mesh* input) const {
  Python_mesh output;
  Simplification_report run;
  {
    py::gil_scoped_release released;
    run = apps::Pipeline(m_request.options).result(m_folder, output.mesh);
  }
  bool had_corner_values = false;
  if (input) {
    output.references = input->references;
    output.repairs = input->repairs;
    had_corner_values = Corner_attributes<io::Point>(input->mesh).any_corner_values();
  }
  py::dict report = simplify_report(m_request, run, output.repairs, had_corner_values);
  return {std::move(output), std::move(report)};
}

}  // namespace python
}  // namespace cgal_policies
