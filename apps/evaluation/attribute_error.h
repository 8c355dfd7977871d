// The error of a simplification's corner attributes against its input's: texture coordinates,
// normals, colours, seams and flipped texture triangles (docs/evaluation.md).
#ifndef CGAL_POLICIES_APPS_EVALUATION_ATTRIBUTE_ERROR_H
#define CGAL_POLICIES_APPS_EVALUATION_ATTRIBUTE_ERROR_H

#include "surface_error.h"

#include <cstddef>
#include <optional>

namespace apps {

// The error of B's corner attributes (cgal_policies/Corner_attributes.h) against A's, defined in
// docs/evaluation.md. A field is empty when A or B lacks what it compares.
struct Attribute_error {
  // |uv_A - uv_B| at the samples over the diagonal of A's texture-coordinate bounding box.
  std::optional<double> uv_mean_rel, uv_max_rel;
  // Angle between the interpolated normals at the samples, in degrees.
  std::optional<double> normal_angle_mean_deg, normal_angle_max_deg;
  // Euclidean distance between the interpolated colours (red, green, blue, alpha in [0, 1]).
  std::optional<double> color_mean, color_max;
  // Seam edges (Corner_attributes::is_seam_edge, borders included) and their connected
  // components.
  std::optional<std::size_t> seam_edges_a, seam_edges_b, seam_loops_a, seam_loops_b;
  // Faces of B whose texture triangle does not turn the way the A face nearest its centroid does.
  std::optional<std::size_t> flipped_uv_faces;
};

// Compares the corner attributes of `b` with those of `a` at `samples` face samples of `a` and
// their closest points on `b`, and counts seams and flipped texture triangles. Deterministic.
Attribute_error measure_attribute_error(const Mesh& a, const Mesh& b,
                                        std::size_t samples = kDefaultErrorSamples);

// Calls visit(name, field) for every field of `error`, each a std::optional, in the order of the
// JSON and of simplify_bench's CSV columns.
template <typename Visitor>
void for_each_field(const Attribute_error& error, Visitor&& visit) {
  visit("uv_mean_rel", error.uv_mean_rel);
  visit("uv_max_rel", error.uv_max_rel);
  visit("normal_angle_mean_deg", error.normal_angle_mean_deg);
  visit("normal_angle_max_deg", error.normal_angle_max_deg);
  visit("color_mean", error.color_mean);
  visit("color_max", error.color_max);
  visit("seam_edges_a", error.seam_edges_a);
  visit("seam_edges_b", error.seam_edges_b);
  visit("seam_loops_a", error.seam_loops_a);
  visit("seam_loops_b", error.seam_loops_b);
  visit("flipped_uv_faces", error.flipped_uv_faces);
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EVALUATION_ATTRIBUTE_ERROR_H
