// The fitting pass's last step on a textured output (docs/fitting.md, "Texture coordinates,
// normals and colours"): the texture coordinates of the vertices on no seam solved again, by least
// squares, so that the output reads the input's texture where the input's surface lies nearest.
// Carrying values from collapse to collapse, and then from the output's old star to a moved
// vertex, drifts from the input's values; solving against the input itself removes that drift.
#ifndef CGAL_POLICIES_INTERNAL_RESOLVE_FREE_UVS_H
#define CGAL_POLICIES_INTERNAL_RESOLVE_FREE_UVS_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Triangle_bvh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/surface_samples.h>
#include <cgal_policies/internal/triangle_closest_point.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace cgal_policies {
namespace internal {

// Samples per input face: barycentric_grid(kResolveGridLevel), 6 points.
constexpr int kResolveGridLevel = 3;
// A sample whose texture coordinates lie farther than this fraction of the texture's extent from
// the output's at its nearest point reads the other side of a seam: it would drag the chart
// toward another, so it is left out.
constexpr double kResolveSeamJump = 0.05;
// Each solved vertex is held to its carried value with this share of the mean sample weight a
// vertex gets, so that one no sample reaches keeps its value and the system stays definite.
constexpr double kResolveHold = 1e-6;

// Solves again the texture coordinates of every vertex `solved` names: each must have no seam
// edge, so one value for all its corners. The values minimise the squared texture distance, over
// samples of `original`'s faces, to the output at the point nearest each sample. A face whose
// texture triangle the new values would turn over or make flat keeps its vertices' old values.
template <class Point>
void resolve_free_uvs(CGAL::Surface_mesh<Point>& mesh, const CGAL::Surface_mesh<Point>& original,
                      const std::function<bool(CGAL::SM_Vertex_index)>& solved) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Attributes = Corner_attributes<Point>;
  using Uv = typename Attributes::Uv;
  const Attributes attributes(mesh), input(original);
  if (!attributes.uvs || !input.uvs) return;
  const double extent = input.uv_extent(original);
  if (!(extent > 0)) return;

  std::vector<int> unknown(mesh.num_vertices(), -1);
  std::vector<typename Mesh::Vertex_index> vertex;
  for (const auto v : mesh.vertices())
    if (solved(v) && !mesh.is_isolated(v)) {
      unknown[std::size_t(v)] = int(vertex.size());
      vertex.push_back(v);
    }
  if (vertex.empty()) return;
  std::vector<typename Mesh::Face_index> face;
  std::vector<Triangle_corners> corners;  // of face[k], the tree's triangle k
  for (const auto f : mesh.faces()) {
    corners.push_back(face_corners(f, mesh, mesh.points()));
    face.push_back(f);
  }
  const Triangle_bvh tree(corners);

  // The normal equations, one column of right-hand sides per texture coordinate.
  const Eigen::Index n = Eigen::Index(vertex.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(n, 2);
  double total = 0;
  const std::vector<Eigen::Vector3d> grid = barycentric_grid(kResolveGridLevel);
  for (const auto g : original.faces()) {
    const auto gh = original.halfedge(g);
    const std::array<typename Mesh::Halfedge_index, 3> gc{original.prev(gh), gh, original.next(gh)};
    const Triangle_corners gp = face_corners(g, original, original.points());
    const double area = 0.5 * triangle_area_normal(gp[0], gp[1], gp[2]).norm();
    for (const Eigen::Vector3d& b : grid) {
      Eigen::Vector2d want = Eigen::Vector2d::Zero();
      for (int k = 0; k < 3; ++k)
        want += b[k] * Eigen::Vector2d((*input.uvs)[gc[k]][0], (*input.uvs)[gc[k]][1]);
      if (!want.allFinite()) break;  // a face without texture coordinates
      const Eigen::Vector3d p = b[0] * gp[0] + b[1] * gp[1] + b[2] * gp[2];
      const std::uint32_t at = tree.nearest(p).triangle;
      const auto h = mesh.halfedge(face[at]);
      // Corner k sits at corner k of corners[at]: source(h), target(h), target(next(h)).
      const std::array<typename Mesh::Halfedge_index, 3> fc{mesh.prev(h), h, mesh.next(h)};
      const Triangle_corners& fp = corners[at];
      const Eigen::Vector3d w = closest_barycentric(p, fp[0], fp[1], fp[2]);
      Eigen::Vector2d now = Eigen::Vector2d::Zero(), fixed = Eigen::Vector2d::Zero();
      std::array<int, 3> column{};
      for (int k = 0; k < 3; ++k) {
        const Uv& uv = (*attributes.uvs)[fc[k]];
        now += w[k] * Eigen::Vector2d(uv[0], uv[1]);
        column[k] = unknown[std::size_t(mesh.target(fc[k]))];
        if (column[k] < 0) fixed += w[k] * Eigen::Vector2d(uv[0], uv[1]);
      }
      if (!now.allFinite() || (now - want).norm() > kResolveSeamJump * extent) continue;
      const double weight = area / double(grid.size());
      total += weight;
      for (int i = 0; i < 3; ++i) {
        if (column[i] < 0) continue;
        rhs.row(column[i]) += weight * w[i] * (want - fixed).transpose();
        for (int j = 0; j < 3; ++j)
          if (column[j] >= 0) entries.emplace_back(column[i], column[j], weight * w[i] * w[j]);
      }
    }
  }
  if (!(total > 0)) return;
  const double hold = kResolveHold * total / double(n);
  Eigen::MatrixX2d old(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Uv& uv = (*attributes.uvs)[mesh.halfedge(vertex[std::size_t(i)])];
    old.row(i) << uv[0], uv[1];
    entries.emplace_back(i, i, hold);
    rhs.row(i) += hold * old.row(i);
  }
  Eigen::SparseMatrix<double> normal(n, n);
  normal.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return;
  Eigen::MatrixX2d fresh = solver.solve(rhs);
  if (!fresh.allFinite()) return;

  const auto write = [&](Eigen::Index i) {
    const Uv uv{fresh(i, 0), fresh(i, 1)};
    for (const auto h : CGAL::halfedges_around_target(vertex[std::size_t(i)], mesh))
      if (!mesh.is_border(h)) (*attributes.uvs)[h] = uv;
  };
  std::vector<double> was;
  for (const auto f : mesh.faces()) was.push_back(attributes.face_uv_area(mesh, f));
  for (Eigen::Index i = 0; i < n; ++i) write(i);
  // Faces turned over go back to their old values, until none is: at worst all of them.
  for (bool changed = true; changed;) {
    changed = false;
    std::size_t k = 0;
    for (const auto f : mesh.faces()) {
      const double before = was[k++], now = attributes.face_uv_area(mesh, f);
      if (!std::isfinite(before) || before == 0 || before * now > 0) continue;
      for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        const int i = unknown[std::size_t(v)];
        if (i < 0 || fresh.row(i) == old.row(i)) continue;
        fresh.row(i) = old.row(i);
        write(i);
        changed = true;
      }
    }
  }
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RESOLVE_FREE_UVS_H
