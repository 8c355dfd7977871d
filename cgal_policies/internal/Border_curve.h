// The border edges of a mesh in an AABB tree, so the fitting pass keeps border vertices on the
// input's border curve (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_BORDER_CURVE_H
#define CGAL_POLICIES_INTERNAL_BORDER_CURVE_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>

#include <vector>

namespace cgal_policies {
namespace internal {

class Border_curve {
  using Search_kernel = CGAL::Simple_cartesian<double>;
  using Segments = std::vector<Search_kernel::Segment_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<
      Search_kernel, CGAL::AABB_segment_primitive<Search_kernel, Segments::const_iterator>>>;

 public:
  template <typename TriangleMesh, typename VertexPointMap>
  Border_curve(const TriangleMesh& tm, const VertexPointMap& vpm) {
    for (auto h : halfedges(tm)) {
      if (!CGAL::is_border(h, tm)) continue;
      const Eigen::Vector3d a = to_eigen(get(vpm, source(h, tm)));
      const Eigen::Vector3d b = to_eigen(get(vpm, target(h, tm)));
      m_segments.emplace_back(Search_kernel::Point_3(a.x(), a.y(), a.z()),
                              Search_kernel::Point_3(b.x(), b.y(), b.z()));
    }
    if (m_segments.empty()) return;
    m_tree.rebuild(m_segments.begin(), m_segments.end());
    m_tree.accelerate_distance_queries();
  }

  bool empty() const { return m_segments.empty(); }

  Eigen::Vector3d nearest(const Eigen::Vector3d& p) const {
    const auto q = m_tree.closest_point(Search_kernel::Point_3(p.x(), p.y(), p.z()));
    return {q.x(), q.y(), q.z()};
  }

 private:
  Segments m_segments;
  Tree m_tree;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_BORDER_CURVE_H
