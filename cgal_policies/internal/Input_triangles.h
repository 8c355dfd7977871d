// The triangles of an input surface as its distance searches read them (Hausdorff_input_surface,
// the fitting pass's Border_curve and samples): their corners and their neighbours across edges,
// taken from a whole mesh or from one cell of it without building the cell's part.
#ifndef CGAL_POLICIES_INTERNAL_INPUT_TRIANGLES_H
#define CGAL_POLICIES_INTERNAL_INPUT_TRIANGLES_H

#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr std::uint32_t kNoNeighbour = 0xffffffffu;

template <typename Mesh, typename VertexPointMap>
Triangle_corners face_corners(typename boost::graph_traits<Mesh>::face_descriptor f, const Mesh& tm,
                              const VertexPointMap& vpm) {
  const auto h = halfedge(f, tm);
  return {internal::to_eigen(get(vpm, source(h, tm))), internal::to_eigen(get(vpm, target(h, tm))),
          internal::to_eigen(get(vpm, target(next(h, tm), tm)))};
}

struct Input_triangles {
  std::vector<Triangle_corners> corners;
  // Across edge k of triangle i (corners k, k + 1) lies neighbours[i][k], or kNoNeighbour.
  std::vector<std::array<std::uint32_t, 3>> neighbours;
};

// The triangles of every face of `input`, in the order of its faces.
template <typename InputMesh, typename VertexPointMap>
Input_triangles input_triangles(const InputMesh& input, const VertexPointMap& vpm) {
  Input_triangles triangles;
  const auto index = get(CGAL::dynamic_face_property_t<std::uint32_t>(), input);
  for (auto f : faces(input)) {
    put(index, f, std::uint32_t(triangles.corners.size()));
    triangles.corners.push_back(face_corners(f, input, vpm));
  }
  triangles.neighbours.resize(triangles.corners.size());
  for (auto f : faces(input)) {
    std::array<std::uint32_t, 3>& across = triangles.neighbours[get(index, f)];
    int k = 0;
    for (auto h : CGAL::halfedges_around_face(halfedge(f, input), input)) {
      const auto g = face(opposite(h, input), input);
      across[k++] = g == boost::graph_traits<InputMesh>::null_face() ? kNoNeighbour : get(index, g);
    }
  }
  return triangles;
}

// Each face's index among the faces of its cell (cell[f]), in the order of the faces.
inline std::vector<std::uint32_t> ranks_in_cells(const std::vector<std::uint32_t>& cell,
                                                 std::size_t cells) {
  std::vector<std::uint32_t> next(cells, 0), rank(cell.size());
  for (std::size_t f = 0; f < cell.size(); ++f) rank[f] = next[cell[f]]++;
  return rank;
}

// The triangles of mesh_part(mesh, cell, c), corner for corner and neighbour for neighbour, without
// the part: a cell's faces in their order, a neighbour in another cell none. `rank` is
// ranks_in_cells(cell). `mesh` has no garbage.
template <class Point>
Input_triangles cell_triangles(const CGAL::Surface_mesh<Point>& mesh,
                               const std::vector<std::uint32_t>& cell, std::uint32_t c,
                               const std::vector<std::uint32_t>& rank) {
  Input_triangles triangles;
  for (const auto f : mesh.faces()) {
    if (cell[std::size_t(f)] != c) continue;
    triangles.corners.push_back(face_corners(f, mesh, mesh.points()));
    std::array<std::uint32_t, 3>& across = triangles.neighbours.emplace_back();
    int k = 0;
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const auto g = mesh.face(mesh.opposite(h));
      across[k++] =
          g == mesh.null_face() || cell[std::size_t(g)] != c ? kNoNeighbour : rank[std::size_t(g)];
    }
  }
  return triangles;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_INPUT_TRIANGLES_H
