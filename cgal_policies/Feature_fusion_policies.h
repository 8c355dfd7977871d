// Feature_fusion_policies: the multi-feature fusion cost of Wang et al. 2013 (seed 000), a quadric
// error weighted by the normal variation plus a visual term, the normal twist weighted by the
// triangles' side ratio (policies.md §2).
//
//   Cost_all = C_geom + C_visu                          (the paper's eq. 3)
//   C_geom   = (1 + mu * omega(e)) * x~^T (Q0 + Q1) x~  (ours)
//   C_visu   = w_v * zeta(e) * T(e) * L0^2               (the paper's zeta * T; w_v and L0^2 ours)
//
// What is the paper's and what is ours: the paper gives eq. 3, the QEM of eqs. 1-2 and the side
// ratio zeta of eq. 9 (edge length over the sum of the other edges of its two triangles, or of
// its one triangle on a border), implemented exactly; it says in words that normals weight the
// quadric and that zeta weights a torsion, but its eqs. 4-8 (the normal weight and the torsion)
// are missing from the text. The rest is our reconstruction:
//   omega(e) = max(thbar(v0), thbar(v1)), thbar(v) the mean angle (radians) between the
//     area-weighted normal of v and those of its neighbours; the factor 1 + mu omega is >= 1, so
//     it never discounts real error;
//   T(e) = max(T(v0), T(v1)), T(v) the mean |normal twist| along the edges around v, the twist
//     being (n_j - n_v) . (nbar x t) (about the geodesic torsion times the edge length): zero on
//     planes and spheres, large where the surface twists (saddles, anisotropic curvature);
//   L0, the mean edge length of the input, gives C_visu the units of the quadric, so the whole cost
//     is scale-invariant.
// Placement is the quadric's optimum (the shared chain of policies.md §0); the merged vertex keeps
// Q0 + Q1. After each collapse the normals of the kept vertex and its neighbours, and thbar and T
// one ring further, are recomputed.
//
// Models CGAL's `GetCost` and `GetPlacement` concepts (one object, as CGAL's
// GarlandHeckbert_plane_policies); its state lives in dynamic vertex properties, so the mesh gains
// no visible property, and `Update_tag` makes `edge_collapse` call `initialize` and
// `update_after_collapse`. Pair it with a flip filter such as Bounded_normal_angle_filter.
//
// Parameters:
//   mu             weight of the normal variation, per radian (default 2)
//   visual_weight  w_v, weight of the visual term (default 0: off; every weight tried raised the
//                  mean error, see scripts/sweep_fusion.sh)
//   border_weight  weight W_b of a border plane, as in Classic_quadric_policies (default 1000)
//
// Usage:
//   cgal_policies::Feature_fusion_policies<Mesh, Kernel> policies(mesh);
//   cgal_policies::Bounded_normal_angle_filter<> filter;
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost())
//                                                   .get_placement(policies.get_placement())
//                                                   .filter(filter));
#ifndef CGAL_POLICIES_FEATURE_FUSION_POLICIES_H
#define CGAL_POLICIES_FEATURE_FUSION_POLICIES_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/feature_fusion_measures.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Feature_fusion_policies {
  template <typename T>
  using Vertex_map =
      typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<T>>::type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  // Everything the cost reads about a vertex besides its quadric, in one property.
  struct Vertex_features {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // area-weighted, unit
    double normal_angle = 0;                           // thbar(v), radians
    double twist = 0;                                  // T(v)
    std::size_t stamp = 0;                             // the last update that refreshed thbar, T
  };

 public:
  using Update_tag = CGAL::Tag_true;
  using Get_cost = Feature_fusion_policies;
  using Get_placement = Feature_fusion_policies;
  using FT = typename GeomTraits::FT;

  // The defaults chosen by scripts/sweep_fusion.sh.
  static constexpr double default_mu = 2.0;
  static constexpr double default_visual_weight = 0.0;

  explicit Feature_fusion_policies(TriangleMesh& tm, double mu = default_mu,
                                   double visual_weight = default_visual_weight,
                                   double border_weight = 1000.0)
      : m_quadrics(get(CGAL::dynamic_vertex_property_t<internal::Quadric>(), tm)),
        m_features(get(CGAL::dynamic_vertex_property_t<Vertex_features>(), tm)),
        m_mu(mu),
        m_visual_weight(visual_weight),
        m_border_weight(border_weight) {}

  const Get_cost& get_cost() const { return *this; }
  const Get_placement& get_placement() const { return *this; }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits&) const {
    internal::accumulate_vertex_quadrics(tm, vpm, Face_weighting::unit, m_border_weight, m_quadrics,
                                         m_quadrics);
    m_input_edge_length = internal::mean_edge_length(tm, vpm);
    m_stamp = 0;
    for (vertex_descriptor v : vertices(tm)) {
      Vertex_features features;
      features.normal = internal::vertex_normal(v, tm, vpm, internal::Normal_weighting::area);
      put(m_features, v, features);
    }
    for (vertex_descriptor v : vertices(tm)) refresh_features(v, tm, vpm);
  }

  template <typename Profile>
  void update_after_collapse(const Profile& profile, vertex_descriptor kept) const {
    put(m_quadrics, kept, edge_quadric(profile));
    const TriangleMesh& tm = profile.surface_mesh();
    const auto vpm = profile.vertex_point_map();
    // The faces around the kept vertex moved: the normals of the vertex and its neighbours change,
    // and thbar and T read the neighbours' normals, so they change one ring further.
    const auto ring = CGAL::vertices_around_target(halfedge(kept, tm), tm);
    refresh_normal(kept, tm, vpm);
    for (vertex_descriptor j : ring) refresh_normal(j, tm, vpm);
    ++m_stamp;
    for (vertex_descriptor j : ring)
      for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(j, tm), tm))
        if (get(m_features, w).stamp != m_stamp) refresh_features(w, tm, vpm);
  }

  // Cost.
  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    // Round-off can dip the quadric below zero.
    const double quadric_error =
        (std::max)(0.0, edge_quadric(profile).evaluate(internal::to_eigen(*placement)));
    const double geometric = normal_factor(profile.v0(), profile.v1()) * quadric_error;
    if (m_visual_weight == 0) return typename Profile::FT(geometric);  // the default: skip zeta
    const double zeta =
        internal::side_ratio(profile.v0_v1(), profile.surface_mesh(), profile.vertex_point_map());
    const double visual = m_visual_weight * zeta * edge_twist(profile.v0(), profile.v1()) *
                          m_input_edge_length * m_input_edge_length;
    return typename Profile::FT(geometric + visual);
  }

  // Placement.
  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const internal::Quadric_placement choice = internal::optimal_placement(
        edge_quadric(profile), internal::to_eigen(profile.p0()), internal::to_eigen(profile.p1()));
    return internal::to_point<typename Profile::Point>(choice.point);
  }

  // The terms of the cost, for tests and inspection; valid once `initialize` has run.
  double normal_factor(vertex_descriptor v0, vertex_descriptor v1) const {
    return 1.0 +
           m_mu * (std::max)(get(m_features, v0).normal_angle, get(m_features, v1).normal_angle);
  }
  double edge_twist(vertex_descriptor v0, vertex_descriptor v1) const {
    return (std::max)(get(m_features, v0).twist, get(m_features, v1).twist);
  }
  double input_mean_edge_length() const { return m_input_edge_length; }

 private:
  template <typename Profile>
  internal::Quadric edge_quadric(const Profile& profile) const {
    return get(m_quadrics, profile.v0()) + get(m_quadrics, profile.v1());
  }

  template <typename VertexPointMap>
  void refresh_normal(vertex_descriptor v, const TriangleMesh& tm,
                      const VertexPointMap& vpm) const {
    Vertex_features features = get(m_features, v);
    features.normal = internal::vertex_normal(v, tm, vpm, internal::Normal_weighting::area);
    put(m_features, v, features);
  }

  // thbar and T of v from the current normals, stamped with the current update.
  template <typename VertexPointMap>
  void refresh_features(vertex_descriptor v, const TriangleMesh& tm,
                        const VertexPointMap& vpm) const {
    const auto normal = [this](vertex_descriptor u) { return get(m_features, u).normal; };
    Vertex_features features = get(m_features, v);
    const internal::Normal_variation variation = internal::normal_variation(v, tm, vpm, normal);
    features.normal_angle = variation.mean_angle;
    features.twist = variation.mean_twist;
    features.stamp = m_stamp;
    put(m_features, v, features);
  }

  Vertex_map<internal::Quadric> m_quadrics;
  Vertex_map<Vertex_features> m_features;
  double m_mu;
  double m_visual_weight;
  double m_border_weight;
  mutable double m_input_edge_length = 0;  // L0, set by initialize
  mutable std::size_t m_stamp = 0;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FEATURE_FUSION_POLICIES_H
