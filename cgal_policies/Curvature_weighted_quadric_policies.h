// Curvature_weighted_quadric_policies: the approximate-curvature quadric error metric of
// [Zhang09] (docs/curvature.md).
//
// - Vertex normal n_s: the normalised sum of the unit normals of the faces around s.
// - Approximate curvature K_s (eq. 9-10): the mean, over the neighbours i of s, of cos(n_s, n_i).
//   It is 1 on a plane and falls as the surface bends.
// - Cost of collapsing (s, t) to x (eq. 12, with a floor):
//     f * x~^T Q_face x~ + x~^T Q_border x~,   f = eps + 1 - (K_s + K_t) / 2,
//   so flat regions (f near eps) collapse first and curved detail stays. The border planes stay
//   outside the factor, so that a flat border keeps its protection.
// - Placement: the optimum of the unweighted quadric Q_face + Q_border (the placement chain of
//   Classic_quadric_policies); the kept vertex gets the sums of both quadrics.
// - After each collapse the normals and K of the kept vertex and of its neighbours are refreshed;
//   CGAL then recomputes the cost of every edge that touches them.
// - Ties: on a plane the weighted error is exactly zero for many edges; a term
//   tie_break_weight * |e|^2 (|e|^4 with area weights, to keep the units of the quadrics) lets the
//   shorter edge go first there, so that the order is geometric and the triangles stay even.
//
// Literal mode is eq. 12 as printed: eps = 0 and f scales the border quadric too. Then a symmetric
// sawtooth, whose vertex normals are all parallel, costs nothing, and flat borders lose their
// protection; the default floor eps keeps real relief from being free.
//
// Models CGAL's `GetCost` and `GetPlacement` concepts (one object, as CGAL's
// GarlandHeckbert_plane_policies); its state lives in dynamic vertex properties, so the mesh gains
// no visible property, and `Update_tag` makes `edge_collapse` call `initialize` and
// `update_after_collapse`. Pair it with a flip filter such as Bounded_normal_angle_filter.
//
// Parameters: Curvature_weighted_options (eps, literal, and the shared Quadric_options).
//
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

  // Weight of the shorter-edge-first term, relative to a squared edge length: far below any real
  // weighted error (f >= eps times a squared distance), so it only orders exact ties.
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

  // For inspection (tests, reports): K of v as last refreshed, after `initialize`.
  double approximate_curvature(vertex_descriptor v) const { return get(m_curvatures, v); }

  // The factor f that weights the quadric of the edge (v0, v1). Round-off can lift K a hair above
  // 1 on a plane, hence the clamp.
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

  // f scales the face planes only (both in literal mode); the tie-break orders exact ties.
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
