// Metro-style two-sided geometric error between two meshes (docs/evaluation.md), shared by
// mesh_error, simplify --measure and simplify_bench, and the face samples the other measures use.
#ifndef CGAL_POLICIES_APPS_EVALUATION_SURFACE_ERROR_H
#define CGAL_POLICIES_APPS_EVALUATION_SURFACE_ERROR_H

#include "app_types.h"

#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>

#include <array>
#include <cstddef>
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

  // The mean distance of the two directions, the figure the tests and the bench compare.
  double mean() const { return (mean_a_to_b + mean_b_to_a) / 2; }
};

// An AABB tree over a mesh's faces, for distance and closest-face queries.
using Face_tree = CGAL::AABB_tree<
    cgal_policies::internal::Aabb_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

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

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EVALUATION_SURFACE_ERROR_H
