// Whether two faces of a mesh intersect other than along what they share (a common corner or
// edge), with exact predicates, for the fitting pass's self-intersection guard (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
#define CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H

#include <CGAL/Bbox_3.h>
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
  int shared = 0;
  std::array<int, 3> in_t = {-1, -1, -1};  // in_t[i]: where corner i of s is in t
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.vertices[i] == t.vertices[j]) {
        in_t[i] = j;
        ++shared;
      }
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto triangle = [](const Indexed_triangle& f) {
    const auto point = [&](int k) {
      return K::Point_3(f.points[k].x(), f.points[k].y(), f.points[k].z());
    };
    return K::Triangle_3(point(0), point(1), point(2));
  };
  const K::Triangle_3 a = triangle(s), b = triangle(t);
  // Boxes compare the coordinates exactly: what lies in boxes apart cannot meet. Most pairs the
  // guard's grid offers are such, and skip the predicates.
  const CGAL::Bbox_3 box_a = a.bbox(), box_b = b.bbox();
  if (shared == 3 || !CGAL::do_overlap(box_a, box_b)) return false;
  // Degenerate faces have no orientation to test against; the guard keeps new faces proper.
  const auto proper = [&] { return !a.is_degenerate() && !b.is_degenerate(); };
  if (shared == 0) return proper() && CGAL::do_intersect(a, b);
  if (shared == 2) {  // a common edge: they meet elsewhere only folded flat onto each other
    int i = 0;
    while (in_t[i] != -1) ++i;
    int j = 0;
    while (j == in_t[(i + 1) % 3] || j == in_t[(i + 2) % 3]) ++j;
    const K::Point_3& u = a[(i + 1) % 3];
    const K::Point_3& w = a[(i + 2) % 3];
    return proper() && CGAL::coplanar(u, w, a[i], b[j]) &&
           CGAL::coplanar_orientation(u, w, a[i], b[j]) == CGAL::POSITIVE;
  }
  // One common corner: they meet elsewhere when the edge facing it in one crosses the other.
  int i = 0;
  while (in_t[i] == -1) ++i;
  const int j = in_t[i];
  const K::Segment_3 facing_s(a[(i + 1) % 3], a[(i + 2) % 3]);
  const K::Segment_3 facing_t(b[(j + 1) % 3], b[(j + 2) % 3]);
  const bool s_near = CGAL::do_overlap(facing_s.bbox(), box_b);
  const bool t_near = CGAL::do_overlap(facing_t.bbox(), box_a);
  return (s_near || t_near) && proper() &&
         ((s_near && CGAL::do_intersect(facing_s, b)) ||
          (t_near && CGAL::do_intersect(facing_t, a)));
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
