// A bounding-volume hierarchy over a fixed set of triangles, for exact nearest-triangle queries
// (the input of the fitting pass and of the Hausdorff-bounded policies, docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_TRIANGLE_BVH_H
#define CGAL_POLICIES_INTERNAL_TRIANGLE_BVH_H

#include <cgal_policies/internal/for_each_in_parallel.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace cgal_policies {
namespace internal {

class Triangle_bvh {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  // A triangle, by its index in the constructor's vector, and p's squared distance to it.
  struct Hit {
    std::uint32_t triangle = kNone;
    double squared_distance = std::numeric_limits<double>::infinity();
  };

  Triangle_bvh() = default;  // no triangles

  // Built on up to `threads` cores (0: all of them); the tree is the same for every count.
  explicit Triangle_bvh(const std::vector<Triangle_corners>& triangles, std::size_t threads = 1) {
    std::vector<Item> items;
    items.reserve(triangles.size());
    for (const Triangle_corners& t : triangles) {
      items.push_back({(t[0] + t[1] + t[2]) / 3, std::uint32_t(items.size())});
      for (const Eigen::Vector3d& c : t)
        m_magnitude = std::max(m_magnitude, c.cwiseAbs().maxCoeff());
    }
    if (!items.empty()) {
      m_nodes.resize(node_count(items.size()));
      build(triangles, items, 0, std::uint32_t(items.size()), 0, threads);
    }
    m_triangles.reserve(items.size());
    m_index.reserve(items.size());
    for (const Item& item : items) {
      m_triangles.push_back(triangles[item.index]);
      m_index.push_back(item.index);
    }
  }

  // The triangle nearest to p, the lowest index among equals, when it is no farther than `start`
  // (which need not be one of the triangles: an upper bound that prunes from the beginning);
  // otherwise `start`. The distances are squared_distance_to_triangle's, exactly.
  Hit nearest(const Eigen::Vector3d& p, Hit start) const {
    Hit best = start;
    if (m_nodes.empty()) return best;
    // The box distance and the triangle distance round differently: a box is pruned only when it
    // is farther than the best by more than any rounding of squared_distance_to_triangle, so that
    // the answer is the minimum of the distances as computed, not as they would be exactly.
    const double slack = kSlack * (p.cwiseAbs().maxCoeff() + m_magnitude);
    double prune = pruning_bound(best.squared_distance, slack);
    std::array<Pending, kMaxDepth> stack;
    std::size_t top = 0;
    stack[top++] = {0, box_squared_distance(m_nodes[0], p)};
    while (top > 0) {
      const Pending at = stack[--top];
      if (at.squared_distance > prune) continue;
      const Node& node = m_nodes[at.node];
      if (node.count > 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
          const double d2 = squared_distance_to_triangle(p, m_triangles[k]);
          const std::uint32_t i = m_index[k];
          if (d2 < best.squared_distance || (d2 == best.squared_distance && i < best.triangle)) {
            if (d2 < best.squared_distance) prune = pruning_bound(d2, slack);
            best = {i, d2};
          }
        }
        continue;
      }
      // The nearer child goes on top, to be searched first.
      Pending nearer{at.node + 1, box_squared_distance(m_nodes[at.node + 1], p)};
      Pending farther{node.first, box_squared_distance(m_nodes[node.first], p)};
      if (farther.squared_distance < nearer.squared_distance) std::swap(nearer, farther);
      if (farther.squared_distance <= prune) stack[top++] = farther;
      if (nearer.squared_distance <= prune) stack[top++] = nearer;
    }
    return best;
  }

  Hit nearest(const Eigen::Vector3d& p) const { return nearest(p, Hit()); }

  // The triangles in the order of the leaves, near ones mostly close together: a caller that walks
  // the surface keeps them here, in this order, rather than in a copy of its own.
  std::size_t size() const { return m_triangles.size(); }
  const Triangle_corners& stored(std::uint32_t k) const { return m_triangles[k]; }
  // The constructor's index of stored(k).
  std::uint32_t index(std::uint32_t k) const { return m_index[k]; }

 private:
  // A leaf holds 2 to 4 triangles; an inner node's left child follows it, `first` is its right.
  struct Node {
    std::array<float, 3> lo, hi;  // rounded outward from the triangles' double corners
    std::uint32_t first = 0;
    std::uint32_t count = 0;  // 0 for an inner node
  };
  struct Item {  // while building
    Eigen::Vector3d centroid;
    std::uint32_t index;
  };
  struct Pending {
    std::uint32_t node;
    double squared_distance;
  };

  static constexpr std::uint32_t kLeafSize = 4;
  // Triangles below which a subtree is built on the core that split it.
  static constexpr std::uint32_t kTrianglesPerTask = 16384;
  // Median splits halve the triangles: 2^32 of them need fewer levels, plus one pending per level.
  static constexpr std::size_t kMaxDepth = 64;
  // A bound of the rounding of squared_distance_to_triangle's distance relative to the
  // coordinates' magnitude: thousands of ulps, where its few dozen operations round by far fewer.
  static constexpr double kSlack = 0x1p-40;

  static std::size_t node_count(std::size_t triangles) {
    return triangles <= kLeafSize
               ? 1
               : 1 + node_count(triangles / 2) + node_count(triangles - triangles / 2);
  }

  static double pruning_bound(double squared_distance, double slack) {
    const double d = std::sqrt(squared_distance) + slack;
    return d * d;
  }

  static double box_squared_distance(const Node& node, const Eigen::Vector3d& p) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double out = std::max({double(node.lo[k]) - p[k], p[k] - double(node.hi[k]), 0.0});
      d2 += out * out;
    }
    return d2;
  }

  static float below(double x) {
    const float f = float(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
  }
  static float above(double x) {
    const float f = float(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
  }

  // Builds the subtree of items[begin, end) at node `at`: a leaf, or two halves split at the
  // median of the centroids along the longest side of their box (ties by index, so that the tree
  // is the same on every platform), the left one at at + 1, the right one after it. Halves of
  // kTrianglesPerTask triangles or more are built at once on `threads` cores, the right one at
  // its place counted in advance. Returns the node after the subtree's last.
  std::uint32_t build(const std::vector<Triangle_corners>& triangles, std::vector<Item>& items,
                      std::uint32_t begin, std::uint32_t end, std::uint32_t at,
                      std::size_t threads) {
    if (end - begin <= kLeafSize) {
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
      Eigen::Vector3d hi = -lo;
      for (std::uint32_t k = begin; k < end; ++k)
        for (const Eigen::Vector3d& c : triangles[items[k].index]) {
          lo = lo.cwiseMin(c);
          hi = hi.cwiseMax(c);
        }
      Node& leaf = m_nodes[at];
      for (int k = 0; k < 3; ++k) {
        leaf.lo[k] = below(lo[k]);
        leaf.hi[k] = above(hi[k]);
      }
      leaf.first = begin;
      leaf.count = end - begin;
      return at + 1;
    }
    Eigen::Vector3d lo = items[begin].centroid, hi = lo;
    for (std::uint32_t k = begin + 1; k < end; ++k) {
      lo = lo.cwiseMin(items[k].centroid);
      hi = hi.cwiseMax(items[k].centroid);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                     [axis](const Item& a, const Item& b) {
                       const double ca = a.centroid[axis], cb = b.centroid[axis];
                       return ca < cb || (ca == cb && a.index < b.index);
                     });
    std::uint32_t right = 0, after = 0;
    if (threads == 1 || middle - begin < kTrianglesPerTask) {
      right = build(triangles, items, begin, middle, at + 1, 1);
      after = build(triangles, items, middle, end, right, 1);
    } else {
      right = at + 1 + std::uint32_t(node_count(middle - begin));
      for_each_in_parallel(2, threads, [&](std::size_t half) {
        if (half == 0)
          build(triangles, items, begin, middle, at + 1, threads);
        else
          after = build(triangles, items, middle, end, right, threads);
      });
    }
    Node& node = m_nodes[at];
    const Node& first = m_nodes[at + 1];
    const Node& second = m_nodes[right];
    for (int k = 0; k < 3; ++k) {
      node.lo[k] = std::min(first.lo[k], second.lo[k]);
      node.hi[k] = std::max(first.hi[k], second.hi[k]);
    }
    node.first = right;
    return after;
  }

  std::vector<Node> m_nodes;
  std::vector<Triangle_corners> m_triangles;  // in the order of the leaves
  std::vector<std::uint32_t> m_index;         // the constructor's index of each of m_triangles
  double m_magnitude = 0;                     // the largest absolute coordinate of a corner
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_TRIANGLE_BVH_H
