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

void add_fields(Json_object& report, const cgal_policies::Simplification_report& run,
                const cgal_policies::Simplification_options& options, const Policy_entry& policy) {
  using cgal_policies::Simplification_pass;
  const double seconds = run.seconds(Simplification_pass::simplification);
  report.add("input_faces", run.input_faces);
  report.add("input_vertices", run.input_vertices);
  report.add("target_faces", run.target_faces);
  report.add("output_faces", run.output_faces);
  report.add("output_vertices", run.output_vertices);
  report.add("seconds", seconds);
  report.add("total_seconds", run.total_seconds());  // every pass of the pipeline
  report.add("faces_removed_per_second",
             seconds > 0 ? (run.input_faces - run.output_faces) / seconds : 0.0);
  report.add("stop_reason", to_string(run.stop_reason));
  // Signed: dropping a last piece may overshoot the target.
  report.add("target_gap_faces",
             static_cast<long long>(run.output_faces) - static_cast<long long>(run.target_faces));
  report.add("time_limit_seconds", options.time_limit_seconds);
  report.add("min_component", options.min_component);
  report.add("dropped_components", run.dropped_before.components);
  report.add("dropped_component_faces", run.dropped_before.faces);
  report.add("drop_small_pieces", options.drop_small_pieces);
  report.add("vanished_components", run.dropped_after.components);
  report.add("vanished_faces", run.dropped_after.faces);
  report.add("max_error", options.max_error);
  report.add("prepass", options.prepass_factor);
  report.add("parts", run.parts);
  report.add("threads", options.threads);
  report.add("smooth_iterations", options.smoothing.iterations);
  report.add("smooth_refused_moves", run.smoothing_refused_moves);
  report.add("smooth_seconds", run.seconds(Simplification_pass::smoothing));
  report.add("fit", options.fit);
  if (run.fitted) {
    report.add("fit_seconds", run.seconds(Simplification_pass::fit));
    report.add("fit_rounds", run.fit.rounds);
    report.add("fit_moves", run.fit.moves);
    report.add("fit_refused_moves", run.fit.refused_moves);
    report.add("fit_flips", run.fit.flips);
    report.add("fit_refused_flips", run.fit.refused_flips);
  }
  report.add("merge_distance", options.merge_distance);
  report.add("merged_pairs", run.merged.merged_pairs);
  report.add("stitched_edges", run.merged.stitched_edges);
  report.add("refused_pairs", run.merged.refused_pairs);
  for (const auto& [reason, count] : run.merged.refused_by_reason)
    report.add("refused_pairs_" + reason, count);
  for (const Policy_option& o : policy.options) report.add("option_" + o.name, o.get(options));
}

const char* corner_attributes_word(bool input_had_them, bool carried) {
  if (!input_had_them) return "none";
  if (!carried)
    throw std::logic_error("a policy of the pipeline did not carry the corner attributes");
  return "carried";
}

}  // namespace apps
