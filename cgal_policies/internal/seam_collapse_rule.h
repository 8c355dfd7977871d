// The seam rules of a collapse (docs/attributes.md, "The rules of a collapse"), shared by
// Corner_attribute_carrier (on a CGAL::Surface_mesh) and Fast_threshold_engine (on flat arrays).
#ifndef CGAL_POLICIES_INTERNAL_SEAM_COLLAPSE_RULE_H
#define CGAL_POLICIES_INTERNAL_SEAM_COLLAPSE_RULE_H

#include <cstddef>

namespace cgal_policies {
namespace internal {

enum class Seam_placement { anywhere, at_first, at_second, nowhere };

// A seam corner, where seams meet or end: neither on no seam nor merely along one. The rule below
// never moves it.
inline bool is_seam_corner(std::size_t seam_edges) { return seam_edges != 0 && seam_edges != 2; }

// Where the collapse of an edge may put the kept vertex, given the seam edges at its first and
// second end: a free vertex goes to a seam vertex; two seam vertices merge only along a seam edge
// (is_seam_edge()), at the end that is not merely along the seam (the nearer one to the policy's
// point when both are, first_is_nearer()), and never when a triangle on the edge has its other two
// edges on seams too (closes_chart()): its chart would vanish. Two seam corners never merge.
template <class Is_seam_edge, class Closes_chart, class First_is_nearer>
Seam_placement seam_collapse_rule(std::size_t seams_first, std::size_t seams_second,
                                  const Is_seam_edge& is_seam_edge,
                                  const Closes_chart& closes_chart,
                                  const First_is_nearer& first_is_nearer) {
  if (seams_first == 0 && seams_second == 0) return Seam_placement::anywhere;
  if (seams_first == 0) return Seam_placement::at_second;
  if (seams_second == 0) return Seam_placement::at_first;
  if (!is_seam_edge() || closes_chart()) return Seam_placement::nowhere;
  const bool along_first = seams_first == 2, along_second = seams_second == 2;
  if (along_first && along_second)
    return first_is_nearer() ? Seam_placement::at_first : Seam_placement::at_second;
  if (along_first) return Seam_placement::at_second;
  if (along_second) return Seam_placement::at_first;
  return Seam_placement::nowhere;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_SEAM_COLLAPSE_RULE_H
