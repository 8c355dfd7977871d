// simplify_fast IN OUT RATIO: the 2014 report's interface to its "improved" method ([Hu14] §5.2),
// Fast_threshold_simplifier with its defaults; not an edge_collapse policy but a function object
// on the mesh. `simplify --policy fast` offers the options.
#include "example_files.h"

#include <cgal_policies/Fast_threshold_simplifier.h>

using example::Mesh;

int main(int argc, char** argv) {
  const example::Arguments args =
      example::arguments(argc, argv, "usage: simplify_fast IN OUT RATIO (0 < RATIO <= 1)");
  Mesh mesh = example::read_mesh(args.input);
  const cgal_policies::Fast_threshold_report report =
      cgal_policies::Fast_threshold_simplifier()(mesh, example::target_of(mesh, args.ratio));
  std::cout << mesh.number_of_faces() << " faces in " << report.passes << " passes ("
            << (report.target_reached ? "target reached" : "no collapse left") << ")\n";
  example::write_mesh(mesh, args.output);
}
