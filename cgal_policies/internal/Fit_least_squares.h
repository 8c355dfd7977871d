// The linear least-squares problem of one fit round (docs/fitting.md): each match adds to a 9x9
// block over its face's corners, then the blocks are summed into one sparse system over every
// vertex, solved with Eigen's sparse Cholesky (SimplicialLDLT).
#ifndef CGAL_POLICIES_INTERNAL_FIT_LEAST_SQUARES_H
#define CGAL_POLICIES_INTERNAL_FIT_LEAST_SQUARES_H

#include <cgal_policies/Two_sided_fit_options.h>
#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace cgal_policies {
namespace internal {

class Fit_least_squares {
  using Block = Eigen::Matrix<double, 9, 9>;
  using Side = Eigen::Matrix<double, 9, 1>;

 public:
  // Over faces `corners` of vertices at `points`; `scale` is the mean distance of the last matches.
  Fit_least_squares(const std::vector<Fit_face_corners>& corners,
                    const std::vector<Eigen::Vector3d>& points,
                    const Two_sided_fit_options& options, double scale)
      : m_corners(&corners),
        m_points(&points),
        m_tangent_weight(options.tangent_weight),
        m_target_mean(options.target_mean),
        m_scale(scale),
        m_blocks(corners.size(), Block::Zero()),
        m_sides(corners.size(), Side::Zero()) {}

  // A match of the point at barycentric coordinates b of face f to `target`, of weight `base` and
  // at `distance`. Its squared distance is measured along its direction in full and across it at
  // tangent_weight: the distance to the tangent plane, which lets a vertex slide along the surface
  // instead of being held to last round's nearest points.
  void add(std::uint32_t f, const Eigen::Vector3d& b, double base, double distance,
           const Eigen::Vector3d& target) {
    const double w = weight(base, distance);
    const std::vector<Eigen::Vector3d>& points = *m_points;
    const Fit_face_corners& c = (*m_corners)[f];
    Eigen::Vector3d along =
        b[0] * points[c[0]] + b[1] * points[c[1]] + b[2] * points[c[2]] - target;
    if (!(along.norm() > 0)) along = triangle_area_normal(points[c[0]], points[c[1]], points[c[2]]);
    along = unit_or_zero(along);
    const Eigen::Matrix3d metric = w * (m_tangent_weight * Eigen::Matrix3d::Identity() +
                                        (1 - m_tangent_weight) * along * along.transpose());
    const Eigen::Vector3d pulled = metric * target;
    for (int r = 0; r < 3; ++r) {
      m_sides[f].segment<3>(3 * r) += b[r] * pulled;
      for (int k = 0; k < 3; ++k) m_blocks[f].block<3, 3>(3 * r, 3 * k) += b[r] * b[k] * metric;
    }
  }

  // Every vertex's point that the matches ask for; none when the system could not be solved.
  std::optional<Eigen::VectorXd> solve() const {
    const Eigen::Index size = Eigen::Index(3 * m_points->size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    const double trace = add_blocks(entries, rhs);
    add_pull(1e-3 * trace / double(size), entries, rhs);
    Eigen::SparseMatrix<double> system{size, size};
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success) return std::nullopt;
    Eigen::VectorXd solved = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solved.allFinite()) return std::nullopt;
    return solved;
  }

 private:
  // Reweighting by the distances aims the fit at the mean (L1) distance.
  double weight(double base, double distance) const {
    return m_target_mean ? base / std::max(distance, 0.1 * m_scale) : base;
  }

  // The face blocks summed into the system; returns the trace of their diagonal blocks.
  double add_blocks(std::vector<Eigen::Triplet<double>>& entries, Eigen::VectorXd& rhs) const {
    double trace = 0;
    for (std::uint32_t f = 0; f < m_corners->size(); ++f) {
      const Fit_face_corners& c = (*m_corners)[f];
      for (int r = 0; r < 3; ++r) {
        const Eigen::Index row = 3 * Eigen::Index(c[r]);
        for (int k = 0; k < 3; ++k) {
          const Eigen::Index column = 3 * Eigen::Index(c[k]);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              entries.emplace_back(row + i, column + j, m_blocks[f](3 * r + i, 3 * k + j));
        }
        rhs.segment<3>(row) += m_sides[f].segment<3>(3 * r);
        trace += m_blocks[f].block<3, 3>(3 * r, 3 * r).trace();
      }
    }
    return trace;
  }

  // A light pull toward where each vertex is keeps the system definite (a vertex no sample
  // reaches stays, and so does a vertex's slide along a flat tangent plane).
  void add_pull(double pull, std::vector<Eigen::Triplet<double>>& entries,
                Eigen::VectorXd& rhs) const {
    const std::vector<Eigen::Vector3d>& points = *m_points;
    for (std::uint32_t v = 0; v < points.size(); ++v)
      for (int i = 0; i < 3; ++i) {
        entries.emplace_back(3 * v + i, 3 * v + i, pull);
        rhs[3 * v + i] += pull * points[v][i];
      }
  }

  const std::vector<Fit_face_corners>* m_corners;
  const std::vector<Eigen::Vector3d>* m_points;
  double m_tangent_weight;
  bool m_target_mean;
  double m_scale;
  std::vector<Block> m_blocks;
  std::vector<Side> m_sides;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_LEAST_SQUARES_H
