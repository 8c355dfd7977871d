// Simplification_pass: the passes of Simplification_pipeline, in the order it runs them; the
// report gives each one's seconds, the progress callback names the one running.
#ifndef CGAL_POLICIES_SIMPLIFICATION_PASS_H
#define CGAL_POLICIES_SIMPLIFICATION_PASS_H

#include <array>
#include <cstddef>

namespace cgal_policies {

enum class Simplification_pass {
  merge,           // Border_pair_contraction: stitch border pairs closer than merge_distance
  components,      // drop the components smaller than min_component
  simplification,  // the policy, with the corner attributes, the error bound and the time limit
  pieces,          // drop whole components when the policy stopped short of the target
  smoothing,       // Laplacian_smoother
  fit              // Two_sided_fitter
};

inline constexpr std::size_t simplification_pass_count = 6;

inline const char* to_string(Simplification_pass pass) {
  static constexpr std::array<const char*, simplification_pass_count> names = {
      "merge", "components", "simplification", "pieces", "smoothing", "fit"};
  return names[std::size_t(pass)];
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SIMPLIFICATION_PASS_H
