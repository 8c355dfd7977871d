#include "attribute_error.h"

#include "surface_error.h"

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/triangle_closest_point.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace apps {
namespace {

using Attributes = cgal_policies::Corner_attributes<Point>;
using Vector = Kernel::Vector_3;
constexpr double kNone = Attributes::kNone;

// A face's corners in the order of Face_sample::weights.
std::array<Mesh::Halfedge_index, 3> corners_of(Mesh::Face_index f, const Mesh& mesh) {
  const auto h = halfedge(f, mesh);
  return {h, next(h, mesh), prev(h, mesh)};
}

// The weights of the point of face f closest to p.
std::array<double, 3> closest_weights(const Point& p, Mesh::Face_index f, const Mesh& mesh) {
  const auto eigen = [&](Mesh::Halfedge_index h) {
    const Point& q = mesh.point(target(h, mesh));
    return Eigen::Vector3d(q.x(), q.y(), q.z());
  };
  const auto c = corners_of(f, mesh);
  const Eigen::Vector3d w = cgal_policies::internal::closest_barycentric(
      Eigen::Vector3d(p.x(), p.y(), p.z()), eigen(c[0]), eigen(c[1]), eigen(c[2]));
  return {w[0], w[1], w[2]};
}

Attributes::Values interpolated(const Attributes& attributes,
                                const std::array<Mesh::Halfedge_index, 3>& c,
                                const std::array<double, 3>& w) {
  return Attributes::blend(
      {attributes.values(c[0]), attributes.values(c[1]), attributes.values(c[2])}, w);
}

// In degrees; NaN where either normal is missing or the corners' normals cancel out.
double angle_between(const Vector& m, const Vector& n) {
  if (!(m.squared_length() > 0) || !(n.squared_length() > 0)) return kNone;
  // atan2 rather than acos: exact at 0 and accurate near it.
  return std::atan2(std::sqrt(CGAL::cross_product(m, n).squared_length()), m * n) * 180.0 / M_PI;
}

double color_distance(const Attributes::Color& p, const Attributes::Color& q) {
  double sum = 0;
  for (int d = 0; d < 4; ++d) sum += (p[d] - q[d]) * (p[d] - q[d]);
  return std::sqrt(sum);
}

// The mean and the maximum of the finite values, none when there is none.
void summarise(const std::vector<double>& values, std::optional<double>& mean,
               std::optional<double>& maximum) {
  double sum = 0, largest = 0;
  std::size_t count = 0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    sum += v;
    largest = std::max(largest, v);
    ++count;
  }
  if (count == 0) return;
  mean = sum / double(count);
  maximum = largest;
}

struct Seams {
  std::size_t edges = 0, loops = 0;
};

// Seam edges by the carrier's own rule, and their connected components.
Seams count_seams(const Mesh& mesh) {
  const Attributes attributes(mesh);
  std::vector<std::size_t> parent(mesh.num_vertices());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<bool> on_seam(parent.size(), false);
  Seams seams;
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    if (!attributes.is_seam_edge(mesh, h)) continue;
    ++seams.edges;
    const std::size_t s = source(h, mesh), t = target(h, mesh);
    on_seam[s] = on_seam[t] = true;
    parent[root(s)] = root(t);
  }
  for (std::size_t v = 0; v < parent.size(); ++v) seams.loops += on_seam[v] && root(v) == v;
  return seams;
}

int sign(double x) { return (x > 0) - (x < 0); }

// B's faces whose texture triangle does not turn the way that of the A face nearest the B face's
// centroid does (a flat B triangle against a turning A one counts; a flat A one, or a corner
// without a value, is not judged).
std::size_t flipped_uv_faces(const Mesh& a, const Attributes& in_a, const Mesh& b,
                             const Attributes& in_b) {
  Face_tree tree(faces(a).first, faces(a).second, a);
  tree.accelerate_distance_queries();
  tree.build();  // before the threads query it (surface_error.cpp says why)
  const std::vector<Mesh::Face_index> b_faces(faces(b).begin(), faces(b).end());
  std::vector<char> flipped(b_faces.size(), 0);
  cgal_policies::internal::for_each_in_parallel(b_faces.size(), 0, [&](std::size_t i) {
    const auto c = corners_of(b_faces[i], b);
    const Point centroid = CGAL::centroid(b.point(target(c[0], b)), b.point(target(c[1], b)),
                                          b.point(target(c[2], b)));
    const double area_a = in_a.face_uv_area(a, tree.closest_point_and_primitive(centroid).second);
    const double area_b = in_b.face_uv_area(b, b_faces[i]);
    if (!std::isfinite(area_a) || !std::isfinite(area_b) || area_a == 0) return;
    flipped[i] = sign(area_b) != sign(area_a);
  });
  return std::size_t(std::count(flipped.begin(), flipped.end(), 1));
}

}  // namespace

Attribute_error measure_attribute_error(const Mesh& a, const Mesh& b, std::size_t samples) {
  const Attributes in_a(a), in_b(b);
  Attribute_error error;
  // Seams are judged on every corner value a mesh has, so they compare only like with like.
  const auto kinds_a = in_a.kinds(), kinds_b = in_b.kinds();
  if (in_a.any_corner_values() && kinds_a.uvs == kinds_b.uvs &&
      kinds_a.normals == kinds_b.normals && kinds_a.colors == kinds_b.colors &&
      kinds_a.second_uvs == kinds_b.second_uvs && kinds_a.skins == kinds_b.skins) {
    const Seams seams_a = count_seams(a), seams_b = count_seams(b);
    error.seam_edges_a = seams_a.edges;
    error.seam_edges_b = seams_b.edges;
    error.seam_loops_a = seams_a.loops;
    error.seam_loops_b = seams_b.loops;
  }
  const double extent = in_a.uv_extent(a);
  const bool uvs = in_a.uvs && in_b.uvs && extent > 0, normals = in_a.normals && in_b.normals,
             colors = in_a.colors && in_b.colors;
  if (uvs) error.flipped_uv_faces = flipped_uv_faces(a, in_a, b, in_b);
  if (!uvs && !normals && !colors) return error;

  // At each sample of A and the closest point of B: each side's interpolated value. A closest
  // point on a seam of B takes the values of the face the tree gives, whichever chart it is in.
  const std::vector<Face_sample> points = sample_face_points(a, samples);
  Face_tree tree(faces(b).first, faces(b).second, b);
  tree.accelerate_distance_queries();
  tree.build();  // before the threads query it (surface_error.cpp says why)
  std::vector<double> uv_distance(points.size(), kNone), angle(points.size(), kNone),
      color_distances(points.size(), kNone);
  cgal_policies::internal::for_each_in_parallel(points.size(), 0, [&](std::size_t i) {
    const Face_sample& s = points[i];
    const Mesh::Face_index f = tree.closest_point_and_primitive(s.point).second;
    const auto corners_a = corners_of(s.face, a), corners_b = corners_of(f, b);
    const std::array<double, 3> weights_b = closest_weights(s.point, f, b);
    const Attributes::Values p = interpolated(in_a, corners_a, s.weights),
                             q = interpolated(in_b, corners_b, weights_b);
    if (uvs) uv_distance[i] = std::hypot(p.uv[0] - q.uv[0], p.uv[1] - q.uv[1]) / extent;
    if (normals) angle[i] = angle_between(p.normal, q.normal);
    if (colors) color_distances[i] = color_distance(p.color, q.color);
  });
  if (uvs) summarise(uv_distance, error.uv_mean_rel, error.uv_max_rel);
  if (normals) summarise(angle, error.normal_angle_mean_deg, error.normal_angle_max_deg);
  if (colors) summarise(color_distances, error.color_mean, error.color_max);
  return error;
}

}  // namespace apps
