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
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::array<K::Point_3, 3> a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = point(s.points[k]);
    b[k] = point(t.points[k]);
  }
  // Boxes compare the coordinates exactly: what lies in boxes apart cannot meet. Most pairs the
  // guard's grid offers are such, and skip the predicates.
  const CGAL::Bbox_3 box_a = a[0].bbox() + a[1].bbox() + a[2].bbox();
  const CGAL::Bbox_3 box_b = b[0].bbox() + b[1].bbox() + b[2].bbox();
  if (shared == 3 || !CGAL::do_overlap(box_a, box_b)) return false;
  // Degenerate faces have no orientation to test against; the guard keeps new faces proper.
  const auto proper = [&] {
    return !CGAL::collinear(a[0], a[1], a[2]) && !CGAL::collinear(b[0], b[1], b[2]);
  };
  if (shared == 0)
    return proper() &&
           CGAL::do_intersect(K::Triangle_3(a[0], a[1], a[2]), K::Triangle_3(b[0], b[1], b[2]));
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
         ((s_near && CGAL::do_intersect(facing_s, K::Triangle_3(b[0], b[1], b[2]))) ||
          (t_near && CGAL::do_intersect(facing_t, K::Triangle_3(a[0], a[1], a[2]))));
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
