// Conservative distance tests between small triangle sets, for the Hausdorff-bounded policies
// (policies.md §3). Two directions, two arguments:
// - A triangle is within `limit` of a reference surface when the distance at the corners of a
//   barycentric sample grid plus the grid's covering radius stays below `limit` (the distance to a
//   set is 1-Lipschitz). The grid is refined (n = 1, 2, 4, ...) only where the bound is not met.
// - A piece of the reference is within `limit` of one triangle T when its three corners are: the
//   distance to a convex set is convex, so its maximum over the piece is at a corner. A piece that
//   no single triangle covers is split in four and retried.
#ifndef CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H
#define CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H

#include <cgal_policies/internal/quadric_placement.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

using Triangle_corners = std::array<Eigen::Vector3d, 3>;

// Squared distance from p to the triangle (a, b, c), through the Voronoi regions of its corners,
// edges and face; a degenerate triangle falls back to its three edges.
inline double squared_distance_to_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (ap - (d1 / (d1 - d3)) * ab).squaredNorm();
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (ap - (d2 / (d2 - d6)) * ac).squaredNorm();
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return (bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)).squaredNorm();
  const double sum = va + vb + vc;
  if (!(sum > 0))
    return std::min({squared_distance_to_segment(p, a, b), squared_distance_to_segment(p, b, c),
                     squared_distance_to_segment(p, c, a)});
  const double v = vb / sum, w = vc / sum;
  return (ap - v * ab - w * ac).squaredNorm();
}

inline double squared_distance_to_triangle(const Eigen::Vector3d& p, const Triangle_corners& t) {
  return squared_distance_to_triangle(p, t[0], t[1], t[2]);
}

// The largest distance from a point of the triangle to its nearest corner: the circumradius when
// the triangle is acute (the circumcentre is inside), else at most half the longest edge.
inline double covering_radius(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c) {
  std::array<double, 3> e2 = {(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()};
  std::sort(e2.begin(), e2.end());
  if (e2[2] >= e2[0] + e2[1]) return 0.5 * std::sqrt(e2[2]);
  const double twice_area = (b - a).cross(c - a).norm();
  return std::sqrt(e2[0] * e2[1] * e2[2]) / (2 * twice_area);
}

// The exact distance from a point to the reference, and the reference triangle where it is reached
// (kNoTriangle when unknown).
struct Reference_sample {
  double distance = 0;
  std::size_t triangle = kNoTriangle;
  static constexpr std::size_t kNoTriangle = std::size_t(-1);
};

// True when every point of triangle t is within `limit` of the union of `nearby` reference
// triangles for a reason sampling cannot see, flatness: the triangles that lie within `limit` of
// t's plane and face its way project onto that plane without folding, and when their projection
// covers t's (t's corners inside, none of their boundary edges crossing t), the point of the union
// above any point of t is within `limit` of it. `nearby` must hold every reference triangle that
// meets t's bounding box grown by `limit`.
inline bool flat_region_covers(const Triangle_corners& t,
                               const std::vector<const Triangle_corners*>& nearby, double limit) {
  const Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
  const double twice_area = normal.norm();
  if (!(twice_area > 0)) return false;
  const Eigen::Vector3d n = normal / twice_area;
  const Eigen::Vector3d u = (t[1] - t[0]).normalized(), w = n.cross(u);
  const auto flat = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - t[0];
    return Eigen::Vector2d(d.dot(u), d.dot(w));
  };
  using Key = std::array<double, 6>;
  std::vector<std::array<Eigen::Vector2d, 3>> kept;
  std::vector<std::pair<Key, std::array<Eigen::Vector2d, 2>>> edges;
  for (const Triangle_corners* r : nearby) {
    const Triangle_corners& q = *r;
    if (std::abs((q[0] - t[0]).dot(n)) > limit || std::abs((q[1] - t[0]).dot(n)) > limit ||
        std::abs((q[2] - t[0]).dot(n)) > limit || !((q[1] - q[0]).cross(q[2] - q[0]).dot(n) > 0))
      continue;
    kept.push_back({flat(q[0]), flat(q[1]), flat(q[2])});
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d &a = q[k], &b = q[(k + 1) % 3];
      const bool ordered =
          std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
      const Eigen::Vector3d &lo = ordered ? a : b, &hi = ordered ? b : a;
      edges.push_back({{lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()}, {flat(a), flat(b)}});
    }
  }
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  const std::array<Eigen::Vector2d, 3> tt = {flat(t[0]), flat(t[1]), flat(t[2])};
  for (const Eigen::Vector2d& corner : tt) {
    bool inside = false;
    for (const auto& q : kept)
      if (cross(q[1] - q[0], corner - q[0]) >= 0 && cross(q[2] - q[1], corner - q[1]) >= 0 &&
          cross(q[0] - q[2], corner - q[2]) >= 0) {
        inside = true;
        break;
      }
    if (!inside) return false;
  }
  // Boundary edges of the kept triangles belong to one of them only.
  std::sort(edges.begin(), edges.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  const double scale = std::sqrt(twice_area);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    if (j - i == 1) {
      // Clip the segment to the open triangle (counter-clockwise in the frame): a part of
      // positive length inside means the region's border crosses t.
      const Eigen::Vector2d a = edges[i].second[0], d = edges[i].second[1] - a;
      double lo = 0, hi = 1;
      for (int k = 0; k < 3 && lo < hi; ++k) {
        const Eigen::Vector2d e = tt[(k + 1) % 3] - tt[k];
        const double at = cross(e, a - tt[k]), slope = cross(e, d);
        const double margin = 1e-12 * scale * e.norm();
        if (slope == 0) {
          if (at <= margin) hi = lo;
        } else if (slope > 0) {
          lo = (std::max)(lo, (margin - at) / slope);
        } else {
          hi = (std::min)(hi, (margin - at) / slope);
        }
      }
      if (hi - lo > 1e-12) return false;
    }
    i = j;
  }
  return true;
}

// A triangle of a patch with the exact reference samples at its corners.
struct Sampled_triangle {
  Triangle_corners corners;
  std::array<Reference_sample, 3> samples;
};

// True when every point of the triangles is provably within `limit` of the reference: a triangle
// passes when its farthest corner plus its covering radius stays within (the distance is
// 1-Lipschitz), or when one reference triangle is within `limit` of all three corners (the
// distance to a triangle is convex); the others are split in four, `sample(x)` giving the new
// corners, at most `depth` times and for at most `budget` samples in all; whole triangles may also
// pass `flat(corners)`. The grid is refined level
// by level, so a point farther than `limit` refuses early (exact); running out of levels or
// samples refuses too (conservative). `reference(t)` gives reference triangle t.
template <typename Sample, typename Reference, typename Flat>
bool triangles_within(std::vector<Sampled_triangle> level, double limit, int depth,
                      std::size_t budget, const Sample& sample, const Reference& reference,
                      const Flat& flat) {
  const double limit2 = limit * limit;
  std::vector<Sampled_triangle> next;
  for (int d = 0; !level.empty(); ++d) {
    for (const Sampled_triangle& t : level)
      for (const Reference_sample& s : t.samples)
        if (s.distance > limit) return false;
    next.clear();
    for (const Sampled_triangle& t : level) {
      const Eigen::Vector3d &a = t.corners[0], &b = t.corners[1], &c = t.corners[2];
      const double worst =
          (std::max)({t.samples[0].distance, t.samples[1].distance, t.samples[2].distance});
      if (worst + covering_radius(a, b, c) <= limit) continue;
      bool covered = false;
      for (const Reference_sample& s : t.samples) {
        if (s.triangle == Reference_sample::kNoTriangle) continue;
        const Triangle_corners& r = reference(s.triangle);
        if (squared_distance_to_triangle(a, r) <= limit2 &&
            squared_distance_to_triangle(b, r) <= limit2 &&
            squared_distance_to_triangle(c, r) <= limit2) {
          covered = true;
          break;
        }
      }
      if (covered || (d == 0 && flat(t.corners))) continue;
      if (d == depth || budget < 3) return false;
      budget -= 3;
      const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
      const Reference_sample sab = sample(ab), sbc = sample(bc), sca = sample(ca);
      const auto& s = t.samples;
      next.push_back({{a, ab, ca}, {s[0], sab, sca}});
      next.push_back({{ab, b, bc}, {sab, s[1], sbc}});
      next.push_back({{ca, bc, c}, {sca, sbc, s[2]}});
      next.push_back({{ab, bc, ca}, {sab, sbc, sca}});
    }
    level.swap(next);
  }
  return true;
}

// A piece of a reference triangle and the triangle of a patch that covers it.
struct Piece_cover {
  Triangle_corners piece;
  std::uint32_t source;  // the index the piece had before, or kNewPiece when it was split
  std::size_t triangle;  // index into the patch's triangles
};
constexpr std::uint32_t kNewPiece = 0xffffffffu;

// Appends to `covers` how the piece is covered by single triangles of `patch` within `limit`,
// splitting it at most `depth` times; false when that fails. `hint` is the triangle tried first.
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

// The largest distance from a corner of the pieces (at most about `budget` of them, evenly spread)
// to the patch: a lower bound of the one-sided Hausdorff distance, returned early once it reaches
// `stop`.
inline double corner_distance_lower_bound(const std::vector<Triangle_corners>& pieces,
                                          const std::vector<Triangle_corners>& patch, double stop,
                                          std::size_t budget) {
  double worst2 = 0;
  const double stop2 = stop * stop;
  const std::size_t stride = (std::max)(std::size_t(1), pieces.size() / budget);
  for (std::size_t i = 0; i < pieces.size(); i += stride)
    for (const Eigen::Vector3d& corner : pieces[i]) {
      double nearest2 = std::numeric_limits<double>::infinity();
      for (const Triangle_corners& t : patch) {
        nearest2 = (std::min)(nearest2, squared_distance_to_triangle(corner, t));
        if (nearest2 <= worst2) break;
      }
      worst2 = (std::max)(worst2, nearest2);
      if (worst2 >= stop2) return std::sqrt(worst2);
    }
  return std::sqrt(worst2);
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PATCH_DISTANCE_H
