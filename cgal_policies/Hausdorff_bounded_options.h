// The parameters of Hausdorff_bounded_policies and its parts ([Liu17] §2.3; docs/hausdorff.md);
// Hausdorff_bounded_policies.h lists their ranges and defaults.
#ifndef CGAL_POLICIES_HAUSDORFF_BOUNDED_OPTIONS_H
#define CGAL_POLICIES_HAUSDORFF_BOUNDED_OPTIONS_H

namespace cgal_policies {

enum class Hausdorff_reference {
  global,  // the original surface: the output stays within the tolerance of the input
  local    // [Liu17]'s literal rule: the current patch, so errors may accumulate
};

enum class Collapse_order {
  by_cost,  // CGAL's priority queue, keyed by the quadric error of the edge
  storage   // [Liu17]'s single pass over the edges in storage order
};

enum class Border_rule {
  slide,  // move only along the border
  lock    // never move (and are never removed)
};

struct Hausdorff_bounded_options {
  double beta = 0.005;  // tolerance factor, a fraction of the input's bounding-box diagonal D
  double alpha = 1.0;   // simplification coefficient in (0, 1]: tau = alpha * beta * D
  int steps = 10;       // K: the edge is probed at K + 1 points at a constant step
  Hausdorff_reference reference = Hausdorff_reference::global;
  Collapse_order order = Collapse_order::by_cost;
  Border_rule border = Border_rule::slide;
  double max_normal_angle_deg = 90;  // flip prevention (Bounded_normal_angle_filter)
  double border_weight = 1000;       // border planes of the quadric that orders the queue
  int max_refinement = 5;            // sample grids are refined up to 2^5 steps per edge
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_HAUSDORFF_BOUNDED_OPTIONS_H
