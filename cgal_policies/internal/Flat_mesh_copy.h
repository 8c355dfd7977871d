// Flat_mesh_copy: a triangle mesh copied into the flat arrays of the engines that work on
// Flat_collapse_mesh (Fast_threshold_engine, Lindstrom_turk_engine), and their result written
// back into it with its corner values, materials and, for a part of a partitioned run, the locks
// and origins of its vertices (internal/Mesh_parts.h).
#ifndef CGAL_POLICIES_INTERNAL_FLAT_MESH_COPY_H
#define CGAL_POLICIES_INTERNAL_FLAT_MESH_COPY_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/Flat_collapse_mesh.h>
#include <cgal_policies/internal/Is_surface_mesh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace cgal_policies {
namespace internal {

// The engines' view of Corner_attributes' values (Flat_collapse_mesh's Corners).
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

// vertices(g) and faces(g) as argument-dependent lookup finds them for every face graph (OpenMesh's
// are in its own namespace): Flat_mesh_copy's members hide the names.
template <class Graph>
auto vertex_range(const Graph& g) {
  return vertices(g);
}
template <class Graph>
auto face_range(const Graph& g) {
  return faces(g);
}

// Corners: No_corner_values, or Corner_attribute_values for a CGAL::Surface_mesh that has them.
template <class TriangleMesh, class Corners>
class Flat_mesh_copy {
 public:
  static constexpr bool kCarries = !std::is_same_v<Corners, No_corner_values>;
  using Vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
  using Values = typename Corners::Values;
  using Attributes = Corner_attributes<Point>;

  // Per vertex, in the order of vertices(tm): the vertex, its point, whether it is on the border
  // and whether it is locked; per face, its vertices' indices and, with kCarries, its corners.
  std::vector<Vertex_descriptor> vertices;
  std::vector<Eigen::Vector3d> points;
  std::vector<char> border;
  std::vector<char> locked;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<Values, 3>> corners;
  double diagonal = 0;  // of the points' bounding box

  explicit Flat_mesh_copy(TriangleMesh& tm) {
    const auto vpm = get(CGAL::vertex_point, tm);
    if constexpr (kCarries) m_attributes = Attributes(tm);
    read_locks(tm);
    // A dynamic map, gone when the constructor returns: write_back() clears tm.
    auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
    Eigen::AlignedBox3d box;
    for (Vertex_descriptor v : vertex_range(tm)) {
      put(index, v, int(points.size()));
      vertices.push_back(v);
      points.push_back(to_eigen(get(vpm, v)));
      box.extend(points.back());
      border.push_back(bool(CGAL::is_border(v, tm)));
    }
    if (locked.empty()) locked.assign(points.size(), false);
    for (auto f : face_range(tm)) {
      const auto h = halfedge(f, tm);
      triangles.push_back({get(index, source(h, tm)), get(index, target(h, tm)),
                           get(index, target(next(h, tm), tm))});
      if constexpr (kCarries) {
        corners.push_back({m_attributes->values(prev(h, tm)), m_attributes->values(h),
                           m_attributes->values(next(h, tm))});
        if (m_attributes->materials) m_materials.push_back((*m_attributes->materials)[f]);
      }
    }
    diagonal = points.empty() ? 0.0 : box.diagonal().norm();
  }

  // Clears tm and fills it with the result of an engine, its Flat_collapse_mesh.
  template <class Flat_mesh>
  void write_back(Flat_mesh& flat, TriangleMesh& tm) {
    std::vector<Eigen::Vector3d> new_points;
    std::vector<std::array<int, 3>> new_triangles;
    std::vector<std::array<Values, 3>> new_corners;
    std::vector<int> origins, kept;
    flat.extract(new_points, new_triangles, kCarries ? &new_corners : nullptr,
                 kCarries ? &origins : nullptr, m_origin.empty() ? nullptr : &kept);
    const typename Attributes::Kinds kinds =
        m_attributes ? m_attributes->kinds() : typename Attributes::Kinds{};
    CGAL::clear(tm);  // which resets the internal point map too
    if constexpr (kCarries) m_attributes = Attributes::add(tm, kinds);
    const auto vpm = get(CGAL::vertex_point, tm);
    std::vector<Vertex_descriptor> new_vertices;
    new_vertices.reserve(new_points.size());
    for (const Eigen::Vector3d& p : new_points) {
      new_vertices.push_back(add_vertex(tm));
      put(vpm, new_vertices.back(), to_point<Point>(p));
    }
    write_locks(tm, new_vertices, kept);
    for (std::size_t k = 0; k < new_triangles.size(); ++k) {
      const auto& t = new_triangles[k];
      const std::array<Vertex_descriptor, 3> face = {new_vertices[std::size_t(t[0])],
                                                     new_vertices[std::size_t(t[1])],
                                                     new_vertices[std::size_t(t[2])]};
      // The link condition makes this impossible for a manifold input.
      const auto f = CGAL::Euler::add_face(face, tm);
      if (f == boost::graph_traits<TriangleMesh>::null_face())
        throw std::logic_error("flat-array simplification: a face could not be rebuilt");
      if constexpr (kCarries) {
        for (const auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
          m_attributes->set_values(h, new_corners[k][target(h, tm) == face[0]   ? 0
                                                     : target(h, tm) == face[1] ? 1
                                                                                : 2]);
        if (m_attributes->materials)
          (*m_attributes->materials)[f] = m_materials[std::size_t(origins[k])];
      }
    }
  }

 private:
  // A part of a partitioned run: its locked vertices and their origins, kept through the rebuild.
  void read_locks(const TriangleMesh& tm) {
    if constexpr (Is_surface_mesh<TriangleMesh>::value) {
      const auto lock = find_vertex_map<bool>(tm, kLockedVertexMap);
      const auto from = find_vertex_map<Vertex_descriptor>(tm, kOriginVertexMap);
      if (lock && from)
        for (const Vertex_descriptor v : tm.vertices()) {
          locked.push_back((*lock)[v]);
          m_origin.push_back((*from)[v]);
        }
    }
  }

  void write_locks(TriangleMesh& tm, const std::vector<Vertex_descriptor>& new_vertices,
                   const std::vector<int>& kept) {
    if constexpr (Is_surface_mesh<TriangleMesh>::value) {
      if (m_origin.empty()) return;
      auto lock = tm.template add_property_map<Vertex_descriptor, bool>(kLockedVertexMap).first;
      auto from =
          tm.template add_property_map<Vertex_descriptor, Vertex_descriptor>(kOriginVertexMap)
              .first;
      for (std::size_t i = 0; i < new_vertices.size(); ++i) {
        lock[new_vertices[i]] = locked[std::size_t(kept[i])];
        from[new_vertices[i]] = m_origin[std::size_t(kept[i])];
      }
    }
  }

  std::optional<Attributes> m_attributes;
  std::vector<std::uint32_t> m_materials;   // with kCarries, each face's, when it has one
  std::vector<Vertex_descriptor> m_origin;  // of each vertex of a part
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FLAT_MESH_COPY_H
