// The output's faces in an AABB tree, built at the first query: where the fitting pass matches an
// input sample that has no output face yet, or whose walk lost its way (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
#define CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H

#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>

#include <Eigen/Core>

#include <cstdint>
#include <optional>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Fit_output_tree {
  using Search = Hausdorff_input_surface;

 public:
  // The faces of `mesh` as they are at the first query.
  explicit Fit_output_tree(const Fit_output_mesh<TriangleMesh>& mesh) : m_mesh(&mesh) {}

  // The tree refers to m_triangles.
  Fit_output_tree(const Fit_output_tree&) = delete;
  Fit_output_tree& operator=(const Fit_output_tree&) = delete;

  // The index of the face nearest p.
  std::uint32_t nearest(const Eigen::Vector3d& p) {
    if (!m_tree) build();
    // Seeded with the last answer: consecutive samples are mostly neighbours.
    m_hint = m_hint ? m_tree->closest_point_and_primitive(Search::search_point(p), *m_hint)
                    : m_tree->closest_point_and_primitive(Search::search_point(p));
    return std::uint32_t(m_hint->second - m_triangles.cbegin());
  }

 private:
  void build() {
    for (std::uint32_t f = 0; f < m_mesh->face_count(); ++f) {
      const Indexed_triangle t = m_mesh->triangle(f);
      m_triangles.emplace_back(Search::search_point(t.points[0]), Search::search_point(t.points[1]),
                               Search::search_point(t.points[2]));
    }
    m_tree.emplace(m_triangles.begin(), m_triangles.end());
    m_tree->accelerate_distance_queries();
  }

  const Fit_output_mesh<TriangleMesh>* m_mesh;
  Search::Search_triangles m_triangles;
  std::optional<Search::Search_tree> m_tree;
  std::optional<Search::Search_tree::Point_and_primitive_id> m_hint;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_OUTPUT_TREE_H
