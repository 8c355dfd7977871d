#include "Python_job.h"

#include "simplify_report.h"

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

void Python_job::run_part(int stage, std::size_t c) const {
  py::gil_scoped_release released;
  apps::Pipeline(m_request.options).run_part(m_folder, stage, c);
}

bool Python_job::stitch(int stage) const {
  py::gil_scoped_release released;
  return apps::Pipeline(m_request.options).stitch(m_folder, stage);
}

std::pair<Python_mesh, py::dict> Python_job::result(const Python_mesh& input) const {
  Python_mesh output;
  Simplification_report run;
  {
    py::gil_scoped_release released;
    run = apps::Pipeline(m_request.options).result(m_folder, output.mesh);
  }
  output.references = input.references;
  output.repairs = input.repairs;
  const bool had_corner_values = Corner_attributes<io::Point>(input.mesh).any_corner_values();
  py::dict report = simplify_report(m_request, run, input.repairs, had_corner_values);
  return {std::move(output), std::move(report)};
}

}  // namespace python
}  // namespace cgal_policies
