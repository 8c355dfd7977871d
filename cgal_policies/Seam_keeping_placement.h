// A GetPlacement for CGAL's edge_collapse that keeps the seams of the mesh's corner attributes: it
// takes the wrapped policy's point where no seam is near, the point of a seam vertex where one end
// of the edge is on a seam, and refuses a collapse that would tear or slide a seam
// (Corner_attribute_carrier.h has the rules). Without a carrier it is the wrapped placement.
#ifndef CGAL_POLICIES_SEAM_KEEPING_PLACEMENT_H
#define CGAL_POLICIES_SEAM_KEEPING_PLACEMENT_H

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/internal/cgal_version.h>

namespace cgal_policies {

template <class Point, class BasePlacement>
class Seam_keeping_placement {
 public:
  Seam_keeping_placement(const BasePlacement& base, const Corner_attribute_carrier<Point>* carrier)
      : m_base(base), m_carrier(carrier) {}

  template <class Profile>
  internal::Optional<Point> operator()(const Profile& profile) const {
    const internal::Optional<Point> proposed = m_base(profile);
    if (!proposed || !m_carrier) return proposed;
    const std::optional<Point> kept = m_carrier->seam_placement(profile, *proposed);
    if (!kept) return {};
    return *kept;
  }

 private:
  BasePlacement m_base;
  const Corner_attribute_carrier<Point>* m_carrier;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SEAM_KEEPING_PLACEMENT_H
