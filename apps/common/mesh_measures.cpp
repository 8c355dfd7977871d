#include "mesh_measures.h"

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/triangle_closest_point.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
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

// Runs body(i) for every i < n on every core. Each i belongs to one thread, so a body that writes
// slot i alone gives a result that does not depend on the schedule.
template <class Body>
void for_each_index_in_parallel(std::size_t n, const Body& body) {
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = (n + threads - 1) / threads;
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = t * chunk, end = std::min(n, begin + chunk);
    if (begin >= end) break;
    workers.emplace_back([&body, begin, end] {
      for (std::size_t i = begin; i < end; ++i) body(i);
    });
  }
  for (std::thread& w : workers) w.join();
}

// CGAL 5.5's kernel projects a point onto a triangle with two equal corners wrongly for some corner
// orders (fuzz/README.md). Such a triangle is the union of its edges, and is projected so here;
// every other triangle as CGAL does.
struct Distance_kernel : Kernel {
  struct Construct_projected_point_3 : Kernel::Construct_projected_point_3 {
    using Base = Kernel::Construct_projected_point_3;
    using Base::operator();
    Point operator()(const Kernel::Triangle_3& t, const Point& p) const {
      if (!t.is_degenerate()) return Base::operator()(t, p);
      Point nearest = t[0];
      double best = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 3; ++i) {
        const Point q = Base::operator()(Kernel::Segment_3(t[i], t[(i + 1) % 3]), p);
        const double d = CGAL::squared_distance(p, q);
        if (d < best) {
          best = d;
          nearest = q;
        }
      }
      return nearest;
    }
  };
  Construct_projected_point_3 construct_projected_point_3_object() const { return {}; }
};
using Distance_tree = CGAL::AABB_tree<
    CGAL::AABB_traits<Distance_kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

// Squared distances from points to the surface in the tree, computed on every core.
std::vector<double> squared_distances(const std::vector<Point>& points, const Distance_tree& tree) {
  std::vector<double> result(points.size());
  for_each_index_in_parallel(points.size(),
                             [&](std::size_t i) { result[i] = tree.squared_distance(points[i]); });
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

  Distance_tree tree(faces(to).first, faces(to).second, to);
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

std::vector<Face_sample> sample_face_points(const Mesh& mesh, std::size_t samples) {
  // The draws of CGAL 5.5's Random_points_in_triangle_mesh_3, which gave the points before the
  // faces were needed, in its order and arithmetic, so that every measure keeps its samples: a
  // face by area, then two numbers in [0, 1) for the point inside it. That generator drew from
  // CGAL's default generator, so that is the one seeded here.
  std::vector<Mesh::Face_index> ids;
  std::vector<double> cumulative_area;
  double area = 0;
  for (Mesh::Face_index f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    area += std::sqrt(Kernel::Compute_squared_area_3()(
        Kernel::Triangle_3(mesh.point(target(h, mesh)), mesh.point(target(next(h, mesh), mesh)),
                           mesh.point(source(h, mesh)))));
    ids.push_back(f);
    cumulative_area.push_back(area);
  }
  std::vector<Face_sample> result;
  if (!(area > 0)) return result;
  result.reserve(samples);
  CGAL::Random& random = CGAL::get_default_random();
  random = CGAL::Random(kSamplingSeed);
  for (std::size_t i = 0; i < samples; ++i) {
    const double at = random.get_double(0, area);
    const std::size_t k = std::min<std::size_t>(
        ids.size() - 1, std::upper_bound(cumulative_area.begin(), cumulative_area.end(), at) -
                            cumulative_area.begin());
    double a1 = random.get_double(0, 1), a2 = random.get_double(0, 1);
    if (a1 > a2) std::swap(a1, a2);
    const std::array<double, 3> w{a1, a2 - a1, 1.0 - a2};
    const auto h = halfedge(ids[k], mesh);
    const Point& p = mesh.point(target(h, mesh));
    const Point& q = mesh.point(target(next(h, mesh), mesh));
    const Point& r = mesh.point(source(h, mesh));
    result.push_back({ids[k], w,
                      Point(p.x() * w[0] + q.x() * w[1] + r.x() * w[2],
                            p.y() * w[0] + q.y() * w[1] + r.y() * w[2],
                            p.z() * w[0] + q.z() * w[1] + r.z() * w[2])});
  }
  return result;
}

std::vector<Point> sample_faces(const Mesh& mesh, std::size_t samples) {
  const std::vector<Face_sample> sampled = sample_face_points(mesh, samples);
  std::vector<Point> points;
  points.reserve(sampled.size());
  for (const Face_sample& s : sampled) points.push_back(s.point);
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
  const std::vector<Mesh::Face_index> b_faces(faces(b).begin(), faces(b).end());
  std::vector<char> flipped(b_faces.size(), 0);
  for_each_index_in_parallel(b_faces.size(), [&](std::size_t i) {
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
      kinds_a.normals == kinds_b.normals && kinds_a.colors == kinds_b.colors) {
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
  std::vector<double> uv_distance(points.size(), kNone), angle(points.size(), kNone),
      color_distances(points.size(), kNone);
  for_each_index_in_parallel(points.size(), [&](std::size_t i) {
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

void add_fields(Json_object& json, const Attribute_error& error) {
  for_each_field(error, [&json](const char* name, const auto& field) {
    if (field) json.add(name, *field);
  });
}

}  // namespace apps
