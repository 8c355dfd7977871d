// Feature_fusion_policies: the multi-feature fusion cost of [Wang13] (docs/fusion.md):
//   Cost_all = C_geom + C_visu                               (the paper's eq. 3)
//   C_geom   = (1 + mu * omega(e)) * x~^T F x~ + x~^T B x~     (ours)
//   C_visu   = w_v * zeta(e) * T(e) * L0^2                    (the paper's zeta * T; w_v, L0 ours)
// F, B: the face-plane and border-plane quadrics of both ends; zeta: eq. 9's side ratio; omega, T:
// normal variation (radians) and twist, our reconstruction of the missing eqs. 4-8; L0: the
// input's mean edge length, for scale invariance. Placement: the optimum of F + B.
// Models CGAL's `GetCost` and `GetPlacement` in one object with `Update_tag` (state in dynamic
// properties); pair it with a flip filter, as below. Parameters: Feature_fusion_options.
// Usage:
//   cgal_policies::Feature_fusion_policies<Mesh, Kernel> policies(mesh);
//   cgal_policies::Bounded_normal_angle_filter<> filter;
//   SMS::edge_collapse(mesh, stop,
//                      CGAL::parameters::get_cost(policies.get_cost())
//                          .get_placement(policies.get_placement())
//                          .filter(filter));
#ifndef CGAL_POLICIES_FEATURE_FUSION_POLICIES_H
#define CGAL_POLICIES_FEATURE_FUSION_POLICIES_H

#include <cgal_policies/Feature_fusion_options.h>
#include <cgal_policies/internal/Quadric_policy_base.h>
#include <cgal_policies/internal/feature_fusion_measures.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Feature_fusion_policies
    : public internal::Quadric_policy_base<
          TriangleMesh, GeomTraits, Feature_fusion_policies<TriangleMesh, GeomTraits>, true> {
  using Base =
      internal::Quadric_policy_base<TriangleMesh, GeomTraits, Feature_fusion_policies, true>;
  friend Base;
  template <typename T>
  using Vertex_map =
      typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<T>>::type;
  template <typename T>
  using Edge_map =
      typename boost::property_map<TriangleMesh, CGAL::dynamic_edge_property_t<T>>::type;
  template <typename T>
  using Face_map =
      typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<T>>::type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

  struct Vertex_features {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // area-weighted, unit
    internal::Normal_variation_sum variation;          // the sums behind thbar(v) and T(v)
    std::size_t stamp = 0;                             // the last update that refreshed the normal
  };
  // A struct, so that the property's default value is initialised.
  struct Face_normal {
    Eigen::Vector3d area_normal = Eigen::Vector3d::Zero();
  };

 public:
  explicit Feature_fusion_policies(TriangleMesh& tm, const Feature_fusion_options& options = {})
      : Base(tm, options),
        m_features(get(CGAL::dynamic_vertex_property_t<Vertex_features>(), tm)),
        m_edge_terms(get(CGAL::dynamic_edge_property_t<internal::Normal_variation_sum>(), tm)),
        m_face_normals(get(CGAL::dynamic_face_property_t<Face_normal>(), tm)),
        m_mu(options.mu),
        m_visual_weight(options.visual_weight) {
    CGAL_precondition(options.mu >= 0);
    CGAL_precondition(options.visual_weight >= 0);
  }

  // For tests and inspection; valid once `initialize` has run.
  double normal_factor(vertex_descriptor v0, vertex_descriptor v1) const {
    return 1.0 + m_mu * (std::max)(get(m_features, v0).variation.mean_angle(),
                                   get(m_features, v1).variation.mean_angle());
  }
  double edge_twist(vertex_descriptor v0, vertex_descriptor v1) const {
    return (std::max)(get(m_features, v0).variation.mean_twist(),
                      get(m_features, v1).variation.mean_twist());
  }
  double input_mean_edge_length() const { return m_input_edge_length; }

 private:
  template <typename VertexPointMap>
  void initialize_features(const TriangleMesh& tm, const VertexPointMap& vpm) const {
    m_input_edge_length = internal::mean_edge_length(tm, vpm);
    m_stamp = 0;
    for (auto f : faces(tm))
      put(m_face_normals, f, Face_normal{internal::face_area_normal(f, tm, vpm)});
    for (vertex_descriptor v : vertices(tm)) {
      put(m_features, v, Vertex_features());
      refresh_normal(v, tm);
    }
    for (auto e : edges(tm)) put(m_edge_terms, e, edge_term(halfedge(e, tm), tm, vpm));
    for (vertex_descriptor v : vertices(tm)) refresh_sums(v, tm);
  }

  template <typename Profile>
  void update_features(const Profile& profile, vertex_descriptor kept) const {
    const TriangleMesh& tm = profile.surface_mesh();
    const auto vpm = profile.vertex_point_map();
    // The normals of `kept` and its ring changed (they get this update's stamp), hence the terms of
    // their edges; a vertex one ring further only swaps those terms in its sums.
    const auto ring = CGAL::vertices_around_target(halfedge(kept, tm), tm);
    ++m_stamp;
    for (auto f : CGAL::faces_around_target(halfedge(kept, tm), tm))
      if (f != boost::graph_traits<TriangleMesh>::null_face())
        put(m_face_normals, f, Face_normal{internal::face_area_normal(f, tm, vpm)});
    refresh_normal(kept, tm);
    for (vertex_descriptor j : ring) refresh_normal(j, tm);
    for (halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(kept, tm), tm))
      put(m_edge_terms, edge(h, tm), edge_term(h, tm, vpm));
    for (vertex_descriptor j : ring)
      for (halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(j, tm), tm)) {
        const vertex_descriptor w = source(h, tm);
        if (w == kept) continue;  // done above
        const internal::Normal_variation_sum term = edge_term(h, tm, vpm);
        if (get(m_features, w).stamp != m_stamp) {
          Vertex_features features = get(m_features, w);
          features.variation -= get(m_edge_terms, edge(h, tm));
          features.variation += term;
          put(m_features, w, features);
        }
        put(m_edge_terms, edge(h, tm), term);
      }
    refresh_sums(kept, tm);
    for (vertex_descriptor j : ring) refresh_sums(j, tm);
  }

  // The factor scales the face planes only, or borders would stiffen wherever normals vary.
  template <typename Profile>
  double cost_of(const Profile& profile, double face_error, double border_error) const {
    const double geometric = normal_factor(profile.v0(), profile.v1()) * face_error + border_error;
    if (m_visual_weight == 0) return geometric;  // the default: skip zeta
    const double zeta =
        internal::side_ratio(profile.v0_v1(), profile.surface_mesh(), profile.vertex_point_map());
    const double visual = m_visual_weight * zeta * edge_twist(profile.v0(), profile.v1()) *
                          m_input_edge_length * m_input_edge_length;
    return geometric + visual;
  }

  // The area-weighted normal, from stored face normals that only the kept vertex's faces change.
  void refresh_normal(vertex_descriptor v, const TriangleMesh& tm) const {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (auto f : CGAL::faces_around_target(halfedge(v, tm), tm))
      if (f != boost::graph_traits<TriangleMesh>::null_face())
        sum += get(m_face_normals, f).area_normal;
    Vertex_features features = get(m_features, v);
    features.normal = internal::unit_or_zero(sum);
    features.stamp = m_stamp;
    put(m_features, v, features);
  }

  // Computed on the edge's own halfedge, so that it does not depend on which end asks.
  template <typename VertexPointMap>
  internal::Normal_variation_sum edge_term(halfedge_descriptor h, const TriangleMesh& tm,
                                           const VertexPointMap& vpm) const {
    const auto normal = [this](vertex_descriptor u) { return get(m_features, u).normal; };
    return internal::Normal_variation_sum::of(internal::edge_normal_variation(
        halfedge(edge(h, tm), tm), tm, vpm, normal, m_visual_weight != 0));
  }

  void refresh_sums(vertex_descriptor v, const TriangleMesh& tm) const {
    const auto stored_term = [&](halfedge_descriptor h) { return get(m_edge_terms, edge(h, tm)); };
    Vertex_features features = get(m_features, v);
    features.variation = internal::normal_variation_sum(v, tm, stored_term);
    put(m_features, v, features);
  }

  Vertex_map<Vertex_features> m_features;
  Edge_map<internal::Normal_variation_sum> m_edge_terms;  // angle and |twist| along each edge
  Face_map<Face_normal> m_face_normals;
  double m_mu;
  double m_visual_weight;
  mutable double m_input_edge_length = 0;  // L0, set by initialize
  mutable std::size_t m_stamp = 0;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FEATURE_FUSION_POLICIES_H
