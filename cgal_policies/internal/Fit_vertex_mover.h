// The guarded moves of a fit round (docs/fitting.md): each vertex toward its solved point within
// its trust region, kept on the input's border curve, then vetted by Fit_guard and, in bounded
// mode, certified within the tolerance.
#ifndef CGAL_POLICIES_INTERNAL_FIT_VERTEX_MOVER_H
#define CGAL_POLICIES_INTERNAL_FIT_VERTEX_MOVER_H

#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/internal/Border_curve.h>
#include <cgal_policies/internal/Fit_guard.h>
#include <cgal_policies/internal/Fit_output_mesh.h>
#include <cgal_policies/internal/Hausdorff_bounded_state.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Fit_vertex_mover {
  using Output_mesh = Fit_output_mesh<TriangleMesh>;
  using vertex_descriptor = typename Output_mesh::vertex_descriptor;
  using face_descriptor = typename Output_mesh::face_descriptor;
  using Bounded_state = Hausdorff_bounded_state<TriangleMesh>;

  // The faces around a vertex, as they would be once it moved.
  struct Moved_star {
    std::vector<std::uint32_t> faces;
    std::vector<Indexed_triangle> triangles;
    std::vector<Eigen::Vector3d> references;
  };

 public:
  // `pinned`, when given, names the vertices that do not move; `diagonal` is the input's.
  Fit_vertex_mover(const Output_mesh& mesh, const Border_curve& border, double diagonal,
                   const std::function<bool(vertex_descriptor)>& pinned, double trust_fraction)
      : m_border(&border), m_trust_fraction(trust_fraction) {
    for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
      m_pinned.push_back(pinned && pinned(mesh.vertex_at(v)));
    // A border vertex the simplification placed off the input's border curve is not snapped
    // onto it: that made the border worse than where the policy put it (docs/fitting.md).
    m_off_curve.assign(mesh.vertex_count(), false);
    if (!border.empty())
      for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
        m_off_curve[v] = CGAL::is_border(mesh.vertex_at(v), mesh.mesh()) &&
                         border.distance(mesh.points()[v]) > 1e-9 * diagonal;
  }

  // Moves every vertex that may move toward its point in `solved`, at most `reach` times its
  // trust region; a move the guards refuse is tried again half as far.
  void move_vertices(Output_mesh& mesh, Fit_guard& guard, Bounded_state* bounded,
                     const Eigen::VectorXd& solved, double reach,
                     Two_sided_fit_report& report) const {
    std::vector<double> edge_sum;
    std::vector<int> edge_count;
    sum_edge_lengths(mesh, edge_sum, edge_count);
    const std::vector<Eigen::Vector3d>& points = mesh.points();
    for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
      if (edge_count[v] == 0 || m_pinned[v]) continue;
      Eigen::Vector3d step = solved.segment<3>(3 * Eigen::Index(v)) - points[v];
      const double limit = reach * m_trust_fraction * edge_sum[v] / edge_count[v];
      if (step.norm() > limit) step *= limit / step.norm();
      if (!(step.norm() > 0)) continue;
      if (try_move(mesh, guard, bounded, v, points[v] + step, limit) ||
          try_move(mesh, guard, bounded, v, points[v] + 0.5 * step, limit))
        ++report.moves;
      else
        ++report.refused_moves;
    }
  }

 private:
  // The lengths of the edges around each vertex, summed, and their number (each edge counted
  // once per face), as the mesh is before the moves.
  static void sum_edge_lengths(const Output_mesh& mesh, std::vector<double>& edge_sum,
                               std::vector<int>& edge_count) {
    edge_sum.assign(mesh.vertex_count(), 0.0);
    edge_count.assign(mesh.vertex_count(), 0);
    const std::vector<Eigen::Vector3d>& points = mesh.points();
    for (const Fit_face_corners& c : mesh.corners())
      for (int k = 0; k < 3; ++k) {
        const double length = (points[c[(k + 1) % 3]] - points[c[k]]).norm();
        for (const std::uint32_t v : {c[k], c[(k + 1) % 3]}) {
          edge_sum[v] += length;
          ++edge_count[v];
        }
      }
  }

  // Moves v to p when the guards allow it and it stays within `limit`.
  bool try_move(Output_mesh& mesh, Fit_guard& guard, Bounded_state* bounded, std::uint32_t v,
                Eigen::Vector3d p, double limit) const {
    const Eigen::Vector3d& from = mesh.points()[v];
    if (!keep_on_border(mesh, v, p, limit)) return false;
    if (p == from || (p - from).norm() > limit) return false;
    const Moved_star star = moved_star(mesh, guard, v, p);
    if (!guard.allows(star.faces, star.triangles, star.references)) return false;
    if (bounded && !bounded->try_move(mesh.mesh(), mesh.vertex_point_map(), mesh.vertex_at(v), p))
      return false;
    mesh.move(v, p);
    guard.apply(star.faces, star.triangles, star.references);
    return true;
  }

  // A border vertex on the input's border curve goes to the point of the curve nearest p along
  // its own stretch of it; one off the curve may move only where it is no farther from the curve
  // (false when p is farther).
  bool keep_on_border(const Output_mesh& mesh, std::uint32_t v, Eigen::Vector3d& p,
                      double limit) const {
    if (!CGAL::is_border(mesh.vertex_at(v), mesh.mesh()) || m_border->empty()) return true;
    const Eigen::Vector3d& from = mesh.points()[v];
    if (!m_off_curve[v])
      p = m_border->nearest_along(from, p, limit);
    else if (m_border->distance(p) > m_border->distance(from))
      return false;
    return true;
  }

  static Moved_star moved_star(const Output_mesh& mesh, const Fit_guard& guard, std::uint32_t v,
                               const Eigen::Vector3d& p) {
    Moved_star star;
    const TriangleMesh& tm = mesh.mesh();
    for (face_descriptor f : CGAL::faces_around_target(halfedge(mesh.vertex_at(v), tm), tm)) {
      if (f == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::uint32_t i = mesh.face_index(f);
      star.faces.push_back(i);
      Indexed_triangle t = mesh.triangle(i);
      for (int k = 0; k < 3; ++k)
        if (t.vertices[k] == v) t.points[k] = p;
      star.triangles.push_back(t);
      star.references.push_back(guard.reference(i));
    }
    return star;
  }

  const Border_curve* m_border;
  double m_trust_fraction;
  std::vector<bool> m_pinned;     // vertices fit() was told to leave where they are
  std::vector<bool> m_off_curve;  // border vertices off the input's border curve
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_VERTEX_MOVER_H
