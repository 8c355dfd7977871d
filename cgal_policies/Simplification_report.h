// Simplification_report: what Simplification_pipeline did to a mesh: why it stopped, the counts
// before and after, each pass's own report and its seconds.
#ifndef CGAL_POLICIES_SIMPLIFICATION_REPORT_H
#define CGAL_POLICIES_SIMPLIFICATION_REPORT_H

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Simplification_pass.h>
#include <cgal_policies/Stop_reason.h>
#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/small_components.h>

#include <array>
#include <cstddef>
#include <numeric>

namespace cgal_policies {

struct Simplification_report {
  Stop_reason stop_reason = Stop_reason::no_collapse_left;  // of the simplification pass
  std::size_t input_faces = 0, input_vertices = 0;
  std::size_t target_faces = 0;
  std::size_t output_faces = 0, output_vertices = 0;
  double bound = 0;       // the two-sided bound the run kept (Simplification_options), 0: none
  std::size_t parts = 1;  // the cells of a partitioned run; 1: it ran whole
  Border_pair_contraction_report merged;
  Dropped_components dropped_before;  // min_component
  Dropped_components dropped_after;   // drop_small_pieces
  std::size_t smoothing_refused_moves = 0;
  bool fitted = false;
  Two_sided_fit_report fit;
  // The mesh had texture coordinates, normals or colours, and the policy carried them through its
  // collapses with their seams (every policy does).
  bool attributes_carried = false;
  std::array<double, simplification_pass_count> pass_seconds{};

  double seconds(Simplification_pass pass) const { return pass_seconds[std::size_t(pass)]; }
  double total_seconds() const {
    return std::accumulate(pass_seconds.begin(), pass_seconds.end(), 0.0);
  }
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SIMPLIFICATION_REPORT_H
