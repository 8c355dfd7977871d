// Quadric_options: the settings every quadric policy of this library shares (docs/quadric_core.md).
//
//   border_weight   W_b, the weight of the plane through each border edge perpendicular to its
//                   face (>= 0; default default_border_weight). With area weights it is multiplied
//                   by the squared edge length, so that it keeps the units of a face quadric.
//   face_weighting  Face_weighting::unit (default, as in the papers) or Face_weighting::area.
//
// Usage:
//   cgal_policies::Quadric_options options;
//   options.face_weighting = cgal_policies::Face_weighting::area;
//   cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh, options);
#ifndef CGAL_POLICIES_QUADRIC_OPTIONS_H
#define CGAL_POLICIES_QUADRIC_OPTIONS_H

#include <cgal_policies/Face_weighting.h>

namespace cgal_policies {

// The border weight of every policy here: large enough that a border moves off its line only when
// nothing else is left, as in the QEM tutorial.
constexpr double default_border_weight = 1000.0;

struct Quadric_options {
  double border_weight = default_border_weight;
  Face_weighting face_weighting = Face_weighting::unit;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_QUADRIC_OPTIONS_H
