// The border edges of a mesh as closed polylines with an AABB tree, so the fitting pass keeps a
// border vertex on the input's border curve and lets it slide only along its own stretch of it
// (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_BORDER_CURVE_H
#define CGAL_POLICIES_INTERNAL_BORDER_CURVE_H

#include <cgal_policies/internal/Input_triangles.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

class Border_curve {
  using Search_kernel = CGAL::Simple_cartesian<double>;
  using Segments = std::vector<Search_kernel::Segment_3>;
  using Tree = CGAL::AABB_tree<
      Aabb_traits<Search_kernel, Aabb_segment_primitive<Search_kernel, Segments::const_iterator>>>;

 public:
  template <typename TriangleMesh, typename VertexPointMap>
  Border_curve(const TriangleMesh& tm, const VertexPointMap& vpm) {
    using Halfedge = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
    std::vector<std::pair<Halfedge, std::uint32_t>> index;
    for (Halfedge h : halfedges(tm)) {
      if (!CGAL::is_border(h, tm)) continue;
      index.emplace_back(h, std::uint32_t(m_segments.size()));
      const Eigen::Vector3d a = to_eigen(get(vpm, source(h, tm)));
      const Eigen::Vector3d b = to_eigen(get(vpm, target(h, tm)));
      m_segments.emplace_back(Search_kernel::Point_3(a.x(), a.y(), a.z()),
                              Search_kernel::Point_3(b.x(), b.y(), b.z()));
    }
    if (m_segments.empty()) return;
    std::sort(index.begin(), index.end());
    const auto index_of = [&](Halfedge h) {
      return std::lower_bound(index.begin(), index.end(), std::make_pair(h, std::uint32_t(0)))
          ->second;
    };
    m_next.resize(m_segments.size());
    m_previous.resize(m_segments.size());
    for (const auto& [h, i] : index) {
      const std::uint32_t j = index_of(next(h, tm));  // the border's next edge is a border edge
      m_next[i] = j;
      m_previous[j] = i;
    }
    build_tree();
  }

  // The border of indexed triangles: the edges without a neighbour, in the order of the triangles
  // and of their edges; the next border edge is found by turning around its end through the
  // triangles, so that where two fans touch each keeps its own border.
  explicit Border_curve(const Input_triangles& triangles) {
    const auto& corners = triangles.corners;
    const auto& neighbours = triangles.neighbours;
    // Edge k of triangle t runs from corner k to corner k + 1; its border edge the other way.
    std::vector<std::uint32_t> first_of(corners.size() + 1, 0);
    for (std::size_t t = 0; t < corners.size(); ++t) {
      first_of[t + 1] = first_of[t];
      for (const int k : kEdgeOrder) {
        if (neighbours[t][k] != kNoNeighbour) continue;
        const Eigen::Vector3d& a = corners[t][(k + 1) % 3];
        const Eigen::Vector3d& b = corners[t][k];
        m_segments.emplace_back(Search_kernel::Point_3(a.x(), a.y(), a.z()),
                                Search_kernel::Point_3(b.x(), b.y(), b.z()));
        ++first_of[t + 1];
      }
    }
    if (m_segments.empty()) return;
    const auto segment_of = [&](std::size_t t, int k) {
      std::uint32_t i = first_of[t];
      for (const int j : kEdgeOrder) {
        if (j == k) break;
        i += neighbours[t][j] == kNoNeighbour;
      }
      return i;
    };
    m_next.resize(m_segments.size());
    m_previous.resize(m_segments.size());
    for (std::size_t t = 0; t < corners.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        if (neighbours[t][k] != kNoNeighbour) continue;
        // The border edge ends at corner k: turn around it, across the edges that enter it, to
        // the edge entering it that has no neighbour; the next border edge is that one's.
        std::size_t u = t;
        int entering = (k + 2) % 3;
        for (std::size_t turns = 0; neighbours[u][entering] != kNoNeighbour; ++turns) {
          if (turns == corners.size()) throw std::logic_error("Border_curve: an open fan");
          const std::size_t from = u;
          const Eigen::Vector3d& end = corners[u][(entering + 1) % 3];
          u = neighbours[u][entering];
          int leaving = 0;
          while (leaving < 3 && (neighbours[u][leaving] != from || corners[u][leaving] != end))
            ++leaving;
          if (leaving == 3) throw std::logic_error("Border_curve: neighbours that disagree");
          entering = (leaving + 2) % 3;
        }
        const std::uint32_t i = segment_of(t, k), j = segment_of(u, entering);
        m_next[i] = j;
        m_previous[j] = i;
      }
    build_tree();
  }

  bool empty() const { return m_segments.empty(); }

  double distance(const Eigen::Vector3d& p) const {
    const auto q = m_tree.closest_point(Search_kernel::Point_3(p.x(), p.y(), p.z()));
    return (Eigen::Vector3d(q.x(), q.y(), q.z()) - p).norm();
  }

  // The point of the curve nearest `to` within arc length `reach` of the curve's point nearest
  // `from`: a border vertex slides along its own stretch of border and never jumps to another
  // hole, or across a thin gap to another part of the same border.
  Eigen::Vector3d nearest_along(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                double reach) const {
    const auto start =
        m_tree.closest_point_and_primitive(Search_kernel::Point_3(from.x(), from.y(), from.z()));
    const std::uint32_t first = std::uint32_t(start.second - m_segments.cbegin());
    const Eigen::Vector3d on(start.first.x(), start.first.y(), start.first.z());
    Eigen::Vector3d best = nearest_on(first, to);
    const auto walk = [&](const std::vector<std::uint32_t>& step, double arc) {
      for (std::uint32_t i = step[first]; arc < reach && i != first; i = step[i]) {
        const Eigen::Vector3d q = nearest_on(i, to);
        if ((q - to).squaredNorm() < (best - to).squaredNorm()) best = q;
        arc += (point(i, 1) - point(i, 0)).norm();
      }
    };
    walk(m_next, (point(first, 1) - on).norm());
    walk(m_previous, (on - point(first, 0)).norm());
    return best;
  }

 private:
  // The order in which a mesh built from the triangles (clean_triangle_mesh.h, as a cell's part is)
  // numbers their border halfedges, those opposite edges 1, 2 and 0 of a triangle: the curve of a
  // cell's triangles is that of its part, segment for segment, and so are the ties of its searches.
  static constexpr std::array<int, 3> kEdgeOrder = {1, 2, 0};

  void build_tree() {
    m_tree.rebuild(m_segments.begin(), m_segments.end());
    m_tree.accelerate_distance_queries();
  }

  // End 0 (the source) or 1 (the target) of border edge i.
  Eigen::Vector3d point(std::uint32_t i, int end) const {
    const Search_kernel::Point_3& p = m_segments[i].vertex(end);
    return {p.x(), p.y(), p.z()};
  }

  Eigen::Vector3d nearest_on(std::uint32_t i, const Eigen::Vector3d& p) const {
    const Eigen::Vector3d a = point(i, 0);
    const Eigen::Vector3d ab = point(i, 1) - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return a + t * ab;
  }

  std::vector<std::uint32_t> m_next, m_previous;  // the adjacent edges along the border
  Segments m_segments;
  Tree m_tree;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_BORDER_CURVE_H
