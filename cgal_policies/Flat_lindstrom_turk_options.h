// Flat_lindstrom_turk_options: the settings of Flat_lindstrom_turk_simplifier (docs/flat_lt.md).
//   volume_weight, boundary_weight, shape_weight   [LT98]'s weights of the volume, border and
//                         shape costs, >= 0 (defaults 0.5, 0.5 and 0, CGAL's LindstromTurk's)
//   max_normal_angle_deg  largest turn of a surviving face normal, degrees in [0, 180] (default 90)
#ifndef CGAL_POLICIES_FLAT_LINDSTROM_TURK_OPTIONS_H
#define CGAL_POLICIES_FLAT_LINDSTROM_TURK_OPTIONS_H

namespace cgal_policies {

struct Flat_lindstrom_turk_options {
  double volume_weight = 0.5;
  double boundary_weight = 0.5;
  double shape_weight = 0;
  double max_normal_angle_deg = 90;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FLAT_LINDSTROM_TURK_OPTIONS_H
