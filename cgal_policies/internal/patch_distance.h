// Conservative distance tests between small triangle sets, for the Hausdorff-bounded policies
// (policies.md §3). Two directions, two arguments:
// - A triangle is within `limit` of a reference surface when the distance at the corners of a
//   barycentric sample grid plus the grid's covering radius stays below `limit` (the distance to a
//   set is 1-Lipschitz). The grid is refined (n = 1, 2, 4, ...) only where the bound is not met.
// - A piece of the reference is within `limit` of one triangle T when its three corners are: the
//   distance to a convex set is convex, so its maximum over the piece is at a corner. A piece that
//   no single triangle covers is split in four and retried; failing that, it is cut exactly along
//   the edges of the new fan (which halving never achieves where the two are coplanar).
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

// The distance from a point to one triangle of the reference (kNoTriangle when unknown): an upper
// bound of its distance to the reference, which is all the tests below need.
struct Reference_sample {
  double distance = 0;
  std::size_t triangle = kNoTriangle;
  static constexpr std::size_t kNoTriangle = std::size_t(-1);
};

// The plane of a triangle t seen from above, for the flatness argument: reference triangles that
// lie within `limit` of t's plane and face its way project onto it without folding, and when the
// projection of a set K of them covers t's, the point of K above any point of t is within `limit`
// of it. The projection covers t's when it holds t's centroid and no edge of K that is not shared
// by two triangles of K crosses the inside of t: a point of t left uncovered would be cut off from
// the centroid by such an edge.
class Flat_frame {
 public:
  Flat_frame(const Triangle_corners& t, double limit) : m_origin(t[0]), m_limit(limit) {
    const Eigen::Vector3d normal = (t[1] - t[0]).cross(t[2] - t[0]);
    const double twice_area = normal.norm();
    m_valid = twice_area > 0;
    if (!m_valid) return;
    m_n = normal / twice_area;
    m_u = (t[1] - t[0]).normalized();
    m_w = m_n.cross(m_u);
    m_scale = std::sqrt(twice_area);
    for (int k = 0; k < 3; ++k) m_t[k] = project(t[k]);
    m_centroid = (m_t[0] + m_t[1] + m_t[2]) / 3;
    m_min = m_t[0].cwiseMin(m_t[1]).cwiseMin(m_t[2]);
    m_max = m_t[0].cwiseMax(m_t[1]).cwiseMax(m_t[2]);
  }

  bool valid() const { return m_valid; }

  // Whether q's projection may meet t's: when not, no edge of q crosses t.
  bool may_meet(const Triangle_corners& q) const {
    Eigen::Vector2d lo = project(q[0]), hi = lo;
    for (int k = 1; k < 3; ++k) {
      const Eigen::Vector2d p = project(q[k]);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    return (lo.array() <= m_max.array()).all() && (hi.array() >= m_min.array()).all();
  }

  // Whether q is within `limit` of t's plane and faces its way.
  bool holds(const Triangle_corners& q) const {
    for (const Eigen::Vector3d& p : q)
      if (std::abs((p - m_origin).dot(m_n)) > m_limit) return false;
    return (q[1] - q[0]).cross(q[2] - q[0]).dot(m_n) > 0;
  }

  // Whether q's projection holds t's centroid (q must face t's way).
  bool holds_centroid(const Triangle_corners& q) const {
    const Eigen::Vector2d a = project(q[0]), b = project(q[1]), c = project(q[2]);
    return cross(b - a, m_centroid - a) >= 0 && cross(c - b, m_centroid - b) >= 0 &&
           cross(a - c, m_centroid - c) >= 0;
  }

  // Whether the segment ab has a part of positive length inside t (in projection), clipped to t
  // shrunk by a rounding margin.
  bool crosses(const Eigen::Vector3d& a3, const Eigen::Vector3d& b3) const {
    const Eigen::Vector2d a = project(a3), d = project(b3) - a;
    double lo = 0, hi = 1;
    for (int k = 0; k < 3 && lo < hi; ++k) {
      const Eigen::Vector2d e = m_t[(k + 1) % 3] - m_t[k];
      const double at = cross(e, a - m_t[k]), slope = cross(e, d);
      const double margin = 1e-12 * m_scale * e.norm();
      if (slope == 0) {
        if (at <= margin) hi = lo;
      } else if (slope > 0) {
        lo = (std::max)(lo, (margin - at) / slope);
      } else {
        hi = (std::min)(hi, (margin - at) / slope);
      }
    }
    return hi - lo > 1e-12;
  }

 private:
  static double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  }
  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - m_origin;
    return {d.dot(m_u), d.dot(m_w)};
  }

  Eigen::Vector3d m_origin, m_n, m_u, m_w;
  double m_limit;
  double m_scale = 0;
  bool m_valid = false;
  std::array<Eigen::Vector2d, 3> m_t;
  Eigen::Vector2d m_centroid, m_min, m_max;
};

// A triangle of a patch with the reference samples at its corners.
struct Sampled_triangle {
  Triangle_corners corners;
  std::array<Reference_sample, 3> samples;
};

// True when every point of the triangles is provably within `limit` of the reference: a triangle
// passes when its farthest corner plus its covering radius stays within (the distance is
// 1-Lipschitz), or when one reference triangle is within `limit` of all three corners (the
// distance to a triangle is convex); the others are split in four, `sample(x, hint)` giving the new
// corners, at most `depth` times and for at most `budget` samples in all; a triangle of any level
// may also pass `flat(triangle)`. The grid is refined level by level, so a point farther than
// `limit` refuses early (exact); running out of levels or samples refuses too (conservative).
// `reference(t)` gives reference triangle t.
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
      if (covered || flat(t)) continue;
      if (d == depth || budget < 3) return false;
      budget -= 3;
      const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
      const auto& s = t.samples;
      const Reference_sample sab = sample(ab, s[0].triangle), sbc = sample(bc, s[1].triangle),
                             sca = sample(ca, s[2].triangle);
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

// Cuts the piece along the edges of `fan`, triangles around `apex`, seen along the piece's normal,
// and appends the parts with the triangle each lies over, when every part is within `limit` of its
// triangle (all of it then is, by convexity). The parts tile the piece when the triangles all face
// the piece's way, turn at most once around the apex (so they do not overlap) and their areas add
// up to the piece's, up to round-off; otherwise false, with nothing appended. Exact where a piece
// and the fan are coplanar, which halving (cover_piece) only approaches.
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
