// A partitioned simplification (docs/scale.md): the mesh cut into the cells of Spatial_cells, each
// part simplified on its own core toward twice its share of the target with its cut vertices
// locked, the parts stitched back along the cuts, and a last run of the same policy over the much
// smaller whole down to the exact target; then, likewise, the fitting pass cell by cell. The output
// depends on the cells, never on the thread count.
#ifndef CGAL_POLICIES_INTERNAL_RUN_PARTITIONED_H
#define CGAL_POLICIES_INTERNAL_RUN_PARTITIONED_H

#include <cgal_policies/internal/Flat_part.h>
#include <cgal_policies/internal/Input_triangles.h>
#include <cgal_policies/internal/Mesh_parts.h>
#include <cgal_policies/internal/Policy_outcome.h>
#include <cgal_policies/internal/Spatial_cells.h>
#include <cgal_policies/internal/fit_carrying_corner_values.h>
#include <cgal_policies/internal/for_each_in_parallel.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr double kPartShare = 2;

// The locked vertices of a part: the ones the stitching needs.
template <class Point>
std::size_t locked_vertex_count(const CGAL::Surface_mesh<Point>& part) {
  const auto lock = find_vertex_map<bool>(part, kLockedVertexMap);
  std::size_t count = 0;
  for (const auto v : part.vertices()) count += (*lock)[v];
  return count;
}

// The edges whose two ends are at one point.
template <class Point>
std::vector<CGAL::SM_Edge_index> zero_length_edges(const CGAL::Surface_mesh<Point>& mesh) {
  std::vector<CGAL::SM_Edge_index> edges;
  for (const auto e : mesh.edges())
    if (mesh.point(mesh.source(mesh.halfedge(e))) == mesh.point(mesh.target(mesh.halfedge(e))))
      edges.push_back(e);
  return edges;
}

// Collapses the edges of zero length that CGAL's edge collapse may collapse, as it does before
// anything else, and collects the garbage. CGAL asks no filter for those collapses, so a part
// would otherwise lose one of two locked vertices at the same point.
template <class Point>
void collapse_zero_length_edges(CGAL::Surface_mesh<Point>& mesh) {
  using Mesh = CGAL::Surface_mesh<Point>;
  const std::vector<CGAL::SM_Edge_index> zero_length = zero_length_edges(mesh);
  if (zero_length.empty()) return;
  // The third corner of a face beside the edge must keep two other edges (collapse_edge's
  // precondition), and an inner edge between two border vertices would pinch the border.
  const auto keeps_its_faces = [&](typename Mesh::Halfedge_index h) {
    return mesh.is_border(h) ||
           CGAL::halfedges_around_target(mesh.target(mesh.next(h)), mesh).size() > 2;
  };
  for (const auto e : zero_length) {
    if (mesh.is_removed(e)) continue;
    const auto h = mesh.halfedge(e);
    if (!mesh.is_border(e) && mesh.is_border(mesh.source(h)) && mesh.is_border(mesh.target(h)))
      continue;
    if (keeps_its_faces(h) && keeps_its_faces(mesh.opposite(h)) &&
        CGAL::Euler::does_satisfy_link_condition(e, mesh))
      CGAL::Euler::collapse_edge(e, mesh);
  }
  mesh.collect_garbage();
}

// The face count a part of `faces` faces, `locked` of its vertices locked, is simplified to in a
// whole of `whole_faces` faces simplified to `target`: kPartShare times its share of the target
// besides one face per locked vertex, which it cannot collapse. The last collapses, which set
// where the detail goes, are left to the run over the whole, ordered across the cuts, and the cut
// does not take the faces of the part's inside.
inline std::size_t part_target(std::size_t faces, std::size_t locked, std::size_t target,
                               std::size_t whole_faces) {
  const double share = std::min(1.0, kPartShare * double(target) / double(whole_faces));
  return std::min<std::size_t>(faces, std::size_t(std::llround(share * double(faces))) + locked);
}

// Simplifies a part of a whole of `whole_faces` faces simplified to `target` to its part_target,
// run_policy(part, target) running the policy, and collects its garbage. False when the part
// lost a locked vertex.
template <class Point, class RunPolicy>
bool simplify_part(CGAL::Surface_mesh<Point>& part, std::size_t target, std::size_t whole_faces,
                   const RunPolicy& run_policy) {
  if (part.is_empty()) return true;
  const std::size_t locked = locked_vertex_count(part);
  run_policy(part, part_target(part.number_of_faces(), locked, target, whole_faces));
  part.collect_garbage();
  return locked_vertex_count(part) == locked;
}

// The parts of cells 0 to `cells` - 1 of a mesh of `whole_faces` faces and `whole_vertices`
// vertices (make_part(c) makes the part of cell c, with its lock and origin maps), each simplified
// toward kPartShare times its share of `target`, run_policy(part or whole, target) running the
// policy; then `whole` becomes them stitched, simplified to `target`. Nothing, and `whole` as it
// was, when a part lost a locked vertex.
template <class Point, class MakePart, class RunPolicy>
std::optional<Policy_outcome> run_parts(std::size_t cells, std::size_t whole_faces,
                                        std::size_t whole_vertices, std::size_t target,
                                        std::size_t threads, const MakePart& make_part,
                                        const RunPolicy& run_policy,
                                        CGAL::Surface_mesh<Point>& whole) {
  std::vector<CGAL::Surface_mesh<Point>> parts(cells);
  std::vector<char> kept_locks(cells, 1);
  for_each_in_parallel(parts.size(), threads, [&](std::size_t c) {
    parts[c] = make_part(c);
    kept_locks[c] = simplify_part(parts[c], target, whole_faces, run_policy);
  });
  for (const char kept : kept_locks)
    if (!kept) return std::nullopt;
  whole = stitch_parts(parts, whole_vertices);
  parts.clear();
  return run_policy(whole, target);
}

// Simplifies `mesh` (no garbage, its edges of zero length collapsed: collapse_zero_length_edges)
// as the header says, by run_parts over `cells`. Nothing, and `mesh` as it was, when a part lost a
// locked vertex all the same: the caller then runs the policy on the whole.
template <class Point, class RunPolicy>
std::optional<Policy_outcome> run_partitioned(CGAL::Surface_mesh<Point>& mesh, std::size_t target,
                                              const Spatial_cells& cells, std::size_t threads,
                                              const RunPolicy& run_policy) {
  const std::vector<std::uint32_t> cell = face_cells(mesh, cells, threads);
  return run_parts(
      cells.size(), mesh.number_of_faces(), mesh.number_of_vertices(), target, threads,
      [&](std::size_t c) { return mesh_part(mesh, cell, std::uint32_t(c)); }, run_policy, mesh);
}

// run_partitioned for the flat-array engines on a mesh without corner values or garbage, whose
// edges of zero length need not be collapsed (the engines keep every locked vertex): the parts kept
// as arrays (Flat_part.h), run_on_part(part, target) running the policy on each, then stitched
// into `mesh` and simplified to `target` by run_policy(mesh, target). The same result as
// run_partitioned with those engines; no part loses a locked vertex (the engines refuse it).
template <class Point, class RunOnPart, class RunPolicy>
Policy_outcome run_flat_partitioned(CGAL::Surface_mesh<Point>& mesh, std::size_t target,
                                    const Spatial_cells& cells, std::size_t threads,
                                    const RunOnPart& run_on_part, const RunPolicy& run_policy) {
  const std::vector<std::uint32_t> cell = face_cells(mesh, cells, threads);
  const std::size_t whole_faces = mesh.number_of_faces();
  std::vector<Flat_part> parts(cells.size());
  for_each_in_parallel(parts.size(), threads, [&](std::size_t c) {
    parts[c] = flat_part(mesh, cell, std::uint32_t(c));
    const std::size_t faces = parts[c].triangles.size();
    if (faces == 0) return;
    const std::size_t locked =
        std::size_t(std::count(parts[c].locked.begin(), parts[c].locked.end(), char(true)));
    run_on_part(parts[c], part_target(faces, locked, target, whole_faces));
  });
  mesh = stitch_flat_parts<Point>(parts, mesh.number_of_vertices());
  parts.clear();
  return run_policy(mesh, target);
}

// Adds the moves and flips of `from` to `to`; the rounds are the caller's to count.
inline void add_fit_counts(Two_sided_fit_report& to, const Two_sided_fit_report& from) {
  to.moves += from.moves;
  to.refused_moves += from.refused_moves;
  to.flips += from.flips;
  to.refused_flips += from.refused_flips;
}

// Fits a part of the output to `near`, the triangles of the same cell of the input, its cut
// vertices pinned.
template <class Point>
Two_sided_fit_report fit_part(CGAL::Surface_mesh<Point>& part, Input_triangles near,
                              const Two_sided_fit_options& options) {
  if (part.number_of_faces() == 0 || near.corners.empty()) return {};
  const auto lock = find_vertex_map<bool>(part, kLockedVertexMap);
  return fit_carrying_corner_values(part, std::move(near), options,
                                    [&](CGAL::SM_Vertex_index v) { return (*lock)[v]; });
}

// The triangles of a cell's part of the input, held as a mesh (read from a file).
template <class Point>
Input_triangles near_triangles(const CGAL::Surface_mesh<Point>& near) {
  return input_triangles(near, near.points());
}

// The report of a fit by cells from those of its cells: the moves and flips add up; the rounds
// are those of the cell that ran the most.
inline Two_sided_fit_report add_cell_fit_reports(const std::vector<Two_sided_fit_report>& reports) {
  Two_sided_fit_report report;
  for (const Two_sided_fit_report& r : reports) {
    report.rounds = (std::max)(report.rounds, r.rounds);
    add_fit_counts(report, r);
  }
  return report;
}

// The fitting pass by cells: each cell of the output fitted to the same cell of the input
// (input_part(c), its Input_triangles), on its own core, then the cells stitched back.
template <class Point, class InputPart>
Two_sided_fit_report fit_partitioned(CGAL::Surface_mesh<Point>& mesh, const Spatial_cells& cells,
                                     std::size_t threads, const Two_sided_fit_options& options,
                                     const InputPart& input_part) {
  using Mesh = CGAL::Surface_mesh<Point>;
  const std::vector<std::uint32_t> output_cell = face_cells(mesh, cells, threads);
  std::vector<std::size_t> faces_in(cells.size(), 0);
  for (const std::uint32_t c : output_cell) ++faces_in[c];
  std::vector<Mesh> parts(cells.size());
  std::vector<Two_sided_fit_report> reports(cells.size());
  for_each_costliest_first(faces_in, threads, [&](std::size_t c) {
    parts[c] = mesh_part(mesh, output_cell, std::uint32_t(c));
    reports[c] = fit_part(parts[c], input_part(c), options);
  });
  mesh = stitch_parts(parts, mesh.number_of_vertices());
  return add_cell_fit_reports(reports);
}

// The cells of the second half of a fit by cells are cut at these quantiles.
constexpr double kShiftedQuantile = 0.35;

// The rounds of half 0 or 1 of a fit by cells of `rounds` rounds.
inline int fit_half_rounds(int rounds, int half) {
  return half == 0 ? (rounds + 1) / 2 : rounds - (rounds + 1) / 2;
}

// The cells of the second half of a fit by cells against an input of these face centroids, split
// on up to `threads` cores.
inline Spatial_cells shifted_cells(std::vector<Eigen::Vector3d> centroids,
                                   const Spatial_cells& cells, std::size_t threads) {
  return Spatial_cells(std::move(centroids), cells.size(), threads, kShiftedQuantile);
}

// The fit by cells, in two halves of its rounds: over the run's `cells`, then over `shifted`, cut
// elsewhere (kShiftedQuantile), so that the vertices pinned on the first cuts move too.
// input_parts(cells) gives the callable that makes the Input_triangles of a cell of those cells.
template <class Point, class InputParts>
Two_sided_fit_report fit_by_cells(CGAL::Surface_mesh<Point>& mesh, const Spatial_cells& cells,
                                  const Spatial_cells& shifted, std::size_t threads,
                                  Two_sided_fit_options fit, const InputParts& input_parts) {
  const int rounds = fit.rounds;
  fit.rounds = fit_half_rounds(rounds, 0);
  Two_sided_fit_report report = fit_partitioned(mesh, cells, threads, fit, input_parts(cells));
  fit.rounds = fit_half_rounds(rounds, 1);
  if (fit.rounds == 0) return report;
  const Two_sided_fit_report second =
      fit_partitioned(mesh, shifted, threads, fit, input_parts(shifted));
  report.rounds += second.rounds;
  add_fit_counts(report, second);
  return report;
}

// The same, `input` held whole.
template <class Point>
Two_sided_fit_report fit_by_cells(CGAL::Surface_mesh<Point>& mesh,
                                  const CGAL::Surface_mesh<Point>& input,
                                  const Spatial_cells& cells, std::size_t threads,
                                  const Two_sided_fit_options& fit) {
  const std::vector<Eigen::Vector3d> centroids = face_centroids(input, threads);
  const Spatial_cells shifted = shifted_cells(centroids, cells, threads);
  return fit_by_cells(mesh, cells, shifted, threads, fit, [&](const Spatial_cells& by) {
    std::vector<std::uint32_t> cell = face_cells(centroids, by, threads);
    std::vector<std::uint32_t> rank = ranks_in_cells(cell, by.size());
    return [&input, cell = std::move(cell), rank = std::move(rank)](std::size_t c) {
      return cell_triangles(input, cell, std::uint32_t(c), rank);
    };
  });
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RUN_PARTITIONED_H
