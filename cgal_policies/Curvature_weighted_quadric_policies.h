// Curvature_weighted_quadric_policies: the approximate-curvature quadric error metric of [Zhang09]
// (docs/curvature.md). K_s (eq. 9-10) is the mean cos(n_s, n_i) over the neighbours i of s, 1 on a
// plane; collapsing (s, t) to x costs (eq. 12, with a floor eps and the border planes outside f)
//     f * x~^T Q_face x~ + x~^T Q_border x~,   f = eps + 1 - (K_s + K_t) / 2,
// so flat regions go first. Placement: the optimum of Q_face + Q_border (the shared chain).
// Models CGAL's `GetCost` and `GetPlacement` in one object with `Update_tag` (state in dynamic
// vertex properties); pair it with a flip filter. Parameters: Curvature_weighted_options.
// Usage:
//   cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(mesh);
//   SMS::edge_collapse(mesh, stop,
//                      CGAL::parameters::get_cost(policies.get_cost())
//                          .get_placement(policies.get_placement()));
#ifndef CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H
#define CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H

#include <cgal_policies/Curvature_weighted_options.h>
#include <cgal_policies/internal/Quadric_policy_base.h>
#include <cgal_policies/internal/approximate_curvature.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Curvature_weighted_quadric_policies
    : public internal::Quadric_policy_base<
          TriangleMesh, GeomTraits, Curvature_weighted_quadric_policies<TriangleMesh, GeomTraits>,
          true> {
  using Base = internal::Quadric_policy_base<TriangleMesh, GeomTraits,
                                             Curvature_weighted_quadric_policies, true>;
  friend Base;
  using Normal_property = CGAL::dynamic_vertex_property_t<internal::Stored_normal>;
  using Normal_map = typename boost::property_map<TriangleMesh, Normal_property>::type;
  using Curvature_property = CGAL::dynamic_vertex_property_t<double>;
  using Curvature_map = typename boost::property_map<TriangleMesh, Curvature_property>::type;

 public:
  using vertex_descriptor = typename Base::vertex_descriptor;

  // Weight of the shorter-edge-first term, per squared edge length (|e|^4 with area weights): far
  // below any real weighted error (f >= eps), so it only orders exact ties.
  static constexpr double tie_break_weight = 1e-12;

  explicit Curvature_weighted_quadric_policies(TriangleMesh& tm,
                                               const Curvature_weighted_options& options = {})
      : Base(tm, options),
        m_normals(get(Normal_property(), tm)),
        m_curvatures(get(Curvature_property(), tm)),
        m_eps(options.literal ? 0.0 : options.eps),
        m_literal(options.literal) {
    CGAL_precondition(options.eps >= 0);
  }

  // K of v as last refreshed (tests, reports); valid after `initialize`.
  double approximate_curvature(vertex_descriptor v) const { return get(m_curvatures, v); }

  // The clamp absorbs round-off that lifts K a hair above 1 on a plane.
  double curvature_factor(vertex_descriptor v0, vertex_descriptor v1) const {
    return m_eps + (std::max)(0.0, 1.0 - 0.5 * (get(m_curvatures, v0) + get(m_curvatures, v1)));
  }

 private:
  template <typename VertexPointMap>
  void initialize_features(const TriangleMesh& tm, const VertexPointMap& vpm) const {
    internal::compute_approximate_curvatures(tm, vpm, m_normals, m_curvatures);
  }

  // Only the faces around `kept` moved, so only its normal and its neighbours' changed.
  template <typename Profile>
  void update_features(const Profile& profile, vertex_descriptor kept) const {
    const TriangleMesh& tm = profile.surface_mesh();
    const auto vpm = profile.vertex_point_map();
    put(m_normals, kept, internal::curvature_vertex_normal(kept, tm, vpm));
    for (auto h : CGAL::halfedges_around_target(halfedge(kept, tm), tm))
      put(m_normals, source(h, tm), internal::curvature_vertex_normal(source(h, tm), tm, vpm));
    put(m_curvatures, kept, internal::approximate_curvature(kept, tm, m_normals));
    for (auto h : CGAL::halfedges_around_target(halfedge(kept, tm), tm))
      put(m_curvatures, source(h, tm),
          internal::approximate_curvature(source(h, tm), tm, m_normals));
  }

  template <typename Profile>
  double cost_of(const Profile& profile, double face_error, double border_error) const {
    const double f = curvature_factor(profile.v0(), profile.v1());
    const double weighted =
        m_literal ? f * (face_error + border_error) : f * face_error + border_error;
    const double length2 =
        (internal::to_eigen(profile.p1()) - internal::to_eigen(profile.p0())).squaredNorm();
    const bool area_weights = this->quadric_options().face_weighting == Face_weighting::area;
    return weighted + tie_break_weight * length2 * (area_weights ? length2 : 1.0);
  }

  Normal_map m_normals;
  Curvature_map m_curvatures;
  double m_eps;
  bool m_literal;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H
