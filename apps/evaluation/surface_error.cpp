#include "surface_error.h"

#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/triangle_closest_point.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
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
using Distance_tree = CGAL::AABB_tree<cgal_policies::internal::Aabb_traits<
    Distance_kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

// Squared distances from points to the surface in the tree, computed on every core.
std::vector<double> squared_distances(const std::vector<Point>& points, const Distance_tree& tree) {
  std::vector<double> result(points.size());
  cgal_policies::internal::for_each_in_parallel(
      points.size(), 0, [&](std::size_t i) { result[i] = tree.squared_distance(points[i]); });
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
  // Built here, not lazily by the first query: CGAL 5.5 sorts the primitives while it builds,
  // and another thread's query reads them meanwhile (ThreadSanitizer caught it).
  tree.build();
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

}  // namespace apps
