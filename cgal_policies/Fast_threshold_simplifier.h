// Fast_threshold_simplifier: the "improved" threshold-driven QEM of [Hu14] §2.2, made safe
// (docs/fast.md). Not an SMS::edge_collapse policy: the mesh is copied to flat arrays, simplified
// there and rebuilt. Pass k collapses, in storage order and at most once per triangle, edges whose
// quadric error is below t_k = 1e-9 (k + 3)^a D^2 (D the bounding-box diagonal) and below a level
// cap that keeps cheap edges first (ours). Refused: collapses that break the link condition
// (missing in [Hu14]; a manifold input stays manifold), turn a face normal by more than
// max_normal_angle_deg or make a needle or sliver; border vertices move only along the border.
// Lossless mode: zero-error collapses only. Deterministic. For a `MutableFaceGraph` triangle mesh
// with an internal vertex point map (e.g. CGAL::Surface_mesh): it is cleared and rebuilt, which no
// external point map, descriptor or user property survives, but for a CGAL::Surface_mesh's corner
// attributes (Corner_attributes.h): they are carried through the collapses by the seam rules of
// Corner_attribute_carrier, and each face keeps its material. Parameters: Fast_threshold_options.
// Usage:
//   cgal_policies::Fast_threshold_simplifier simplifier;
//   const auto report = simplifier(mesh, mesh.number_of_faces() / 100);  // keep 1%
//   // report.target_reached, report.passes
#ifndef CGAL_POLICIES_FAST_THRESHOLD_SIMPLIFIER_H
#define CGAL_POLICIES_FAST_THRESHOLD_SIMPLIFIER_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/Fast_threshold_options.h>
#include <cgal_policies/internal/Fast_threshold_engine.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/part_vertex_maps.h>
#include <cgal_policies/internal/plane_quadrics.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace cgal_policies {
namespace internal {

// The engine's view of Corner_attributes' values (Fast_threshold_engine's Corners).
template <class Point>
struct Corner_attribute_values {
  using Attributes = Corner_attributes<Point>;
  using Values = typename Attributes::Values;
  static Values blend(const std::array<Values, 3>& corner, const std::array<double, 3>& w) {
    return Attributes::blend(corner, w);
  }
  static bool same(const Values& a, const Values& b) { return Attributes::same_values(a, b); }
  static double uv_area(const Values& a, const Values& b, const Values& c) {
    return Attributes::uv_area(a.uv, b.uv, c.uv);
  }
};

template <class Mesh>
struct Is_surface_mesh : std::false_type {};
template <class Point>
struct Is_surface_mesh<CGAL::Surface_mesh<Point>> : std::true_type {};

}  // namespace internal

struct Fast_threshold_report {
  std::size_t passes = 0;
  bool target_reached = false;  // false: no allowed collapse was left
};

class Fast_threshold_simplifier {
 public:
  explicit Fast_threshold_simplifier(const Fast_threshold_options& options = {})
      : m_options(options) {
    CGAL_precondition(options.aggressiveness > 0);
    CGAL_precondition(options.max_normal_angle_deg >= 0 && options.max_normal_angle_deg <= 180);
    CGAL_precondition(options.border_weight >= 0);
  }

  // on_progress, when set, receives the face count after each pass.
  template <typename TriangleMesh>
  Fast_threshold_report operator()(TriangleMesh& tm, std::size_t target_faces,
                                   const std::function<void(std::size_t)>& on_progress = {}) const {
    if constexpr (internal::Is_surface_mesh<TriangleMesh>::value) {
      using Point = typename TriangleMesh::Point;
      if (Corner_attributes<Point>(tm).any())
        return run<internal::Corner_attribute_values<Point>>(tm, target_faces, on_progress);
    }
    return run<internal::No_corner_values>(tm, target_faces, on_progress);
  }

 private:
  template <typename Corners, typename TriangleMesh>
  Fast_threshold_report run(TriangleMesh& tm, std::size_t target_faces,
                            const std::function<void(std::size_t)>& on_progress) const {
    constexpr bool kCarries = !std::is_same_v<Corners, internal::No_corner_values>;
    using Vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
    using Point = typename boost::property_traits<
        typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
    using Values = typename Corners::Values;
    using Attributes = Corner_attributes<Point>;
    const auto vpm = get(CGAL::vertex_point, tm);
    std::optional<Attributes> attributes;
    if constexpr (kCarries) attributes = Attributes(tm);

    // The dynamic maps live in this block only, so that they are gone when tm is cleared.
    std::vector<internal::Fast_threshold_vertex> vertex_data;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<Values, 3>> corners;  // with kCarries: per triangle, as the faces hold
    std::vector<std::uint32_t> materials;        // them, and each face's material when it has one
    Eigen::AlignedBox3d box;
    // A part of a partitioned run: its locked vertices and their origins are kept through the
    // rebuild (internal/Mesh_parts.h).
    std::vector<char> locked;
    std::vector<CGAL::SM_Vertex_index> origin;
    if constexpr (internal::Is_surface_mesh<TriangleMesh>::value) {
      using Vertex = typename TriangleMesh::Vertex_index;
      const auto lock = internal::find_vertex_map<bool>(tm, internal::kLockedVertexMap);
      const auto from = internal::find_vertex_map<Vertex>(tm, internal::kOriginVertexMap);
      if (lock && from)
        for (const Vertex v : tm.vertices()) {
          locked.push_back((*lock)[v]);
          origin.push_back((*from)[v]);
        }
    }
    {
      auto quadrics = get(CGAL::dynamic_vertex_property_t<internal::Quadric>(), tm);
      internal::accumulate_vertex_quadrics(tm, vpm, Face_weighting::unit, m_options.border_weight,
                                           quadrics, quadrics);
      auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
      for (Vertex_descriptor v : vertices(tm)) {
        put(index, v, int(vertex_data.size()));
        const Eigen::Vector3d p = internal::to_eigen(get(vpm, v));
        box.extend(p);
        vertex_data.push_back({p, get(quadrics, v), bool(is_border(v, tm)),
                               !locked.empty() && locked[vertex_data.size()]});
      }
      for (auto f : faces(tm)) {
        const auto h = halfedge(f, tm);
        triangles.push_back({get(index, source(h, tm)), get(index, target(h, tm)),
                             get(index, target(next(h, tm), tm))});
        if constexpr (kCarries) {
          corners.push_back({attributes->values(prev(h, tm)), attributes->values(h),
                             attributes->values(next(h, tm))});
          if (attributes->materials) materials.push_back((*attributes->materials)[f]);
        }
      }
    }
    const double diagonal = vertex_data.empty() ? 0.0 : box.diagonal().norm();

    internal::Fast_threshold_engine<Corners> engine(std::move(vertex_data), std::move(triangles),
                                                    diagonal);
    if constexpr (kCarries) engine.set_corner_values(std::move(corners));
    Fast_threshold_report report;
    const auto outcome = engine.simplify(target_faces, m_options, on_progress);
    report.passes = outcome.passes;
    report.target_reached = outcome.target_reached;

    std::vector<Eigen::Vector3d> points;
    std::vector<int> origins, kept;
    engine.extract(points, triangles, kCarries ? &corners : nullptr, kCarries ? &origins : nullptr,
                   locked.empty() ? nullptr : &kept);
    const typename Attributes::Kinds kinds =
        attributes ? attributes->kinds() : typename Attributes::Kinds{};
    CGAL::clear(tm);  // which resets the internal point map too
    if constexpr (kCarries) attributes = Attributes::add(tm, kinds);
    const auto new_vpm = get(CGAL::vertex_point, tm);
    std::vector<Vertex_descriptor> new_vertices;
    new_vertices.reserve(points.size());
    for (const Eigen::Vector3d& p : points) {
      new_vertices.push_back(add_vertex(tm));
      put(new_vpm, new_vertices.back(), internal::to_point<Point>(p));
    }
    if constexpr (internal::Is_surface_mesh<TriangleMesh>::value) {
      using Vertex = typename TriangleMesh::Vertex_index;
      if (!locked.empty()) {
        auto lock = tm.template add_property_map<Vertex, bool>(internal::kLockedVertexMap).first;
        auto from = tm.template add_property_map<Vertex, Vertex>(internal::kOriginVertexMap).first;
        for (std::size_t i = 0; i < new_vertices.size(); ++i) {
          lock[new_vertices[i]] = locked[std::size_t(kept[i])];
          from[new_vertices[i]] = origin[std::size_t(kept[i])];
        }
      }
    }
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const auto& t = triangles[k];
      const std::array<Vertex_descriptor, 3> face = {new_vertices[t[0]], new_vertices[t[1]],
                                                     new_vertices[t[2]]};
      // The link condition makes this impossible for a manifold input.
      const auto f = CGAL::Euler::add_face(face, tm);
      if (f == boost::graph_traits<TriangleMesh>::null_face())
        throw std::logic_error("Fast_threshold_simplifier: a face could not be rebuilt");
      if constexpr (kCarries) {
        for (const auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
          attributes->set_values(h, corners[k][target(h, tm) == face[0]   ? 0
                                               : target(h, tm) == face[1] ? 1
                                                                          : 2]);
        if (attributes->materials) (*attributes->materials)[f] = materials[std::size_t(origins[k])];
      }
    }
    return report;
  }

  Fast_threshold_options m_options;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FAST_THRESHOLD_SIMPLIFIER_H
