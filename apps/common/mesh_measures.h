// Metro-style two-sided geometric error between two meshes (docs/evaluation.md), the error of their
// corner attributes, and the validity figures of one mesh, shared by mesh_error, simplify --measure
// and simplify_bench.
#ifndef CGAL_POLICIES_APPS_MESH_MEASURES_H
#define CGAL_POLICIES_APPS_MESH_MEASURES_H

#include "Json_object.h"
#include "Mesh_types.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace apps {

// Face samples per direction by default: doubling it moves the mean by well under 1%
// (tests/mesh_error_test.cpp checks it on the bunny).
constexpr std::size_t kDefaultErrorSamples = 200000;

struct Mesh_error {
  double bbox_diagonal = 0;  // of the first mesh, the reference
  double hausdorff = 0;      // max of both one-sided maxima
  double hausdorff_a_to_b = 0, hausdorff_b_to_a = 0;
  double mean_a_to_b = 0, mean_b_to_a = 0;
  double rms = 0;           // over the face samples of both directions
  std::size_t samples = 0;  // face samples per direction (vertices are sampled as well)
};

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

struct Mesh_validity {
  bool valid = false;   // a valid halfedge structure made of triangles only
  bool closed = false;  // no boundary edge
  std::size_t faces = 0, vertices = 0;
  std::size_t boundary_edges = 0, non_manifold_vertices = 0, degenerate_faces = 0;
  double min_angle_deg = 0;
  long euler_characteristic = 0;
};

// An AABB tree over a mesh's faces, for distance and closest-face queries.
using Face_tree =
    CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

double bbox_diagonal(const Mesh& mesh);

// A point on a face, with its barycentric weights at the face's corners halfedge(face), next and
// prev (the corner at target(h) is the halfedge h, as in cgal_policies/Corner_attributes.h).
struct Face_sample {
  Mesh::Face_index face;
  std::array<double, 3> weights;
  Point point;
};

// `samples` area-uniform random points on the faces of `mesh`, the same on every run; none on a
// mesh without area.
std::vector<Face_sample> sample_face_points(const Mesh& mesh, std::size_t samples);
// Their points alone.
std::vector<Point> sample_faces(const Mesh& mesh, std::size_t samples);

// Distances from samples of `a` (its vertices and `samples` area-uniform random points on its
// faces, fixed seed, plus a fine grid on the faces of the farthest samples) to `b`, and the other
// way round, through AABB trees. Deterministic.
Mesh_error measure_mesh_error(const Mesh& a, const Mesh& b,
                              std::size_t samples = kDefaultErrorSamples);

// Compares the corner attributes of `b` with those of `a` at `samples` face samples of `a` and
// their closest points on `b`, and counts seams and flipped texture triangles. Deterministic.
Attribute_error measure_attribute_error(const Mesh& a, const Mesh& b,
                                        std::size_t samples = kDefaultErrorSamples);

Mesh_validity check_mesh_validity(const Mesh& mesh);

void add_fields(Json_object& json, const Mesh_error& error);
void add_fields(Json_object& json, const Mesh_validity& validity);
// The fields that are there, none for an empty one.
void add_fields(Json_object& json, const Attribute_error& error);

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

#endif  // CGAL_POLICIES_APPS_MESH_MEASURES_H
