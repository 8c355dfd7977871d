// Simplification_options: everything Simplification_pipeline does to a mesh, with the library's
// defaults (docs/pipeline.md). Each field states its unit, range and default; a value outside its
// range is a precondition of Simplification_pipeline's constructor.
//   target                faces kept: Face_target::ratio(r), 0 < r <= 1, or Face_target::faces(n)
//                         (default ratio 0.1)
//   policy                the policy of the simplification pass (default below: the lowest mean
//                         error among the pipelines quick enough for a default, docs/pipeline.md)
//   classic ... attributes  that policy's options, with their own defaults; the one of `policy`
//                         is used
//   max_normal_angle_deg  no collapse turns a surviving face normal by more than this, degrees in
//                         [0, 180] (default 90); every policy of this library, and the fitting
//                         pass; it overrides the field of the same name in the policies' options.
//                         CGAL's own policies run as CGAL ships them.
//   max_error             > 0: the output stays within this two-sided Hausdorff distance of the
//                         input, a fraction of its bounding-box diagonal; 0: no bound (default).
//                         Every policy that runs_edge_collapse()
//   time_limit_seconds    > 0: the simplification stops where it is after this long; 0: none
//                         (default). Every policy that runs_edge_collapse()
//   merge_distance        > 0: first stitch border vertices of different border loops closer than
//                         this, a fraction of the diagonal (Border_pair_contraction; default 0,
//                         off)
//   min_component         > 1: first drop every connected component of fewer faces but the largest
//                         (default 0, off)
//   drop_small_pieces     when no collapse is left short of the target, drop whole components,
//                         smallest first, never the largest, until it is met (default false)
//   prepass_factor        >= 1: before the policy, fast takes the mesh (each part of a partitioned
//                         run) down to this many times the policy's target, when it has more, so
//                         that the policy works on a much smaller mesh (docs/pipeline.md); 0: off
//                         (default). Not with a bound, a time limit or on_collapse
//   smoothing             Smoothing_options (default: none)
//   fit                   then fit the output to the input both ways (Two_sided_fitter), within the
//                         run's bound when it has one (default below)
//   fit_options           the fitter's rounds, samples and steps (its max_normal_angle_deg,
//                         tolerance and threads come from this struct)
//   parts                 cells of a partitioned run (docs/scale.md), rounded down to a power
//                         of two; 0: one per kFacesPerPart input faces (default), 1: none. A
//                         run with on_collapse runs whole; a bound holds as in a whole run
//   threads               cores for the parts and the fit's matching, 0: all of them (default);
//                         the output is the same for every count
//   progress              called now and then with the pass running, how far it is in [0, 1], and
//                         the face count; may be empty. The parts of a partitioned run call it
//                         from their threads, one call at a time, with the whole's face count
//   pass_done             called after each pass that ran, the mesh compact; may be empty
//   interrupted           polled during the passes; true stops the run where it is, with
//                         Stop_reason::interrupted, the mesh still valid; may be empty. In a
//                         partitioned run it is polled from several threads at once
//   on_collapse           called after every collapse of an edge-collapse policy with the vertex
//                         removed and the one kept (already at its new point); may be empty
#ifndef CGAL_POLICIES_SIMPLIFICATION_OPTIONS_H
#define CGAL_POLICIES_SIMPLIFICATION_OPTIONS_H

#include <cgal_policies/Attribute_quadric_options.h>
#include <cgal_policies/Curvature_weighted_options.h>
#include <cgal_policies/Face_target.h>
#include <cgal_policies/Fast_threshold_options.h>
#include <cgal_policies/Feature_fusion_options.h>
#include <cgal_policies/Flat_lindstrom_turk_options.h>
#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/Quadric_options.h>
#include <cgal_policies/Simplification_pass.h>
#include <cgal_policies/Simplification_policy.h>
#include <cgal_policies/Smoothing_options.h>
#include <cgal_policies/Two_sided_fit_options.h>

#include <CGAL/Surface_mesh/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>

namespace cgal_policies {

struct Simplification_options {
  Face_target target = Face_target::ratio(0.1);
  Simplification_policy policy = Simplification_policy::lt;
  Quadric_options classic;
  Curvature_weighted_options curvature;
  Feature_fusion_options fusion;
  Fast_threshold_options fast;
  Flat_lindstrom_turk_options flat_lt;
  Hausdorff_bounded_options hausdorff;
  Attribute_quadric_options attributes;
  double max_normal_angle_deg = 90;
  double max_error = 0;
  double time_limit_seconds = 0;
  double merge_distance = 0;
  std::size_t min_component = 0;
  bool drop_small_pieces = false;
  double prepass_factor = 0;
  Smoothing_options smoothing;
  bool fit = true;
  Two_sided_fit_options fit_options;
  std::size_t parts = 0;
  std::size_t threads = 0;
  std::function<void(Simplification_pass pass, double done, std::size_t faces)> progress;
  std::function<void(Simplification_pass pass)> pass_done;
  std::function<bool()> interrupted;
  std::function<void(CGAL::SM_Vertex_index removed, CGAL::SM_Vertex_index kept)> on_collapse;

  // Input faces per cell of a partitioned run when `parts` is 0.
  static constexpr std::size_t kFacesPerPart = 500000;

  // The cells a run on `input_faces` faces is cut into: 1 when it runs whole.
  std::size_t cell_count(std::size_t input_faces) const {
    if (on_collapse) return 1;  // the viewer's replay numbers the vertices of one mesh
    const std::size_t wanted = parts > 0 ? parts : input_faces / kFacesPerPart;
    std::size_t cells = 1;
    while (2 * cells <= wanted) cells *= 2;
    return cells;
  }

  // The faces the fast prepass leaves for a policy run to `policy_target` faces; 0 without a
  // prepass (fast itself has none).
  std::size_t prepass_faces(std::size_t policy_target) const {
    if (prepass_factor == 0 || policy == Simplification_policy::fast) return 0;
    return std::size_t(std::ceil(prepass_factor * double(std::max<std::size_t>(policy_target, 1))));
  }

  // The two-sided bound the run keeps, a fraction of the input's diagonal: max_error, else the
  // hausdorff policy's own tolerance in its global mode; 0 when there is none.
  double two_sided_bound() const {
    if (max_error > 0) return max_error;
    if (policy == Simplification_policy::hausdorff &&
        hausdorff.reference == Hausdorff_reference::global)
      return hausdorff.alpha * hausdorff.beta;
    return 0;
  }
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SIMPLIFICATION_OPTIONS_H
