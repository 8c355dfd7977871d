// The module's reports: simplify --json's and mesh_error --json's objects as Python dicts, so that
// the module and the tools never disagree.
#ifndef CGAL_POLICIES_PYTHON_SIMPLIFY_REPORT_H
#define CGAL_POLICIES_PYTHON_SIMPLIFY_REPORT_H

#include "cli/Json_object.h"
#include "cli/simplify_request.h"

#include <cgal_policies/Simplification_report.h>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace cgal_policies {
namespace python {

namespace py = pybind11;

py::dict as_dict(const apps::Json_object& json);

// The object `simplify --json` prints for this run, without the files: `repairs` what reading the
// input repaired, `had_corner_values` whether the input had texture coordinates, normals or
// colours.
py::dict simplify_report(const apps::Pipeline_request& request, const Simplification_report& run,
                         const std::vector<std::string>& repairs, bool had_corner_values);

}  // namespace python
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_PYTHON_SIMPLIFY_REPORT_H
