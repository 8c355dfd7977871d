#include "simplify_report.h"

#include "cli/report_fields.h"

namespace cgal_policies {
namespace python {

py::dict as_dict(const apps::Json_object& json) {
  return py::module_::import("json").attr("loads")(json.str());
}

py::dict simplify_report(const apps::Pipeline_request& request, const Simplification_report& run,
                         const std::vector<std::string>& repairs, bool had_corner_values) {
  apps::Json_object report;
  report.add("policy", request.policy->name);
  apps::add_fields(report, run, request.options, *request.policy);
  report.add("repairs", repairs);
  report.add("attributes", apps::corner_attributes_word(had_corner_values, run.attributes_carried));
  return as_dict(report);
}

}  // namespace python
}  // namespace cgal_policies
