// Distances from points to a fixed surface (the original mesh), for the viewer's error heat map.
#ifndef CGAL_POLICIES_APPS_VIEWER_SURFACE_DISTANCE_H
#define CGAL_POLICIES_APPS_VIEWER_SURFACE_DISTANCE_H

#include "Collapse_replay.h"

#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>

#include <vector>

namespace apps {

class Surface_distance {
 public:
  explicit Surface_distance(const Mesh& surface);
  Surface_distance(const Surface_distance&) = delete;  // the tree points into m_surface
  Surface_distance& operator=(const Surface_distance&) = delete;

  double operator()(const Point& p) const;

  // The distance of every vertex of `mesh` (by index; 0 for removed vertices). `cache` holds one
  // slot per point version (Indexed_mesh::point_ids), negative until computed; all the meshes given
  // with one cache must come from one Collapse_replay (or be the same mesh).
  std::vector<double> vertex_distances(const Indexed_mesh& mesh, std::vector<double>& cache) const;

 private:
  using Tree = CGAL::AABB_tree<
      cgal_policies::internal::Aabb_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  Mesh m_surface;
  Tree m_tree;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_SURFACE_DISTANCE_H
