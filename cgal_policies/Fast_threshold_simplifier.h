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
#include <cgal_policies/internal/Flat_mesh_copy.h>
#include <cgal_policies/internal/plane_quadrics.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace cgal_policies {

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
    using Copy = internal::Flat_mesh_copy<TriangleMesh, Corners>;
    Copy copy(tm);
    std::vector<internal::Fast_threshold_vertex> vertex_data;
    {
      // The dynamic map lives in this block only, so that it is gone when tm is cleared.
      auto quadrics = get(CGAL::dynamic_vertex_property_t<internal::Quadric>(), tm);
      internal::accumulate_vertex_quadrics(tm, get(CGAL::vertex_point, tm),
                                           plane_weighting(m_options), m_options.border_weight,
                                           quadrics, quadrics);
      for (std::size_t i = 0; i < copy.vertices.size(); ++i)
        vertex_data.push_back({copy.points[i], get(quadrics, copy.vertices[i]),
                               bool(copy.border[i]), bool(copy.locked[i])});
    }
    internal::Fast_threshold_engine<Corners> engine(std::move(vertex_data), copy.triangles,
                                                    copy.diagonal, plane_weighting(m_options));
    if constexpr (Copy::kCarries) engine.mesh().set_corner_values(std::move(copy.corners));
    const auto outcome = engine.simplify(target_faces, m_options, on_progress);
    copy.write_back(engine.mesh(), tm);
    Fast_threshold_report report;
    report.passes = outcome.passes;
    report.target_reached = outcome.target_reached;
    return report;
  }

  Fast_threshold_options m_options;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FAST_THRESHOLD_SIMPLIFIER_H
