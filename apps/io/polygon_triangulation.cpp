#include "polygon_triangulation.h"

#include "polygon_crossing.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace cgal_policies {
namespace io {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Triangle = std::array<std::size_t, 3>;
using Vector = Kernel::Vector_3;

double smallest_angle(const Point& a, const Point& b, const Point& c) {
  const auto angle = [](const Vector& u, const Vector& v) {
    return std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
  };
  return std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
}

// A quad's two triangles along the diagonal from corner `first` (0 or 1) to the one opposite.
std::array<Triangle, 2> quad_split(std::size_t first) {
  return {Triangle{first, first + 1, (first + 2) % 4},
          Triangle{first, (first + 2) % 4, (first + 3) % 4}};
}

// Whether the split's triangles face the same way, then its smallest angle: a twisted quad has
// one diagonal that folds it and one that does not.
std::pair<bool, double> split_quality(const std::vector<Point>& quad,
                                      const std::array<Triangle, 2>& split) {
  const auto normal = [&](const Triangle& t) {
    return CGAL::cross_product(quad[t[1]] - quad[t[0]], quad[t[2]] - quad[t[0]]);
  };
  const auto angle = [&](const Triangle& t) {
    return smallest_angle(quad[t[0]], quad[t[1]], quad[t[2]]);
  };
  return {normal(split[0]) * normal(split[1]) > 0, std::min(angle(split[0]), angle(split[1]))};
}

// CGAL's triangulation of the polygon when it is simple seen along its normal; empty otherwise.
std::vector<Triangle> simple_polygon_triangles(const std::vector<Point>& corners) {
  Mesh polygon;
  std::vector<Mesh::Vertex_index> vertices;
  for (const Point& p : corners) vertices.push_back(polygon.add_vertex(p));
  const Mesh::Face_index face = polygon.add_face(vertices);
  if (face == Mesh::null_face()) return {};
  const Vector normal = PMP::compute_face_normal(face, polygon);
  if (normal == CGAL::NULL_VECTOR || polygon_crosses_itself(corners, normal)) return {};
  if (!PMP::triangulate_face(face, polygon)) return {};
  std::vector<Triangle> triangles;
  for (const auto f : polygon.faces()) {
    Triangle t{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(polygon.halfedge(f), polygon))
      t[k++] = std::size_t(v);
    triangles.push_back(t);
  }
  return triangles;
}

// The boundary triangulation takes cubic time where its Delaunay shortcut fails: about 3 seconds
// for 800 random corners, 0.1 for 200. Larger polygons that cross themselves get a fan.
constexpr std::size_t kMaxBoundaryCorners = 500;

// The least-area triangulation of the polygon's boundary in 3D. Every triangle of a polygon's
// triangulation, its corners in increasing order, turns the polygon's way.
std::vector<Triangle> boundary_triangles(const std::vector<Point>& corners) {
  std::vector<CGAL::Triple<int, int, int>> patch;
  PMP::triangulate_hole_polyline(corners, std::back_inserter(patch));
  std::vector<Triangle> triangles;
  for (const auto& t : patch) {
    Triangle sorted{std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)};
    std::sort(sorted.begin(), sorted.end());
    triangles.push_back(sorted);
  }
  return triangles;
}

}  // namespace

std::vector<Triangle> polygon_triangles(const std::vector<Point>& corners) {
  const std::size_t n = corners.size();
  if (n == 3) return {Triangle{0, 1, 2}};
  if (n == 4) {
    const std::array<Triangle, 2> first = quad_split(0), second = quad_split(1);
    const auto& better =
        split_quality(corners, second) > split_quality(corners, first) ? second : first;
    return {better[0], better[1]};
  }
  std::vector<Triangle> triangles = simple_polygon_triangles(corners);
  if (triangles.size() != n - 2 && n <= kMaxBoundaryCorners)
    triangles = boundary_triangles(corners);
  if (triangles.size() != n - 2) {
    triangles.clear();
    for (std::size_t i = 1; i + 1 < n; ++i) triangles.push_back({0, i, i + 1});
  }
  return triangles;
}

}  // namespace io
}  // namespace cgal_policies
