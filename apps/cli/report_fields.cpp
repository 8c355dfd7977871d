#include "report_fields.h"

#include <stdexcept>

namespace apps {

void add_fields(Json_object& json, const Mesh_error& e) {
  const double d = e.bbox_diagonal > 0 ? e.bbox_diagonal : 1;
  json.add("bbox_diagonal", e.bbox_diagonal);
  json.add("hausdorff", e.hausdorff);
  json.add("hausdorff_a_to_b", e.hausdorff_a_to_b);
  json.add("hausdorff_b_to_a", e.hausdorff_b_to_a);
  json.add("mean_a_to_b", e.mean_a_to_b);
  json.add("mean_b_to_a", e.mean_b_to_a);
  json.add("rms", e.rms);
  json.add("hausdorff_rel", e.hausdorff / d);
  json.add("hausdorff_a_to_b_rel", e.hausdorff_a_to_b / d);
  json.add("hausdorff_b_to_a_rel", e.hausdorff_b_to_a / d);
  json.add("mean_a_to_b_rel", e.mean_a_to_b / d);
  json.add("mean_b_to_a_rel", e.mean_b_to_a / d);
  json.add("rms_rel", e.rms / d);
  json.add("samples", e.samples);
}

void add_fields(Json_object& json, const Mesh_validity& v) {
  json.add("valid", v.valid);
  json.add("closed", v.closed);
  json.add("boundary_edges", v.boundary_edges);
  json.add("non_manifold_vertices", v.non_manifold_vertices);
  json.add("degenerate_faces", v.degenerate_faces);
  json.add("min_angle_deg", v.min_angle_deg);
  json.add("euler_characteristic", v.euler_characteristic);
}

void add_fields(Json_object& json, const Attribute_error& error) {
  for_each_field(error, [&json](const char* name, const auto& field) {
    if (field) json.add(name, *field);
  });
}

const char* corner_attributes_word(bool input_had_them, bool carried) {
  if (!input_had_them) return "none";
  if (!carried)
    throw std::logic_error("a policy of the pipeline did not carry the corner attributes");
  return "carried";
}

}  // namespace apps
