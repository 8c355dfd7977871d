// The output's faces in a bounding-volume hierarchy: where the fitting pass matches an input sample
// that has no output face yet, or whose walk lost its way (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
#define CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H

#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Triangle_bvh.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Fit_output_tree {
 public:
  // The faces of `mesh` as they are now, indexed on up to `threads` cores.
  Fit_output_tree(const Fit_output_mesh<TriangleMesh>& mesh, std::size_t threads)
      : m_mesh(&mesh), m_bvh(triangles_of(mesh), threads) {}

  // The index of the face nearest p, the lowest among equals, whatever `near` is: a face near p
  // (kFitNoFace when none is known), whose distance bounds the search from the start.
  std::uint32_t nearest(const Eigen::Vector3d& p, std::uint32_t near) const {
    Triangle_bvh::Hit start;
    if (near != kFitNoFace) start = {near, m_mesh->squared_distance(p, near)};
    return m_bvh.nearest(p, start).triangle;
  }

 private:
  static std::vector<Triangle_corners> triangles_of(const Fit_output_mesh<TriangleMesh>& mesh) {
    std::vector<Triangle_corners> triangles;
    triangles.reserve(mesh.face_count());
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f)
      triangles.push_back(mesh.triangle(f).points);
    return triangles;
  }

  const Fit_output_mesh<TriangleMesh>* m_mesh;
  Triangle_bvh m_bvh;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
