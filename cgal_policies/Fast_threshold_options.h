// Fast_threshold_options: the settings of Fast_threshold_simplifier (docs/fast.md).
//   aggressiveness        a in the threshold t_k = 1e-9 (k + 3)^a D^2 of pass k, > 0 (default 7;
//                         larger is faster and coarser)
//   lossless              only collapses of zero error, up to round-off (default false)
//   max_normal_angle_deg  largest turn of a surviving face normal, degrees in [0, 180] (default 90)
//   border_weight         weight of the border planes, >= 0 (default 100, as CGAL's
//                         Garland-Heckbert: a lower mean error than the other policies' 1000 on
//                         the shipped meshes with borders, docs/fast.md)
//   face_weighting        Face_weighting::area (default: the lower mean error on the shipped
//                         scans, docs/fast.md) or Face_weighting::unit, as in the papers; a
//                         lossless run gives the planes equal weights (plane_weighting)
#ifndef CGAL_POLICIES_FAST_THRESHOLD_OPTIONS_H
#define CGAL_POLICIES_FAST_THRESHOLD_OPTIONS_H

#include <cgal_policies/Face_weighting.h>

namespace cgal_policies {

struct Fast_threshold_options {
  double aggressiveness = 7;
  bool lossless = false;
  double max_normal_angle_deg = 90;
  double border_weight = 100;
  Face_weighting face_weighting = Face_weighting::area;
};

// The weighting of the planes in a run with `options`: a lossless run's threshold is a squared
// distance, which an error weighted by area is not.
inline Face_weighting plane_weighting(const Fast_threshold_options& options) {
  return options.lossless ? Face_weighting::unit : options.face_weighting;
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FAST_THRESHOLD_OPTIONS_H
