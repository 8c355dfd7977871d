// A Filter for CGAL's edge_collapse that refuses a collapse turning a texture triangle over
// (Corner_attribute_carrier.h), then asks the wrapped filter, and tells the carrier the point the
// wrapped filter accepted (Hausdorff_bounded_filter picks one of its own). Without a carrier it is
// the wrapped filter.
#ifndef CGAL_POLICIES_SEAM_KEEPING_FILTER_H
#define CGAL_POLICIES_SEAM_KEEPING_FILTER_H

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/internal/cgal_version.h>

namespace cgal_policies {

template <class Point, class BaseFilter>
class Seam_keeping_filter {
 public:
  Seam_keeping_filter(const BaseFilter& base, const Corner_attribute_carrier<Point>* carrier)
      : m_base(base), m_carrier(carrier) {}

  // Last comes the wrapped filter, which may commit to what it accepts (Hausdorff_bounded_filter).
  template <class Profile>
  internal::Optional<Point> operator()(const Profile& profile,
                                       const internal::Optional<Point>& placement) const {
    if (!m_carrier) return m_base(profile, placement);
    if (placement && !m_carrier->keeps_uv_orientation(profile, *placement)) return {};
    const internal::Optional<Point> accepted = m_base(profile, placement);
    if (accepted) m_carrier->accepted(profile, *accepted);
    return accepted;
  }

 private:
  BaseFilter m_base;
  const Corner_attribute_carrier<Point>* m_carrier;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SEAM_KEEPING_FILTER_H
