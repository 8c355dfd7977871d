// The engine every quadric policy shares (docs/quadric_core.md), as CGAL's
// GarlandHeckbert_policy_base: per-vertex quadrics, their sums after a collapse, clamped errors and
// the placement chain. A policy derives from it (CRTP) as CGAL's `GetCost` and `GetPlacement` with
// `Update_tag`, and may override cost_of (from the clamped errors; default: their sum) and
// initialize_features / update_features (its own state, after the quadrics'). With
// KeepsBorderPlanesApart, border quadrics are kept apart so that a factor never scales them.
#ifndef CGAL_POLICIES_INTERNAL_QUADRIC_POLICY_BASE_H
#define CGAL_POLICIES_INTERNAL_QUADRIC_POLICY_BASE_H

#include <cgal_policies/Quadric_options.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <type_traits>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh, typename GeomTraits, typename Derived, bool KeepsBorderPlanesApart>
class Quadric_policy_base {
  using Quadric_property = CGAL::dynamic_vertex_property_t<Quadric>;
  using Quadric_map = typename boost::property_map<TriangleMesh, Quadric_property>::type;
  struct No_border_quadrics {};
  using Border_quadric_map =
      std::conditional_t<KeepsBorderPlanesApart, Quadric_map, No_border_quadrics>;

 public:
  using Update_tag = CGAL::Tag_true;
  using Get_cost = Derived;
  using Get_placement = Derived;
  using FT = typename GeomTraits::FT;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  const Get_cost& get_cost() const { return derived(); }
  const Get_placement& get_placement() const { return derived(); }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits&) const {
    if constexpr (KeepsBorderPlanesApart)
      accumulate_vertex_quadrics(tm, vpm, m_options.face_weighting, m_options.border_weight,
                                 m_face_quadrics, m_border_quadrics);
    else
      accumulate_vertex_quadrics(tm, vpm, m_options.face_weighting, m_options.border_weight,
                                 m_face_quadrics, m_face_quadrics);
    derived().initialize_features(tm, vpm);
  }

  template <typename Profile>
  void update_after_collapse(const Profile& profile, vertex_descriptor kept) const {
    put(m_face_quadrics, kept, face_quadric(profile));
    if constexpr (KeepsBorderPlanesApart) put(m_border_quadrics, kept, border_quadric(profile));
    derived().update_features(profile, kept);
  }

  // Cost.
  template <typename Profile>
  Optional<typename Profile::FT> operator()(
      const Profile& profile, const Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    const Eigen::Vector3d x = to_eigen(*placement);
    const double face_error = clamped(face_quadric(profile).evaluate(x));
    double border_error = 0;
    if constexpr (KeepsBorderPlanesApart)
      border_error = clamped(border_quadric(profile).evaluate(x));
    return typename Profile::FT(derived().cost_of(profile, face_error, border_error));
  }

  // Placement.
  template <typename Profile>
  Optional<typename Profile::Point> operator()(const Profile& profile) const {
    Quadric quadric = face_quadric(profile);
    if constexpr (KeepsBorderPlanesApart) quadric += border_quadric(profile);
    const Quadric_placement choice =
        optimal_placement(quadric, to_eigen(profile.p0()), to_eigen(profile.p1()));
    return to_point<typename Profile::Point>(choice.point);
  }

  const Quadric_options& quadric_options() const { return m_options; }

 protected:
  Quadric_policy_base(TriangleMesh& tm, const Quadric_options& options)
      : m_face_quadrics(get(Quadric_property(), tm)),
        m_border_quadrics(border_quadric_map(tm)),
        m_options(options) {
    CGAL_precondition(options.border_weight >= 0);
  }

  template <typename Profile>
  double cost_of(const Profile&, double face_error, double border_error) const {
    return face_error + border_error;
  }
  template <typename VertexPointMap>
  void initialize_features(const TriangleMesh&, const VertexPointMap&) const {}
  template <typename Profile>
  void update_features(const Profile&, vertex_descriptor) const {}

 private:
  const Derived& derived() const { return static_cast<const Derived&>(*this); }

  static Border_quadric_map border_quadric_map(TriangleMesh& tm) {
    if constexpr (KeepsBorderPlanesApart)
      return get(Quadric_property(), tm);
    else
      return {};
  }

  // A quadric is positive semi-definite; round-off can still dip its value below zero.
  static double clamped(double error) { return (std::max)(0.0, error); }

  template <typename Profile>
  Quadric face_quadric(const Profile& profile) const {
    return get(m_face_quadrics, profile.v0()) + get(m_face_quadrics, profile.v1());
  }
  template <typename Profile>
  Quadric border_quadric(const Profile& profile) const {
    return get(m_border_quadrics, profile.v0()) + get(m_border_quadrics, profile.v1());
  }

  Quadric_map m_face_quadrics;  // with the border planes too, unless kept apart
  Border_quadric_map m_border_quadrics;
  Quadric_options m_options;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_QUADRIC_POLICY_BASE_H
