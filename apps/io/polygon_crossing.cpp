#include "polygon_crossing.h"

#include <CGAL/Projection_traits_3.h>

#include <cstddef>

namespace cgal_policies {
namespace io {
namespace {

using Projection = CGAL::Projection_traits_3<Kernel>;

class Projected_segments {
 public:
  explicit Projected_segments(const Kernel::Vector_3& normal)
      : traits_(normal),
        orientation_(traits_.orientation_2_object()),
        compare_x_(traits_.compare_x_2_object()),
        compare_y_(traits_.compare_y_2_object()) {}

  // Whether p lies on the closed segment ab in the projection.
  bool on_segment(const Point& a, const Point& b, const Point& p) const {
    return orientation_(a, b, p) == CGAL::COLLINEAR && between(compare_x_, a, b, p) &&
           between(compare_y_, a, b, p);
  }

  // Whether the closed segments ab and cd share a point in the projection.
  bool meet(const Point& a, const Point& b, const Point& c, const Point& d) const {
    const CGAL::Orientation c_side = orientation_(a, b, c), d_side = orientation_(a, b, d);
    const CGAL::Orientation a_side = orientation_(c, d, a), b_side = orientation_(c, d, b);
    if (c_side != CGAL::COLLINEAR && d_side != CGAL::COLLINEAR && a_side != CGAL::COLLINEAR &&
        b_side != CGAL::COLLINEAR)
      return c_side != d_side && a_side != b_side;
    return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
  }

 private:
  template <class Compare>
  static bool between(const Compare& compare, const Point& a, const Point& b, const Point& p) {
    return int(compare(a, p)) * int(compare(p, b)) >= 0;
  }

  Projection traits_;
  Projection::Orientation_2 orientation_;
  Projection::Compare_x_2 compare_x_;
  Projection::Compare_y_2 compare_y_;
};

}  // namespace

bool polygon_crosses_itself(const std::vector<Point>& corners, const Kernel::Vector_3& normal) {
  const Projected_segments projected(normal);
  const std::size_t n = corners.size();
  const auto corner = [&](std::size_t i) -> const Point& { return corners[i % n]; };
  for (std::size_t i = 0; i < n; ++i) {
    // Edge i runs from corner i to corner i + 1. Its successor shares corner i + 1 and must not
    // turn back over it.
    const Point &a = corner(i), &b = corner(i + 1), &c = corner(i + 2);
    if (projected.on_segment(a, b, c) || projected.on_segment(b, c, a)) return true;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the closing edge is edge 0's other neighbour
      if (projected.meet(a, b, corner(j), corner(j + 1))) return true;
    }
  }
  return false;
}

}  // namespace io
}  // namespace cgal_policies
