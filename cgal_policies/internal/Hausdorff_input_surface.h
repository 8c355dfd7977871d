// The input surface of the Hausdorff-bounded policies (docs/hausdorff.md): its triangles, their
// neighbours across edges and a bounding-volume hierarchy, for distance queries and the flatness
// argument.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_INPUT_SURFACE_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_INPUT_SURFACE_H

#include <cgal_policies/internal/Flat_frame.h>
#include <cgal_policies/internal/Input_triangles.h>
#include <cgal_policies/internal/Triangle_bvh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/patch_distance.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// A walk on the input toward a point stops after this many steps (see nearest()).
constexpr std::size_t kWalkSteps = 64;
// The flatness argument gives up after this many input triangles.
constexpr std::size_t kFlatSearchLimit = 2000;

// The length of the diagonal of `box`: D, of which a Hausdorff bound's tolerance is a fraction.
inline double diagonal_length(const CGAL::Bbox_3& box) {
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

class Hausdorff_input_surface {
 public:
  // Not `indexed` (local reference): only the tolerance, tolerance_fraction * D, is known. The
  // hierarchy is built on up to `threads` cores, the same on any count.
  template <typename InputMesh, typename VertexPointMap>
  Hausdorff_input_surface(const InputMesh& input, const VertexPointMap& vpm,
                          double tolerance_fraction, bool indexed, std::size_t threads = 1) {
    m_diagonal = diagonal_length(
        CGAL::Polygon_mesh_processing::bbox(input, CGAL::parameters::vertex_point_map(vpm)));
    m_tolerance = tolerance_fraction * m_diagonal;
    if (indexed) index(input_triangles(input, vpm), threads);
  }

  // Indexed triangles, with a tolerance of tolerance_fraction * D, D the diagonal of their box.
  Hausdorff_input_surface(Input_triangles triangles, double tolerance_fraction,
                          std::size_t threads = 1) {
    CGAL::Bbox_3 box;
    for (const Triangle_corners& t : triangles.corners)
      for (const Eigen::Vector3d& c : t)
        box += CGAL::Bbox_3(c.x(), c.y(), c.z(), c.x(), c.y(), c.z());
    m_diagonal = diagonal_length(box);
    m_tolerance = tolerance_fraction * m_diagonal;
    index(std::move(triangles), threads);
  }

  Hausdorff_input_surface(const Hausdorff_input_surface&) = delete;
  Hausdorff_input_surface& operator=(const Hausdorff_input_surface&) = delete;

  double diagonal() const { return m_diagonal; }
  double tolerance() const { return m_tolerance; }
  std::size_t size() const { return m_bvh.size(); }
  const Triangle_corners& corners(std::size_t i) const { return m_bvh.stored(m_position[i]); }

  // An upper bound of p's distance (all the tests need): a walk across input edges from `hint`
  // while the distance drops; beyond the tolerance, the exact nearest triangle (the lowest index
  // among equals, whatever the hint), searched with the walk's end as a first bound. Without a
  // tolerance the search always runs, and the hint's own distance bounds it: the walk's scattered
  // reads cost more than the tighter bound saves (docs/fitting.md).
  Reference_sample nearest(const Eigen::Vector3d& p,
                           std::size_t hint = Reference_sample::kNoTriangle) const {
    Triangle_bvh::Hit start;
    if (hint != Reference_sample::kNoTriangle) {
      std::uint32_t at = m_position[hint];  // the walk goes by positions in the hierarchy
      double d2 = squared_distance_to_triangle(p, m_bvh.stored(at));
      const std::size_t steps = m_tolerance > 0 ? kWalkSteps : 0;
      for (std::size_t step = 0; step < steps; ++step) {
        const std::uint32_t from = at;
        for (const std::uint32_t j : m_neighbours[from]) {
          if (j == kNoNeighbour) continue;
          const double e2 = squared_distance_to_triangle(p, m_bvh.stored(j));
          if (e2 < d2) {
            d2 = e2;
            at = j;
          }
        }
        if (at == from) break;
      }
      if (d2 <= m_tolerance * m_tolerance) return {std::sqrt(d2), m_bvh.index(at)};
      start = {m_bvh.index(at), d2};
    }
    const Triangle_bvh::Hit hit = m_bvh.nearest(p, start);
    if (hit.triangle == Triangle_bvh::kNone) return {};  // no input triangles
    return {std::sqrt(hit.squared_distance), hit.triangle};
  }

  // Whether t lies within the tolerance of a flat part K of the input (Flat_frame): K grows through
  // triangles that hold the argument and may meet t; its edges to others, or to none, must miss t.
  bool flat_covers(const Sampled_triangle& t) const {
    const Flat_frame frame(t.corners, m_tolerance);
    if (!frame.valid()) return false;
    enum : std::uint8_t { outside, kept, rejected };
    if (++m_flat_stamp == 0) {  // wrapped: stale stamps would pass for current ones
      std::fill(m_flat_state.begin(), m_flat_state.end(), std::make_pair(0u, std::uint8_t(0)));
      m_flat_stamp = 1;
    }
    m_flat_stack.clear();
    const auto visit = [&](std::uint32_t j) {  // j a position in the hierarchy
      auto& [stamp, state] = m_flat_state[j];
      if (stamp != m_flat_stamp) {
        stamp = m_flat_stamp;
        const Triangle_corners& q = m_bvh.stored(j);
        state = !frame.may_meet(q) ? outside : frame.holds(q) ? kept : rejected;
        if (state == kept) m_flat_stack.push_back(j);
      }
      return state;
    };
    // Seeds: the triangles nearest to t's corners, or, when one does not hold the argument (a
    // corner on a crease may be nearest to the far side), the two rings of triangles around it.
    for (const Reference_sample& s : t.samples) {
      if (s.triangle == Reference_sample::kNoTriangle) continue;
      const std::uint32_t seed = m_position[s.triangle];
      if (visit(seed) == kept) continue;
      for (const std::uint32_t j : m_neighbours[seed])
        if (j != kNoNeighbour && visit(j) != kept)
          for (const std::uint32_t k : m_neighbours[j])
            if (k != kNoNeighbour) visit(k);
    }
    bool centroid = false;
    for (std::size_t expanded = 0; !m_flat_stack.empty(); ++expanded) {
      if (expanded == kFlatSearchLimit) return false;
      const std::uint32_t i = m_flat_stack.back();
      m_flat_stack.pop_back();
      const Triangle_corners& q = m_bvh.stored(i);
      centroid = centroid || frame.holds_centroid(q);
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t j = m_neighbours[i][k];
        if ((j == kNoNeighbour || visit(j) == rejected) && frame.crosses(q[k], q[(k + 1) % 3]))
          return false;
      }
    }
    return centroid;
  }

 private:
  // The hierarchy keeps the only copy of the corners, in the order of its leaves, and the
  // neighbours follow that order: a walk then reads memory that the search has read or will.
  void index(Input_triangles triangles, std::size_t threads) {
    m_bvh = Triangle_bvh(triangles.corners, threads);
    triangles.corners = {};
    const std::uint32_t n = std::uint32_t(m_bvh.size());
    m_position.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) m_position[m_bvh.index(k)] = k;
    m_neighbours.resize(n);
    for (std::uint32_t k = 0; k < n; ++k)
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t j = triangles.neighbours[m_bvh.index(k)][std::size_t(e)];
        m_neighbours[k][std::size_t(e)] = j == kNoNeighbour ? kNoNeighbour : m_position[j];
      }
    m_flat_state.assign(n, {0, 0});
  }

  double m_diagonal = 0;
  double m_tolerance = 0;
  Triangle_bvh m_bvh;
  std::vector<std::uint32_t> m_position;  // of each triangle in the hierarchy's order
  std::vector<std::array<std::uint32_t, 3>> m_neighbours;  // by positions, in that order
  mutable std::vector<std::pair<std::uint32_t, std::uint8_t>> m_flat_state;  // by positions
  mutable std::uint32_t m_flat_stamp = 0;
  mutable std::vector<std::uint32_t> m_flat_stack;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_INPUT_SURFACE_H
