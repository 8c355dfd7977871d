// The cells of a partitioned run: a k-d split of a mesh's face centroids at their medians, the
// longest side of each box first, into a power of two of cells with about as many faces each.
// Built on the input; every later mesh of the run (the simplified parts, the output to fit) is cut
// by the same planes, so that each cell of the output lies over the same cell of the input.
#ifndef CGAL_POLICIES_INTERNAL_SPATIAL_CELLS_H
#define CGAL_POLICIES_INTERNAL_SPATIAL_CELLS_H

#include <cgal_policies/internal/for_each_in_parallel.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

class Spatial_cells {
 public:
  struct Split {
    int axis = 0;
    double at = 0;  // below: the first child; at or above: the second
  };

  // `cells` is rounded down to a power of two; 1 when there are fewer centroids than cells. Each
  // box is split at the `quantile` of its centroids along its longest side (default the median),
  // the two halves of a large box on two of `threads` cores (0: all), with the same planes.
  Spatial_cells(std::vector<Eigen::Vector3d> centroids, std::size_t cells, std::size_t threads = 1,
                double quantile = 0.5)
      : m_quantile(quantile) {
    while ((std::size_t(1) << (m_levels + 1)) <= cells &&
           (std::size_t(1) << (m_levels + 1)) <= centroids.size())
      ++m_levels;
    m_splits.resize((std::size_t(1) << m_levels) - 1);
    if (m_levels > 0) split(centroids.begin(), centroids.end(), 0, 0, threads);
  }

  // The cells of these planes, as splits() gave them (a partitioned job's file).
  explicit Spatial_cells(std::vector<Split> splits) : m_quantile(0), m_splits(std::move(splits)) {
    while ((std::size_t(2) << m_levels) - 1 <= m_splits.size()) ++m_levels;
    m_splits.resize((std::size_t(1) << m_levels) - 1);
  }

  std::size_t size() const { return std::size_t(1) << m_levels; }

  // The planes, a complete binary tree in heap order.
  const std::vector<Split>& splits() const { return m_splits; }

  std::size_t cell_of(const Eigen::Vector3d& p) const {
    std::size_t node = 0;
    for (int level = 0; level < m_levels; ++level)
      node = 2 * node + (p[m_splits[node].axis] < m_splits[node].at ? 1 : 2);
    return node - m_splits.size();
  }

 private:
  using Iterator = std::vector<Eigen::Vector3d>::iterator;

  // Boxes of fewer centroids split both halves on one core: a task would cost more than it saves.
  static constexpr std::ptrdiff_t kCentroidsPerTask = std::ptrdiff_t(1) << 16;

  // Each half is split on its own (its own nodes and centroids), so the order does not matter.
  void split(Iterator begin, Iterator end, std::size_t node, int level, std::size_t threads) {
    if (level == m_levels || begin == end) return;  // an empty box keeps a split at 0 on x
    Eigen::Vector3d low = *begin, high = *begin;
    for (Iterator it = begin; it != end; ++it) {
      low = low.cwiseMin(*it);
      high = high.cwiseMax(*it);
    }
    Split& s = m_splits[node];
    (high - low).maxCoeff(&s.axis);
    const Iterator middle = begin + std::ptrdiff_t(m_quantile * double(end - begin));
    std::nth_element(begin, middle, end,
                     [axis = s.axis](const auto& a, const auto& b) { return a[axis] < b[axis]; });
    s.at = (*middle)[s.axis];
    for_each_in_parallel(2, end - begin < kCentroidsPerTask ? 1 : threads, [&](std::size_t half) {
      if (half == 0)
        split(begin, middle, 2 * node + 1, level + 1, threads);
      else
        split(middle, end, 2 * node + 2, level + 1, threads);
    });
  }

  double m_quantile;
  int m_levels = 0;
  std::vector<Split> m_splits;  // a complete binary tree in heap order
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_SPATIAL_CELLS_H
