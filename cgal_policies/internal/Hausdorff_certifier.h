// Ranking and conservative two-sided certification of a Hausdorff-bounded change's candidates
// (docs/hausdorff.md, "Conservative two-sided certification", "Ranking the candidates").
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_CERTIFIER_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_CERTIFIER_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Hausdorff_patch.h>
#include <cgal_policies/internal/patch_distance.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// Candidates are ranked on the corners of this many pieces at most: a lower bound all the same.
constexpr std::size_t kRankingPieces = 32;
// A patch that needs more reference samples than this to be certified is refused.
constexpr std::size_t kSampleBudget = 600;
// Only the best few candidates are put to the full test: the others rarely pass when they fail.
constexpr std::size_t kMaxCertified = 3;

struct Ranked_candidate {
  double bound;               // a lower bound of the two-sided distance
  Reference_sample distance;  // from the candidate to the reference
  std::size_t index;          // into the candidates
};

class Hausdorff_certifier {
 public:
  Hausdorff_certifier(const Hausdorff_input_surface& input, Hausdorff_reference reference,
                      int max_refinement)
      : m_input(&input),
        m_global(reference == Hausdorff_reference::global),
        m_max_refinement(max_refinement) {}

  double tolerance() const { return m_input->tolerance(); }

  // The nearest point of the patch's reference: the input, or the patch before the change. `hint`
  // is an input triangle near p (global reference).
  template <typename Patch>
  Reference_sample sample(const Patch& patch, const Eigen::Vector3d& p, std::size_t hint) const {
    if (m_global) return m_input->nearest(p, hint);
    Reference_sample nearest{std::numeric_limits<double>::infinity(), 0};
    for (std::size_t t = 0; t < patch.reference.size(); ++t) {
      const double d2 = squared_distance_to_triangle(p, patch.reference[t]);
      if (d2 < nearest.distance) nearest = {d2, t};
    }
    nearest.distance = std::sqrt(nearest.distance);
    return nearest;
  }

  // Those within the tolerance that `acceptable` lets through, smallest bound first, at most
  // kMaxCertified; a candidate's walk starts from the hint of the nearer end, p0 or p1.
  template <typename Patch, typename Acceptable>
  std::vector<Ranked_candidate> rank(const Patch& patch,
                                     const std::vector<Eigen::Vector3d>& candidates,
                                     const Eigen::Vector3d& p0, std::size_t hint0,
                                     const Eigen::Vector3d& p1, std::size_t hint1,
                                     const Acceptable& acceptable) const {
    const double tolerance = m_input->tolerance();
    std::vector<Ranked_candidate> ranked;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const Eigen::Vector3d& p = candidates[i];
      // The cheapest refusals first: the pieces' corners, the flip check, then p's distance.
      const double stop = (std::min)(best, tolerance);
      const double pieces_bound =
          corner_distance_lower_bound(patch.pieces, moved(patch, p), stop, kRankingPieces);
      if (pieces_bound > tolerance || !acceptable(p)) continue;
      const bool nearer_v0 = (p - p0).squaredNorm() <= (p - p1).squaredNorm();
      const Reference_sample d = sample(patch, p, nearer_v0 ? hint0 : hint1);
      const double bound = (std::max)(d.distance, pieces_bound);
      if (bound > tolerance) continue;
      best = (std::min)(best, bound);
      ranked.push_back({bound, d, i});
    }
    std::stable_sort(
        ranked.begin(), ranked.end(),
        [](const Ranked_candidate& a, const Ranked_candidate& b) { return a.bound < b.bound; });
    if (ranked.size() > kMaxCertified) ranked.resize(kMaxCertified);
    return ranked;
  }

  template <typename Patch>
  bool certify(const Patch& patch, const Eigen::Vector3d& p, const Reference_sample& d_p,
               std::vector<Piece_cover>& covers) const {
    const double tolerance = m_input->tolerance();
    const std::vector<Triangle_corners> after = moved(patch, p);
    const auto sample_at = [&](const Eigen::Vector3d& x, std::size_t hint) {
      return sample(patch, x, hint);
    };
    const auto reference = [&](std::size_t t) -> const Triangle_corners& {
      return m_global ? m_input->corners(t) : patch.reference[t];
    };
    std::vector<Sampled_triangle> triangles;
    for (std::size_t j = 0; j < after.size(); ++j) {
      std::array<Reference_sample, 3> d = patch.corner_distances[j];
      for (int k = 0; k < 3; ++k)
        if (patch.moving[j][k]) d[k] = d_p;
      triangles.push_back({after[j], d});
    }
    const auto flat = [&](const Sampled_triangle& t) {
      return m_global && m_input->flat_covers(t);
    };
    if (!triangles_within(std::move(triangles), tolerance, m_max_refinement, kSampleBudget,
                          sample_at, reference, flat))
      return false;
    std::size_t hint = 0;
    for (std::size_t i = 0; i < patch.pieces.size(); ++i) {
      const std::size_t before = covers.size();
      if (cover_piece(patch.pieces[i], patch.piece_sources[i], after, tolerance, m_max_refinement,
                      hint, covers))
        continue;
      covers.resize(before);
      if (!cover_piece_along_fan(patch.pieces[i], after, p, tolerance, covers)) return false;
    }
    return true;
  }

 private:
  const Hausdorff_input_surface* m_input;
  bool m_global;
  int m_max_refinement;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_CERTIFIER_H
