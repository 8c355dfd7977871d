// Flat_lindstrom_turk_simplifier: Lindstrom and Turk's memoryless simplification [LT98] on flat
// arrays (docs/flat_lt.md). Each edge's cost and placement come from the faces and border edges
// around its two ends as they are now, as in CGAL's LindstromTurk_cost and
// LindstromTurk_placement: the placement keeps the volume and the border, then minimises the
// volume and border changes, then evens out the link; the cost weighs the same terms. The
// cheapest edge goes first. Refused: collapses that break the link condition, turn a face normal
// by more than max_normal_angle_deg or make a needle or sliver (the checks of
// Fast_threshold_simplifier); an edge with no placement (fewer than three independent
// constraints). Not an SMS::edge_collapse policy: the mesh is copied to flat arrays, simplified
// there and rebuilt, like Fast_threshold_simplifier, with the same rules for corner attributes,
// materials and the locked vertices of a partitioned run. Deterministic.
// Usage:
//   cgal_policies::Flat_lindstrom_turk_simplifier simplifier;
//   const auto report = simplifier(mesh, mesh.number_of_faces() / 100);  // keep 1%
//   // report.target_reached, report.collapses
#ifndef CGAL_POLICIES_FLAT_LINDSTROM_TURK_SIMPLIFIER_H
#define CGAL_POLICIES_FLAT_LINDSTROM_TURK_SIMPLIFIER_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Flat_lindstrom_turk_options.h>
#include <cgal_policies/internal/Flat_mesh_copy.h>
#include <cgal_policies/internal/Lindstrom_turk_engine.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace cgal_policies {

struct Flat_lindstrom_turk_report {
  std::size_t collapses = 0;
  bool target_reached = false;  // false: no allowed collapse was left, or interrupted
  bool interrupted = false;
};

class Flat_lindstrom_turk_simplifier {
 public:
  explicit Flat_lindstrom_turk_simplifier(const Flat_lindstrom_turk_options& options = {})
      : m_options(options) {
    CGAL_precondition(options.volume_weight >= 0 && options.boundary_weight >= 0 &&
                      options.shape_weight >= 0);
    CGAL_precondition(options.max_normal_angle_deg >= 0 && options.max_normal_angle_deg <= 180);
  }

  // on_progress, when set, receives the face count now and then; interrupted, when set, is
  // polled every few thousand collapses and stops the run, the mesh valid, when it says so.
  template <typename TriangleMesh>
  Flat_lindstrom_turk_report operator()(TriangleMesh& tm, std::size_t target_faces,
                                        const std::function<void(std::size_t)>& on_progress = {},
                                        const std::function<bool()>& interrupted = {}) const {
    if constexpr (internal::Is_surface_mesh<TriangleMesh>::value) {
      using Point = typename TriangleMesh::Point;
      if (Corner_attributes<Point>(tm).any())
        return run<internal::Corner_attribute_values<Point>>(tm, target_faces, on_progress,
                                                             interrupted);
    }
    return run<internal::No_corner_values>(tm, target_faces, on_progress, interrupted);
  }

 private:
  template <typename Corners, typename TriangleMesh>
  Flat_lindstrom_turk_report run(TriangleMesh& tm, std::size_t target_faces,
                                 const std::function<void(std::size_t)>& on_progress,
                                 const std::function<bool()>& interrupted) const {
    using Copy = internal::Flat_mesh_copy<TriangleMesh, Corners>;
    Copy copy(tm);
    std::vector<internal::Lindstrom_turk_vertex> vertex_data;
    vertex_data.reserve(copy.points.size());
    for (std::size_t i = 0; i < copy.points.size(); ++i)
      vertex_data.push_back({copy.points[i], bool(copy.border[i]), bool(copy.locked[i])});
    internal::Lindstrom_turk_engine<Corners> engine(std::move(vertex_data), copy.triangles);
    if constexpr (Copy::kCarries) engine.mesh().set_corner_values(std::move(copy.corners));
    const auto outcome = engine.simplify(target_faces, m_options, on_progress, interrupted);
    copy.write_back(engine.mesh(), tm);
    Flat_lindstrom_turk_report report;
    report.collapses = outcome.collapses;
    report.target_reached = outcome.target_reached;
    report.interrupted = outcome.interrupted;
    return report;
  }

  Flat_lindstrom_turk_options m_options;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FLAT_LINDSTROM_TURK_SIMPLIFIER_H
