// The invariants every fuzz target checks; a broken one aborts with its name, which libFuzzer
// reports as a crash and saves the input for.
#ifndef CGAL_POLICIES_FUZZ_FUZZ_CHECKS_H
#define CGAL_POLICIES_FUZZ_FUZZ_CHECKS_H

#include "app_types.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz {

inline void require(bool holds, const std::string& what) {
  if (holds) return;
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}

// An error message: one line that says something.
inline void require_one_line(const std::string& message) {
  require(!message.empty() && message.find('\n') == std::string::npos,
          "an error message of one line: '" + message + "'");
}

// What every mesh read or written is: a valid triangle mesh (mesh_measures' validity) with finite
// points and at least one face. Returns the validity figures, for the checks that follow.
inline apps::Mesh_validity require_finite_triangle_mesh(const apps::Mesh& mesh,
                                                        const std::string& whose) {
  const apps::Mesh_validity validity = apps::check_mesh_validity(mesh);
  require(validity.valid, whose + ": a valid halfedge structure of triangles");
  require(validity.faces > 0, whose + ": at least one face");
  for (const auto v : mesh.vertices()) {
    const apps::Point& p = mesh.point(v);
    require(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()),
            whose + ": finite coordinates");
  }
  return validity;
}

}  // namespace fuzz

#endif  // CGAL_POLICIES_FUZZ_FUZZ_CHECKS_H
