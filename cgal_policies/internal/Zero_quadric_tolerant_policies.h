// CGAL's Garland-Heckbert policies, unchanged but for one precondition: a vertex whose faces all
// have zero area has a zero plane quadric, which CGAL's Debug builds refuse
// (GarlandHeckbert_policy_base.h) although the cost and the placement are well defined: the
// other vertex's quadric alone. Such an edge is priced and placed as CGAL's Release build does.
#ifndef CGAL_POLICIES_INTERNAL_ZERO_QUADRIC_TOLERANT_POLICIES_H
#define CGAL_POLICIES_INTERNAL_ZERO_QUADRIC_TOLERANT_POLICIES_H

#include <cgal_policies/internal/cgal_version.h>

namespace cgal_policies {
namespace internal {

template <typename Policies>
class Zero_quadric_tolerant_policies : public Policies {
 public:
  using Policies::Policies;

  const Zero_quadric_tolerant_policies& get_cost() const { return *this; }
  const Zero_quadric_tolerant_policies& get_placement() const { return *this; }

  template <typename Profile>
  Optional<typename Profile::FT> operator()(
      const Profile& profile, const Optional<typename Profile::Point>& placement) const {
    if (!placement || !has_zero_quadric(profile)) return Policies::operator()(profile, placement);
    const auto p = Policies::point_to_homogenous_column(*placement);
    return typename Profile::FT((p.transpose() * combined(profile) * p)(0, 0));
  }

  template <typename Profile>
  Optional<typename Profile::Point> operator()(const Profile& profile) const {
    if (!has_zero_quadric(profile)) return Policies::operator()(profile);
    const auto optimum = Policies::construct_optimum(
        combined(profile), Policies::point_to_homogenous_column(profile.p0()),
        Policies::point_to_homogenous_column(profile.p1()));
    return typename Profile::Point(optimum(0) / optimum(3), optimum(1) / optimum(3),
                                   optimum(2) / optimum(3));
  }

 private:
  template <typename Profile>
  bool has_zero_quadric(const Profile& profile) const {
    return get(this->vcm(), profile.v0()).isZero(0) || get(this->vcm(), profile.v1()).isZero(0);
  }

  template <typename Profile>
  auto combined(const Profile& profile) const {
    return
        typename Policies::Mat_4(get(this->vcm(), profile.v0()) + get(this->vcm(), profile.v1()));
  }
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_ZERO_QUADRIC_TOLERANT_POLICIES_H
