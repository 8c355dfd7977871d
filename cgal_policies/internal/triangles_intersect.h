// Whether two faces of a mesh intersect other than along what they share (a common corner or
// edge), with exact predicates, for the fitting pass's self-intersection guard (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
#define CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>

namespace cgal_policies {
namespace internal {

struct Indexed_triangle {
  std::array<std::uint32_t, 3> vertices;
  std::array<Eigen::Vector3d, 3> points;
};

// Whether the boxes of two point sets are apart along some axis: then, compared exactly, what they
// span cannot meet. Most faces the guard's grid pairs up are such, and this spares them the
// predicates.
template <std::size_t M, std::size_t N>
bool boxes_apart(const std::array<Eigen::Vector3d, M>& s, const std::array<Eigen::Vector3d, N>& t) {
  for (int axis = 0; axis < 3; ++axis) {
    const auto below = [axis](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return a[axis] < b[axis];
    };
    const auto [s_lo, s_hi] = std::minmax_element(s.begin(), s.end(), below);
    const auto [t_lo, t_hi] = std::minmax_element(t.begin(), t.end(), below);
    if ((*s_hi)[axis] < (*t_lo)[axis] || (*t_hi)[axis] < (*s_lo)[axis]) return true;
  }
  return false;
}

inline bool faces_intersect(const Indexed_triangle& s, const Indexed_triangle& t) {
  int shared = 0;
  std::array<int, 3> in_t = {-1, -1, -1};  // in_t[i]: where corner i of s is in t
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.vertices[i] == t.vertices[j]) {
        in_t[i] = j;
        ++shared;
      }
  if (shared == 3) return false;
  if (shared == 0 && boxes_apart(s.points, t.points)) return false;
  // With one common corner, the corner of each and the edge facing it in each.
  int corner_s = 0;
  while (shared == 1 && in_t[corner_s] == -1) ++corner_s;
  const int corner_t = shared == 1 ? in_t[corner_s] : 0;
  if (shared == 1) {
    const std::array<Eigen::Vector3d, 2> facing_s = {s.points[(corner_s + 1) % 3],
                                                     s.points[(corner_s + 2) % 3]};
    const std::array<Eigen::Vector3d, 2> facing_t = {t.points[(corner_t + 1) % 3],
                                                     t.points[(corner_t + 2) % 3]};
    if (boxes_apart(facing_s, t.points) && boxes_apart(facing_t, s.points)) return false;
  }
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::array<K::Point_3, 3> a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = point(s.points[k]);
    b[k] = point(t.points[k]);
  }
  // Degenerate faces have no orientation to test against; the guard keeps new faces proper.
  if (CGAL::collinear(a[0], a[1], a[2]) || CGAL::collinear(b[0], b[1], b[2])) return false;
  if (shared == 0)
    return CGAL::do_intersect(K::Triangle_3(a[0], a[1], a[2]), K::Triangle_3(b[0], b[1], b[2]));
  if (shared == 2) {  // a common edge: they meet elsewhere only folded flat onto each other
    int lone_s = 0;
    while (in_t[lone_s] != -1) ++lone_s;
    int lone_t = 0;
    while (lone_t == in_t[(lone_s + 1) % 3] || lone_t == in_t[(lone_s + 2) % 3]) ++lone_t;
    const K::Point_3& u = a[(lone_s + 1) % 3];
    const K::Point_3& w = a[(lone_s + 2) % 3];
    return CGAL::coplanar(u, w, a[lone_s], b[lone_t]) &&
           CGAL::coplanar_orientation(u, w, a[lone_s], b[lone_t]) == CGAL::POSITIVE;
  }
  // One common corner: they meet elsewhere when the edge facing it in one crosses the other.
  const K::Segment_3 facing_s(a[(corner_s + 1) % 3], a[(corner_s + 2) % 3]);
  const K::Segment_3 facing_t(b[(corner_t + 1) % 3], b[(corner_t + 2) % 3]);
  return CGAL::do_intersect(facing_s, K::Triangle_3(b[0], b[1], b[2])) ||
         CGAL::do_intersect(facing_t, K::Triangle_3(a[0], a[1], a[2]));
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLES_INTERSECT_H
