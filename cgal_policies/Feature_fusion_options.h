// Feature_fusion_options: the settings of Feature_fusion_policies (docs/fusion.md, which says how
// the defaults were chosen), on top of Quadric_options.
//   mu             weight of the normal variation, per radian, >= 0 (default 2)
//   visual_weight  w_v, weight of the visual term, >= 0 (default 0: off)
#ifndef CGAL_POLICIES_FEATURE_FUSION_OPTIONS_H
#define CGAL_POLICIES_FEATURE_FUSION_OPTIONS_H

#include <cgal_policies/Quadric_options.h>

namespace cgal_policies {

struct Feature_fusion_options : Quadric_options {
  double mu = 2.0;
  double visual_weight = 0.0;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FEATURE_FUSION_OPTIONS_H
