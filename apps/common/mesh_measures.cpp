#include "mesh_measures.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/point_generators_3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <set>
#include <thread>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace apps {
namespace {

constexpr unsigned kSamplingSeed = 20260101;

struct One_sided {
  double max = 0;
  double mean = 0;
  double sum_of_squares = 0;  // over the face samples
};

// Squared distances from points to the surface in the tree, computed on every core; each slot is
// written by one thread, so the result does not depend on the schedule.
std::vector<double> squared_distances(const std::vector<Point>& points, const Face_tree& tree) {
  std::vector<double> result(points.size());
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = (points.size() + threads - 1) / threads;
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = t * chunk, end = std::min(points.size(), begin + chunk);
    if (begin >= end) break;
    workers.emplace_back([&, begin, end] {
      for (std::size_t i = begin; i < end; ++i) result[i] = tree.squared_distance(points[i]);
    });
  }
  for (std::thread& w : workers) w.join();
  return result;
}

// Random samples can only fall short of the maximum distance, most where faces are large: the
// faces that hold the farthest samples are sampled again on a fine barycentric grid, farthest
// first, with no more grid points than random samples (so a small sample count stays cheap).
std::vector<Point> dense_samples_near_the_worst(const Mesh& from, const std::vector<Point>& points,
                                                const std::vector<double>& d2, std::size_t budget) {
  constexpr std::size_t kWorstSamples = 256;
  constexpr int kGridSteps = 24;
  constexpr std::size_t kGridPoints = (kGridSteps + 1) * (kGridSteps + 2) / 2;
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const std::size_t worst = std::min(kWorstSamples, order.size());
  std::partial_sort(
      order.begin(), order.begin() + worst, order.end(),
      [&](std::size_t i, std::size_t j) { return d2[i] > d2[j] || (d2[i] == d2[j] && i < j); });
  Face_tree from_tree(faces(from).first, faces(from).second, from);
  const std::size_t max_faces = std::max<std::size_t>(1, budget / kGridPoints);
  std::set<Mesh::Face_index> seen;
  std::vector<Point> dense;
  for (std::size_t k = 0; k < worst && seen.size() < max_faces; ++k) {
    const Mesh::Face_index f = from_tree.closest_point_and_primitive(points[order[k]]).second;
    if (!seen.insert(f).second) continue;
    const auto h = halfedge(f, from);
    const Point& a = from.point(source(h, from));
    const Point& b = from.point(target(h, from));
    const Point& c = from.point(target(next(h, from), from));
    for (int i = 0; i <= kGridSteps; ++i)
      for (int j = 0; i + j <= kGridSteps; ++j)
        dense.push_back(a + (double(i) / kGridSteps) * (b - a) +
                        (double(j) / kGridSteps) * (c - a));
  }
  return dense;
}

One_sided one_sided_distance(const Mesh& from, const Mesh& to, std::size_t samples) {
  std::vector<Point> points = sample_faces(from, samples);
  points.reserve(samples + from.number_of_vertices());
  const std::size_t face_samples = points.size();
  for (auto v : vertices(from)) points.push_back(from.point(v));

  Face_tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  const std::vector<double> d2 = squared_distances(points, tree);

  One_sided result;
  double sum = 0;
  for (std::size_t i = 0; i < d2.size(); ++i) {
    result.max = std::max(result.max, d2[i]);
    if (i < face_samples) {
      sum += std::sqrt(d2[i]);
      result.sum_of_squares += d2[i];
    }
  }
  const std::vector<Point> dense = dense_samples_near_the_worst(from, points, d2, samples);
  for (double refined : squared_distances(dense, tree)) result.max = std::max(result.max, refined);
  result.max = std::sqrt(result.max);
  result.mean = face_samples ? sum / double(face_samples) : 0;
  return result;
}

double corner_angle_deg(const Point& a, const Point& b, const Point& c) {
  const Kernel::Vector_3 u = b - a, v = c - a;
  const double lengths = std::sqrt(u.squared_length() * v.squared_length());
  if (!(lengths > 0)) return 0;
  return std::acos(std::clamp(u * v / lengths, -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

std::vector<Point> sample_faces(const Mesh& mesh, std::size_t samples) {
  // CGAL 5.5's triangle-mesh point generator (behind sample_triangle_mesh) picks a face with the
  // generator it is given but the point inside the face with CGAL's default generator, so that is
  // the one seeded here.
  std::vector<Point> points;
  points.reserve(samples);
  CGAL::Random& random = CGAL::get_default_random();
  random = CGAL::Random(kSamplingSeed);
  std::copy_n(CGAL::Random_points_in_triangle_mesh_3<Mesh>(mesh, random), samples,
              std::back_inserter(points));
  return points;
}

double bbox_diagonal(const Mesh& mesh) {
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

Mesh_error measure_mesh_error(const Mesh& a, const Mesh& b, std::size_t samples) {
  const One_sided ab = one_sided_distance(a, b, samples);
  const One_sided ba = one_sided_distance(b, a, samples);
  Mesh_error error;
  error.bbox_diagonal = bbox_diagonal(a);
  error.hausdorff_a_to_b = ab.max;
  error.hausdorff_b_to_a = ba.max;
  error.hausdorff = std::max(ab.max, ba.max);
  error.mean_a_to_b = ab.mean;
  error.mean_b_to_a = ba.mean;
  error.rms =
      samples ? std::sqrt((ab.sum_of_squares + ba.sum_of_squares) / double(2 * samples)) : 0;
  error.samples = samples;
  return error;
}

Mesh_validity check_mesh_validity(const Mesh& mesh) {
  Mesh_validity v;
  v.valid = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh);
  v.closed = CGAL::is_closed(mesh);
  v.faces = mesh.number_of_faces();
  v.vertices = mesh.number_of_vertices();
  for (auto e : edges(mesh)) v.boundary_edges += CGAL::is_border(e, mesh);
  std::vector<Mesh::Halfedge_index> pinched;
  PMP::non_manifold_vertices(mesh, std::back_inserter(pinched));
  std::vector<Mesh::Vertex_index> pinched_vertices;
  for (auto h : pinched) pinched_vertices.push_back(target(h, mesh));
  std::sort(pinched_vertices.begin(), pinched_vertices.end());
  v.non_manifold_vertices = std::size_t(
      std::unique(pinched_vertices.begin(), pinched_vertices.end()) - pinched_vertices.begin());
  v.min_angle_deg = 180;
  for (auto f : faces(mesh)) {
    if (!v.valid) break;  // corners are only defined on triangles
    v.degenerate_faces += PMP::is_degenerate_triangle_face(f, mesh);
    const auto h = halfedge(f, mesh);
    const Point& p = mesh.point(source(h, mesh));
    const Point& q = mesh.point(target(h, mesh));
    const Point& r = mesh.point(target(next(h, mesh), mesh));
    v.min_angle_deg = std::min({v.min_angle_deg, corner_angle_deg(p, q, r),
                                corner_angle_deg(q, r, p), corner_angle_deg(r, p, q)});
  }
  v.euler_characteristic =
      long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
  return v;
}

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

}  // namespace apps
