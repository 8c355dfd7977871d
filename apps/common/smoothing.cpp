#include "smoothing.h"

#include "App_error.h"

#include <cgal_policies/Hausdorff_move_guard.h>

namespace apps {

Smoothing_request take_smoothing_options(Command_line& cli) {
  Smoothing_request request;
  // Each pass is linear in the mesh: 10,000 are hours on a large scan, and more never end.
  if (const auto n = cli.take_whole_number("smooth", 0, 10000)) request.iterations = int(*n);
  if (const auto rate = cli.take_number("smooth-rate")) {
    if (!(*rate > 0 && *rate <= 1)) throw App_error(exit_usage, "--smooth-rate must be in (0, 1]");
    request.rate = *rate;
  }
  if (const auto weights = cli.take_value("smooth-weights")) {
    if (*weights == "inverse-distance")
      request.weights = cgal_policies::Smoothing_weights::inverse_distance;
    else if (*weights != "uniform")
      throw App_error(exit_usage, "--smooth-weights must be uniform or inverse-distance");
  }
  if (const auto method = cli.take_value("smooth-method")) {
    if (*method == "taubin")
      request.method = cgal_policies::Smoothing_method::taubin;
    else if (*method != "laplacian")
      throw App_error(exit_usage, "--smooth-method must be laplacian or taubin");
  }
  request.bounded = cli.take_flag("smooth-bounded");
  return request;
}

std::string smoothing_help() {
  return "  --smooth N            N passes of Laplacian smoothing after simplifying, 0..10000\n"
         "                        (default 0)\n"
         "  --smooth-rate R       lambda, 0 < R <= 1 (default 0.5)\n"
         "  --smooth-weights W    uniform (default) or inverse-distance\n"
         "  --smooth-method M     laplacian (default) or taubin (lambda, then mu = -0.53)\n"
         "  --smooth-bounded      skip moves that would take the output farther than the\n"
         "                        tolerance (--max-error, or the policy's --tolerance) from IN\n";
}

std::size_t smooth_mesh(Mesh& mesh, const Mesh& original, const Smoothing_request& request,
                        double tolerance) {
  if (request.iterations == 0) return 0;
  const cgal_policies::Laplacian_smoother<Mesh> smoother(request.rate, request.weights,
                                                         request.method);
  if (!request.bounded) {
    smoother.smooth(mesh, request.iterations);
    return 0;
  }
  const cgal_policies::Hausdorff_move_guard<Mesh> guard(original, mesh, tolerance);
  return smoother.smooth(mesh, request.iterations, guard);
}

}  // namespace apps
