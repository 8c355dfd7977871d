// Curvature_weighted_options: the settings of Curvature_weighted_quadric_policies
// (docs/curvature.md), on top of Quadric_options.
//   eps      floor of the curvature factor f = eps + 1 - (K_s + K_t) / 2; dimensionless, >= 0
//            (default 1e-3); ignored when literal is set
//   literal  eq. 12 of [Zhang09] as printed: eps = 0, f scales the border planes (default false)
#ifndef CGAL_POLICIES_CURVATURE_WEIGHTED_OPTIONS_H
#define CGAL_POLICIES_CURVATURE_WEIGHTED_OPTIONS_H

#include <cgal_policies/Quadric_options.h>

namespace cgal_policies {

struct Curvature_weighted_options : Quadric_options {
  double eps = 1e-3;
  bool literal = false;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CURVATURE_WEIGHTED_OPTIONS_H
