// Quadric_options: the settings every quadric policy here shares (docs/quadric_core.md).
//   border_weight   W_b, weight of the plane through each border edge perpendicular to its face,
//                   >= 0 (default default_border_weight); times |e|^2 with area weights, to keep
//                   the units of a face quadric
//   face_weighting  Face_weighting::unit (default, as in the papers) or Face_weighting::area
// Usage:
//   cgal_policies::Quadric_options options;
//   options.face_weighting = cgal_policies::Face_weighting::area;
//   cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh, options);
#ifndef CGAL_POLICIES_QUADRIC_OPTIONS_H
#define CGAL_POLICIES_QUADRIC_OPTIONS_H

#include <cgal_policies/Face_weighting.h>

namespace cgal_policies {

// Large enough that a border leaves its line only when nothing else is left ([QEM-tutorial]).
constexpr double default_border_weight = 1000.0;

struct Quadric_options {
  double border_weight = default_border_weight;
  Face_weighting face_weighting = Face_weighting::unit;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_QUADRIC_OPTIONS_H
