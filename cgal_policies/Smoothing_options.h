// Smoothing_options: the smoothing pass of Simplification_pipeline (Laplacian_smoother, [Liu17]
// §2.4; docs/hausdorff.md).
//   iterations  passes, >= 0 (default 0: no smoothing)
//   rate        lambda in (0, 1] (default 0.5)
//   weights     uniform (default) or inverse_distance
//   method      laplacian (default) or taubin (lambda, then mu = -0.53)
//   bounded     skip the moves that would take the output farther from the input than the run's
//               two-sided bound (max_error, or the hausdorff policy's tolerance); needs one
#ifndef CGAL_POLICIES_SMOOTHING_OPTIONS_H
#define CGAL_POLICIES_SMOOTHING_OPTIONS_H

#include <cgal_policies/Laplacian_smoother.h>

namespace cgal_policies {

struct Smoothing_options {
  int iterations = 0;
  double rate = 0.5;
  Smoothing_weights weights = Smoothing_weights::uniform;
  Smoothing_method method = Smoothing_method::laplacian;
  bool bounded = false;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SMOOTHING_OPTIONS_H
