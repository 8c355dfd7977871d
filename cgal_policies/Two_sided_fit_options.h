// The parameters of Two_sided_fitter (docs/fitting.md); Two_sided_fitter.h lists their ranges.
#ifndef CGAL_POLICIES_TWO_SIDED_FIT_OPTIONS_H
#define CGAL_POLICIES_TWO_SIDED_FIT_OPTIONS_H

#include <cstddef>

namespace cgal_policies {

struct Two_sided_fit_options {
  int rounds = 4;                    // fit rounds, each followed by a flip round
  bool flips = true;                 // flip edges between the fits
  double trust_fraction = 0.3;       // a vertex moves at most this much of its mean edge per round
  double tangent_weight = 0.001;     // a match's distance across its direction counts this much
  bool target_mean = false;          // reweight toward the mean (L1) distance rather than the RMS
  double max_normal_angle_deg = 90;  // no face normal turns more than this during the pass
  std::size_t min_input_samples = 100000;  // the input is sampled at least this densely
  // > 0: bounded mode, a two-sided bound as a fraction of the input's diagonal
  double tolerance = 0;
  std::size_t threads = 1;  // cores that index and match, 0: all; the fit is the same for any
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_TWO_SIDED_FIT_OPTIONS_H
