// Whether two faces of a mesh intersect other than along what they share (a common corner or
// edge), with exact predicates, for the fitting pass's self-intersection guard (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
#define CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace cgal_policies {
namespace internal {

struct Indexed_triangle {
  std::array<std::uint32_t, 3> vertices;
  std::array<Eigen::Vector3d, 3> points;
};

inline bool faces_intersect(const Indexed_triangle& s, const Indexed_triangle& t) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::array<K::Point_3, 3> a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = point(s.points[k]);
    b[k] = point(t.points[k]);
  }
  // Degenerate faces have no orientation to test against; the guard keeps new faces proper.
  if (CGAL::collinear(a[0], a[1], a[2]) || CGAL::collinear(b[0], b[1], b[2])) return false;
  int shared = 0;
  std::array<int, 3> in_t = {-1, -1, -1};  // in_t[i]: where corner i of s is in t
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.vertices[i] == t.vertices[j]) {
        in_t[i] = j;
        ++shared;
      }
  if (shared == 0)
    return CGAL::do_intersect(K::Triangle_3(a[0], a[1], a[2]), K::Triangle_3(b[0], b[1], b[2]));
  if (shared == 3) return false;
  if (shared == 2) {  // a common edge: they meet elsewhere only folded flat onto each other
    int i = 0;
    while (in_t[i] != -1) ++i;
    int j = 0;
    while (j == in_t[(i + 1) % 3] || j == in_t[(i + 2) % 3]) ++j;
    const K::Point_3& u = a[(i + 1) % 3];
    const K::Point_3& w = a[(i + 2) % 3];
    return CGAL::coplanar(u, w, a[i], b[j]) &&
           CGAL::coplanar_orientation(u, w, a[i], b[j]) == CGAL::POSITIVE;
  }
  // One common corner: they meet elsewhere when the edge facing it in one crosses the other.
  int i = 0;
  while (in_t[i] == -1) ++i;
  const int j = in_t[i];
  const K::Segment_3 opposite_s(a[(i + 1) % 3], a[(i + 2) % 3]);
  const K::Segment_3 opposite_t(b[(j + 1) % 3], b[(j + 2) % 3]);
  return CGAL::do_intersect(opposite_s, K::Triangle_3(b[0], b[1], b[2])) ||
         CGAL::do_intersect(opposite_t, K::Triangle_3(a[0], a[1], a[2]));
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
