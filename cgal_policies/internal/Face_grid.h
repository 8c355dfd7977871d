// A uniform grid of face bounding boxes that follows a mesh whose faces move and flip, so the
// fitting pass can find the faces a changed face might cross (docs/fitting.md).
#ifndef CGAL_POLICIES_INTERNAL_FACE_GRID_H
#define CGAL_POLICIES_INTERNAL_FACE_GRID_H

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace cgal_policies {
namespace internal {

class Face_grid {
 public:
  // Faces 0 .. face_count - 1; `cell` is the cell's edge length, > 0.
  Face_grid(std::size_t face_count, double cell) : m_cell(cell), m_ranges(face_count) {}

  void insert(std::uint32_t face, const std::array<Eigen::Vector3d, 3>& corners) {
    m_ranges[face] = range_of(corners);
    for_each_cell(m_ranges[face], [&](std::uint64_t key) { m_cells[key].push_back(face); });
  }

  void erase(std::uint32_t face) {
    for_each_cell(m_ranges[face], [&](std::uint64_t key) {
      std::vector<std::uint32_t>& list = m_cells[key];
      list.erase(std::find(list.begin(), list.end(), face));
    });
  }

  // The faces that share a cell with the triangle, each once, `skip` not among them.
  template <typename Visit>
  bool any_near(const std::array<Eigen::Vector3d, 3>& corners, std::uint32_t skip,
                const Visit& visit) {
    ++m_stamp;
    if (m_seen.size() < m_ranges.size()) m_seen.resize(m_ranges.size(), 0);
    bool found = false;
    for_each_cell(range_of(corners), [&](std::uint64_t key) {
      if (found) return;
      const auto it = m_cells.find(key);
      if (it == m_cells.end()) return;
      for (const std::uint32_t f : it->second) {
        if (f == skip || m_seen[f] == m_stamp) continue;
        m_seen[f] = m_stamp;
        if (visit(f)) {
          found = true;
          return;
        }
      }
    });
    return found;
  }

 private:
  using Range = std::array<std::int64_t, 6>;  // lowest and highest cell on each axis

  Range range_of(const std::array<Eigen::Vector3d, 3>& corners) const {
    Range r;
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = std::min({corners[0][axis], corners[1][axis], corners[2][axis]});
      const double hi = std::max({corners[0][axis], corners[1][axis], corners[2][axis]});
      r[axis] = std::int64_t(std::floor(lo / m_cell));
      r[axis + 3] = std::int64_t(std::floor(hi / m_cell));
    }
    return r;
  }

  template <typename Visit>
  static void for_each_cell(const Range& r, const Visit& visit) {
    for (std::int64_t i = r[0]; i <= r[3]; ++i)
      for (std::int64_t j = r[1]; j <= r[4]; ++j)
        for (std::int64_t k = r[2]; k <= r[5]; ++k)
          visit((std::uint64_t(i & 0x1fffff) << 42) | (std::uint64_t(j & 0x1fffff) << 21) |
                std::uint64_t(k & 0x1fffff));
  }

  double m_cell;
  std::vector<Range> m_ranges;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;
  std::vector<std::uint32_t> m_seen;
  std::uint32_t m_stamp = 0;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FACE_GRID_H
