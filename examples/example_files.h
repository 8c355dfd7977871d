// What every example does around its policy, kept out of its way: IN OUT RATIO read from the
// command line, the mesh read with CGAL's own readers and written back, each failure one line on
// stderr and the exit code of the suite's apps (2 usage, 3 input, 4 output).
#ifndef CGAL_POLICIES_EXAMPLES_EXAMPLE_FILES_H
#define CGAL_POLICIES_EXAMPLES_EXAMPLE_FILES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <string>

namespace example {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

struct Arguments {
  std::string input, output;
  double ratio = 0;  // the fraction of the faces kept
  double extra = 0;  // an optional fourth argument, 0 when absent
};

inline Arguments arguments(int argc, char** argv, const char* usage) {
  Arguments a;
  char* end = nullptr;
  if (argc == 4 || argc == 5) {
    a = {argv[1], argv[2], std::strtod(argv[3], &end), argc == 5 ? std::atof(argv[4]) : 0};
    if (*end == '\0' && a.ratio > 0 && a.ratio <= 1 && a.extra >= 0) return a;
  }
  std::cerr << usage << '\n';
  std::exit(2);
}

inline Mesh read_mesh(const std::string& path) {
  Mesh mesh;
  // CGAL's reader that repairs a soup on the way in (the cow needs its faces oriented).
  if (!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, mesh) ||
      !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << path << ": not a triangle mesh CGAL can read\n";
    std::exit(3);
  }
  return mesh;
}

inline std::size_t target_of(const Mesh& mesh, double ratio) {
  return std::size_t(ratio * double(mesh.number_of_faces()) + 0.5);
}

inline void write_mesh(Mesh& mesh, const std::string& path) {
  mesh.collect_garbage();
  if (!CGAL::IO::write_polygon_mesh(path, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << path << ": cannot write\n";
    std::exit(4);
  }
}

}  // namespace example

#endif  // CGAL_POLICIES_EXAMPLES_EXAMPLE_FILES_H
