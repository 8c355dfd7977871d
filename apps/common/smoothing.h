// Smoothing as a post-process of any policy (docs/hausdorff.md): the command-line options and the
// run, through cgal_policies::Laplacian_smoother and, in bounded mode, Hausdorff_move_guard.
#ifndef CGAL_POLICIES_APPS_SMOOTHING_H
#define CGAL_POLICIES_APPS_SMOOTHING_H

#include "Command_line.h"
#include "Mesh_types.h"

#include <cgal_policies/Laplacian_smoother.h>

#include <cstddef>
#include <string>

namespace apps {

struct Smoothing_request {
  int iterations = 0;  // 0: no smoothing
  double rate = 0.5;
  cgal_policies::Smoothing_weights weights = cgal_policies::Smoothing_weights::uniform;
  cgal_policies::Smoothing_method method = cgal_policies::Smoothing_method::laplacian;
  bool bounded = false;  // skip moves that would break the tolerance
};

// Takes --smooth N, --smooth-rate R, --smooth-weights uniform|inverse-distance,
// --smooth-method laplacian|taubin and --smooth-bounded; App_error(exit_usage) when malformed.
Smoothing_request take_smoothing_options(Command_line& cli);

// The lines of the help text that describe those options.
std::string smoothing_help();

// Smooths `mesh`; when bounded, keeps it within tolerance * D of `original` (D: its diagonal).
// Returns the number of moves refused.
std::size_t smooth_mesh(Mesh& mesh, const Mesh& original, const Smoothing_request& request,
                        double tolerance);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_SMOOTHING_H
