// Classic_quadric_policies: the quadric error metric of Garland & Heckbert as the QEM tutorial
// (seed 001) and policies.md §0 describe it.
//
// - Cost of collapsing (v0, v1) to x: x~^T (Q0 + Q1) x~, where Q_v sums the planes of the faces
//   around v and, on a border, planes through each border edge perpendicular to its face.
// - Placement: the quadric's minimiser when A is well conditioned and the point stays within two
//   edge lengths of the edge; else the best point of the edge; else the best of v0, v1, midpoint.
// - The merged vertex keeps Q0 + Q1.
//
// Models CGAL's `GetCost` and `GetPlacement` concepts (one object, as CGAL's
// GarlandHeckbert_plane_policies); its state lives in a dynamic vertex property, so the mesh gains
// no visible property, and `Update_tag` makes `edge_collapse` call `initialize` and
// `update_after_collapse`.
//
// Parameters:
//   border_weight  weight W_b of a border plane (default 1000; with area weighting it is multiplied
//                  by the squared edge length so that it keeps the units of a face quadric)
//   face_weighting Face_weighting::unit (default, as the papers) or Face_weighting::area
//
// Usage:
//   cgal_policies::Classic_quadric_policies<Mesh, Kernel> policies(mesh);
//   SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost())
//                                                   .get_placement(policies.get_placement()));
#ifndef CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H
#define CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H

#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Optional.h>
#include <cgal_policies/internal/Quadric.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <algorithm>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Classic_quadric_policies {
  using Quadric_property = CGAL::dynamic_vertex_property_t<internal::Quadric>;
  using Quadric_map = typename boost::property_map<TriangleMesh, Quadric_property>::type;

 public:
  using Update_tag = CGAL::Tag_true;
  using Get_cost = Classic_quadric_policies;
  using Get_placement = Classic_quadric_policies;
  using FT = typename GeomTraits::FT;

  explicit Classic_quadric_policies(TriangleMesh& tm, double border_weight = 1000.0,
                                    Face_weighting face_weighting = Face_weighting::unit)
      : m_quadrics(get(Quadric_property(), tm)),
        m_border_weight(border_weight),
        m_face_weighting(face_weighting) {}

  const Get_cost& get_cost() const { return *this; }
  const Get_placement& get_placement() const { return *this; }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits&) const {
    internal::accumulate_vertex_quadrics(tm, vpm, m_face_weighting, m_border_weight, m_quadrics,
                                         m_quadrics);
  }

  template <typename Profile, typename VertexDescriptor>
  void update_after_collapse(const Profile& profile, VertexDescriptor kept) const {
    put(m_quadrics, kept, edge_quadric(profile));
  }

  // Cost.
  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    const double cost = edge_quadric(profile).evaluate(internal::to_eigen(*placement));
    return typename Profile::FT((std::max)(0.0, cost));  // round-off can dip below zero
  }

  // Placement.
  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const internal::Quadric_placement choice = internal::optimal_placement(
        edge_quadric(profile), internal::to_eigen(profile.p0()), internal::to_eigen(profile.p1()));
    return internal::to_point<typename Profile::Point>(choice.point);
  }

 private:
  template <typename Profile>
  internal::Quadric edge_quadric(const Profile& profile) const {
    return get(m_quadrics, profile.v0()) + get(m_quadrics, profile.v1());
  }

  Quadric_map m_quadrics;
  double m_border_weight;
  Face_weighting m_face_weighting;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CLASSIC_QUADRIC_POLICIES_H
