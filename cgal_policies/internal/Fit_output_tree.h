// The output's faces in a bounding-volume hierarchy, built at the first query: where the fitting
// pass matches an input sample that has no output face yet, or whose walk lost its way
// (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
#define CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H

#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Triangle_bvh.h>

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Fit_output_tree {
 public:
  // The faces of `mesh` as they are at the first query.
  explicit Fit_output_tree(const Fit_output_mesh<TriangleMesh>& mesh) : m_mesh(&mesh) {}

  // The index of the face nearest p, the lowest among equals.
  std::uint32_t nearest(const Eigen::Vector3d& p) {
    if (!m_bvh) build();
    // The last answer bounds the search from the start: consecutive samples are mostly neighbours.
    Triangle_bvh::Hit start;
    if (m_last != Triangle_bvh::kNone) start = {m_last, m_mesh->squared_distance(p, m_last)};
    m_last = m_bvh->nearest(p, start).triangle;
    return m_last;
  }

 private:
  void build() {
    std::vector<Triangle_corners> triangles;
    triangles.reserve(m_mesh->face_count());
    for (std::uint32_t f = 0; f < m_mesh->face_count(); ++f)
      triangles.push_back(m_mesh->triangle(f).points);
    m_bvh.emplace(triangles);
  }

  const Fit_output_mesh<TriangleMesh>* m_mesh;
  std::optional<Triangle_bvh> m_bvh;
  std::uint32_t m_last = Triangle_bvh::kNone;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
