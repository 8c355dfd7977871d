// Curvature_weighted_quadric_policies: the approximate-curvature quadric error metric of Zhang, Liu
// and Guan (2009; seed 004), as policies.md §1 specifies it.
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
// `update_after_collapse`.
//
// Parameters:
//   eps            floor of the curvature factor f, dimensionless (default 1e-3); ignored when
//                  literal is set
//   border_weight  weight W_b of a border plane (default 1000; with area weighting it is multiplied
//                  by the squared edge length so that it keeps the units of a face quadric)
//   face_weighting Face_weighting::unit (default, as the papers) or Face_weighting::area
//   literal        false (default) or true: eps = 0 and the border quadric scaled by f (eq. 12)
//
// Usage:
//   cgal_policies::Curvature_weighted_quadric_policies<Mesh, Kernel> policies(mesh);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost())
//                                                   .get_placement(policies.get_placement()));
#ifndef CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H
#define CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/approximate_curvature.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#include <algorithm>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Curvature_weighted_quadric_policies {
  using Quadric_property = CGAL::dynamic_vertex_property_t<internal::Quadric>;
  using Quadric_map = typename boost::property_map<TriangleMesh, Quadric_property>::type;
  using Normal_property = CGAL::dynamic_vertex_property_t<internal::Stored_normal>;
  using Normal_map = typename boost::property_map<TriangleMesh, Normal_property>::type;
  using Curvature_property = CGAL::dynamic_vertex_property_t<double>;
  using Curvature_map = typename boost::property_map<TriangleMesh, Curvature_property>::type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

 public:
  using Update_tag = CGAL::Tag_true;
  using Get_cost = Curvature_weighted_quadric_policies;
  using Get_placement = Curvature_weighted_quadric_policies;
  using FT = typename GeomTraits::FT;

  // Weight of the shorter-edge-first term, relative to a squared edge length: far below any real
  // weighted error (f >= eps = 1e-3 times a squared distance), so it only orders exact ties.
  static constexpr double tie_break_weight = 1e-12;

  explicit Curvature_weighted_quadric_policies(TriangleMesh& tm, double eps = 1e-3,
                                               double border_weight = 1000.0,
                                               Face_weighting face_weighting = Face_weighting::unit,
                                               bool literal = false)
      : m_face_quadrics(get(Quadric_property(), tm)),
        m_border_quadrics(get(Quadric_property(), tm)),
        m_normals(get(Normal_property(), tm)),
        m_curvatures(get(Curvature_property(), tm)),
        m_eps(literal ? 0.0 : eps),
        m_border_weight(border_weight),
        m_face_weighting(face_weighting),
        m_literal(literal) {}

  const Get_cost& get_cost() const { return *this; }
  const Get_placement& get_placement() const { return *this; }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits&) const {
    internal::accumulate_vertex_quadrics(tm, vpm, m_face_weighting, m_border_weight,
                                         m_face_quadrics, m_border_quadrics);
    internal::compute_approximate_curvatures(tm, vpm, m_normals, m_curvatures);
  }

  template <typename Profile>
  void update_after_collapse(const Profile& profile, vertex_descriptor kept) const {
    put(m_face_quadrics, kept,
        get(m_face_quadrics, profile.v0()) + get(m_face_quadrics, profile.v1()));
    put(m_border_quadrics, kept,
        get(m_border_quadrics, profile.v0()) + get(m_border_quadrics, profile.v1()));

    // Only the faces around `kept` moved, so only its normal and its neighbours' changed.
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

  // Cost.
  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    const Eigen::Vector3d x = internal::to_eigen(*placement);
    const double f = curvature_factor(profile.v0(), profile.v1());
    // Round-off can dip a quadric's value below zero.
    const double face_error = (std::max)(0.0, face_quadric(profile).evaluate(x));
    const double border_error = (std::max)(0.0, border_quadric(profile).evaluate(x));
    const double weighted =
        m_literal ? f * (face_error + border_error) : f * face_error + border_error;
    const double length2 =
        (internal::to_eigen(profile.p1()) - internal::to_eigen(profile.p0())).squaredNorm();
    const double tie_break =
        tie_break_weight * length2 * (m_face_weighting == Face_weighting::area ? length2 : 1.0);
    return typename Profile::FT(weighted + tie_break);
  }

  // Placement.
  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const internal::Quadric_placement choice = internal::optimal_placement(
        face_quadric(profile) + border_quadric(profile), internal::to_eigen(profile.p0()),
        internal::to_eigen(profile.p1()));
    return internal::to_point<typename Profile::Point>(choice.point);
  }

  // For inspection (tests, reports): K of v as last refreshed, after `initialize`.
  double approximate_curvature(vertex_descriptor v) const { return get(m_curvatures, v); }

  // The factor f that weights the quadric of the edge (v0, v1). Round-off can lift K a hair above
  // 1 on a plane, hence the clamp.
  double curvature_factor(vertex_descriptor v0, vertex_descriptor v1) const {
    return m_eps + (std::max)(0.0, 1.0 - 0.5 * (get(m_curvatures, v0) + get(m_curvatures, v1)));
  }

 private:
  template <typename Profile>
  internal::Quadric face_quadric(const Profile& profile) const {
    return get(m_face_quadrics, profile.v0()) + get(m_face_quadrics, profile.v1());
  }
  template <typename Profile>
  internal::Quadric border_quadric(const Profile& profile) const {
    return get(m_border_quadrics, profile.v0()) + get(m_border_quadrics, profile.v1());
  }

  Quadric_map m_face_quadrics;
  Quadric_map m_border_quadrics;
  Normal_map m_normals;
  Curvature_map m_curvatures;
  double m_eps;
  double m_border_weight;
  Face_weighting m_face_weighting;
  bool m_literal;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CURVATURE_WEIGHTED_QUADRIC_POLICIES_H
