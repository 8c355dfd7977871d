// simplify_fast IN OUT RATIO: the 2014 report's interface to its "improved" method ([Hu14] §5.2),
// here Fast_threshold_simplifier with its defaults. simplify --policy fast offers the options.
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/Stop_reason.h"
#include "common/Stopwatch.h"
#include "common/app_main.h"
#include "common/mesh_io.h"

#include <cgal_policies/Fast_threshold_simplifier.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace apps {
namespace {

constexpr const char* kUsage = "usage: simplify_fast IN OUT RATIO (0 < RATIO <= 1)";

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    std::cout
        << kUsage
        << "\nSimplifies IN to RATIO of its faces with the fast threshold QEM and writes OUT.\n"
           "Exit codes: 0 done, 1 not done, 2 bad usage, 3 bad input, 4 output not written.\n";
    return exit_success;
  }
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 3) throw App_error(exit_usage, kUsage);
  const double ratio = parse_number(args[2], "RATIO");
  if (!(ratio > 0 && ratio <= 1)) throw App_error(exit_usage, "the ratio must be in (0, 1]");
  check_output_path(args[0], args[1], false);

  Mesh mesh = read_triangle_mesh(args[0]);
  const std::size_t input_faces = mesh.number_of_faces();
  const Stopwatch watch;
  const auto report = cgal_policies::Fast_threshold_simplifier()(
      mesh, std::size_t(std::llround(ratio * double(input_faces))));
  const double seconds = watch.seconds();
  write_mesh_atomically(mesh, args[1]);
  std::printf("%zu -> %zu faces in %.3f s (%s)\n", input_faces, std::size_t(mesh.number_of_faces()),
              seconds,
              to_string(report.target_reached ? Stop_reason::target_reached
                                              : Stop_reason::no_collapse_left));
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  return apps::guarded_main("simplify_fast", [&] { return apps::run(argc, argv); });
}
