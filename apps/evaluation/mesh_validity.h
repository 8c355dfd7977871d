// The validity figures of one mesh: halfedge structure, borders, manifoldness, degenerate faces,
// smallest angle and Euler characteristic (docs/evaluation.md).
#ifndef CGAL_POLICIES_APPS_EVALUATION_MESH_VALIDITY_H
#define CGAL_POLICIES_APPS_EVALUATION_MESH_VALIDITY_H

#include "app_types.h"

#include <cstddef>

namespace apps {

struct Mesh_validity {
  bool valid = false;   // a valid halfedge structure made of triangles only
  bool closed = false;  // no boundary edge
  std::size_t faces = 0, vertices = 0;
  std::size_t boundary_edges = 0, non_manifold_vertices = 0, degenerate_faces = 0;
  double min_angle_deg = 0;
  long euler_characteristic = 0;
};

Mesh_validity check_mesh_validity(const Mesh& mesh);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EVALUATION_MESH_VALIDITY_H
