// Covering a piece of the reference by single triangles of a patch (docs/hausdorff.md, "the
// pieces"): a piece is within `limit` of a triangle when its corners are (convexity).
#ifndef CGAL_POLICIES_INTERNAL_PIECE_COVER_H
#define CGAL_POLICIES_INTERNAL_PIECE_COVER_H

#include <cgal_policies/internal/triangle_distance.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

struct Piece_cover {
  Triangle_corners piece;
  std::uint32_t source;  // the index the piece had before, or kNewPiece when it was split
  std::size_t triangle;  // index into the patch's triangles
};
constexpr std::uint32_t kNewPiece = 0xffffffffu;

// Appends how the piece is covered by single triangles of `patch`, splitting it in four at most
// `depth` times; false when that fails. `hint` is the triangle tried first.
inline bool cover_piece(const Triangle_corners& piece, std::uint32_t source,
                        const std::vector<Triangle_corners>& patch, double limit, int depth,
                        std::size_t& hint, std::vector<Piece_cover>& covers) {
  const double limit2 = limit * limit;
  for (std::size_t k = 0; k < patch.size(); ++k) {
    const std::size_t j = (hint + k) % patch.size();
    if (squared_distance_to_triangle(piece[0], patch[j]) <= limit2 &&
        squared_distance_to_triangle(piece[1], patch[j]) <= limit2 &&
        squared_distance_to_triangle(piece[2], patch[j]) <= limit2) {
      hint = j;
      covers.push_back({piece, source, j});
      return true;
    }
  }
  if (depth == 0) return false;
  const Eigen::Vector3d ab = 0.5 * (piece[0] + piece[1]), bc = 0.5 * (piece[1] + piece[2]),
                        ca = 0.5 * (piece[2] + piece[0]);
  const Triangle_corners children[] = {
      {piece[0], ab, ca}, {ab, piece[1], bc}, {ca, bc, piece[2]}, {ab, bc, ca}};
  for (const Triangle_corners& child : children)
    if (!cover_piece(child, kNewPiece, patch, limit, depth - 1, hint, covers)) return false;
  return true;
}

// Cuts the piece along the edges of `fan` (around `apex`, seen along the piece's normal) into parts
// each within `limit` of its triangle; exact where halving only approaches (coplanar piece and
// fan). False, with nothing appended, unless the parts tile the piece.
inline bool cover_piece_along_fan(const Triangle_corners& piece,
                                  const std::vector<Triangle_corners>& fan,
                                  const Eigen::Vector3d& apex, double limit,
                                  std::vector<Piece_cover>& covers) {
  const Eigen::Vector3d normal = (piece[1] - piece[0]).cross(piece[2] - piece[0]);
  const double twice_area = normal.norm();
  if (!(twice_area > 0)) return false;
  const Eigen::Vector3d n = normal / twice_area;
  const auto in_plane = [&n](const Eigen::Vector3d& v) -> Eigen::Vector3d {
    return v - v.dot(n) * n;
  };
  double turn = 0;
  for (const Triangle_corners& t : fan) {
    const int k = int(std::find(t.begin(), t.end(), apex) - t.begin());
    if (k == 3) return false;
    const Eigen::Vector3d u = in_plane(t[(k + 1) % 3] - apex), w = in_plane(t[(k + 2) % 3] - apex);
    const double sine = u.cross(w).dot(n);
    if (!(sine > 0)) return false;
    turn += std::atan2(sine, u.dot(w));
  }
  if (turn > 2 * std::acos(-1.0) * (1 + 1e-9)) return false;

  const double limit2 = limit * limit;
  const std::size_t first = covers.size();
  double covered = 0;  // twice the area of the parts
  std::vector<Eigen::Vector3d> polygon, clipped;
  for (std::size_t j = 0; j < fan.size(); ++j) {
    polygon.assign(piece.begin(), piece.end());
    for (int e = 0; e < 3 && polygon.size() >= 3; ++e) {
      const Eigen::Vector3d& a = fan[j][e];
      const Eigen::Vector3d inward = n.cross(fan[j][(e + 1) % 3] - a);
      clipped.clear();
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector3d &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double fp = (p - a).dot(inward), fq = (q - a).dot(inward);
        if (fp >= 0) clipped.push_back(p);
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0))
          clipped.push_back(p + (fp / (fp - fq)) * (q - p));
      }
      polygon.swap(clipped);
    }
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const Triangle_corners part = {polygon[0], polygon[i], polygon[i + 1]};
      const double part_area = (part[1] - part[0]).cross(part[2] - part[0]).norm();
      if (!(part_area > 0)) continue;
      for (const Eigen::Vector3d& corner : part)
        if (squared_distance_to_triangle(corner, fan[j]) > limit2) {
          covers.resize(first);
          return false;
        }
      covers.push_back({part, kNewPiece, j});
      covered += part_area;
    }
  }
  if (std::abs(covered - twice_area) > 1e-9 * twice_area) {
    covers.resize(first);
    return false;
  }
  return true;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PIECE_COVER_H
