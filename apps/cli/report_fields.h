// The evaluator's figures as fields of a JSON report (simplify --json, mesh_error --json), under
// the names docs/evaluation.md gives them.
#ifndef CGAL_POLICIES_APPS_CLI_REPORT_FIELDS_H
#define CGAL_POLICIES_APPS_CLI_REPORT_FIELDS_H

#include "Json_object.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/Simplification_report.h>

namespace apps {

void add_fields(Json_object& json, const Mesh_error& error);
void add_fields(Json_object& json, const Mesh_validity& validity);
// The fields that are there, none for an empty one.
void add_fields(Json_object& json, const Attribute_error& error);

// A run's report as simplify --json gives it (docs/cli.md), `policy` being options.policy's entry;
// the Python module's report is the same object.
void add_fields(Json_object& json, const cgal_policies::Simplification_report& run,
                const cgal_policies::Simplification_options& options, const Policy_entry& policy);

// The reports' word for a run's corner attributes: "carried" when the input had texture
// coordinates, normals or colours (every policy carries them through its collapses), "none" when
// it had none; std::logic_error when a policy dropped them.
const char* corner_attributes_word(bool input_had_them, bool carried);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_REPORT_FIELDS_H
