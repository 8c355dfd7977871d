// The output mesh as the fitting pass sees it (docs/fitting.md): its vertices and faces numbered
// once, their points in double precision, and each face's corners and neighbours as of the last
// refresh_faces(), so the steps of a round work on indices.
#ifndef CGAL_POLICIES_INTERNAL_FIT_OUTPUT_MESH_H
#define CGAL_POLICIES_INTERNAL_FIT_OUTPUT_MESH_H

#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/triangle_distance.h>
#include <cgal_policies/internal/triangles_intersect.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr std::uint32_t kFitNoFace = 0xffffffffu;

using Fit_face_corners = std::array<std::uint32_t, 3>;

inline double triangle_area(const Indexed_triangle& t) {
  return 0.5 * triangle_area_normal(t.points[0], t.points[1], t.points[2]).norm();
}

template <typename TriangleMesh>
class Fit_output_mesh {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using Vertex_point_map = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<Vertex_point_map>::value_type;

 public:
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;

  // Numbers the vertices and faces of `tm`; the corners wait for refresh_faces().
  explicit Fit_output_mesh(TriangleMesh& tm)
      : m_tm(&tm),
        m_vpm(get(CGAL::vertex_point, tm)),
        m_vertex_index(get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm)),
        m_face_index(get(CGAL::dynamic_face_property_t<std::uint32_t>(), tm)) {
    for (vertex_descriptor v : vertices(tm)) {
      put(m_vertex_index, v, std::uint32_t(m_vertices.size()));
      m_vertices.push_back(v);
      m_points.push_back(to_eigen(get(m_vpm, v)));
    }
    for (face_descriptor f : faces(tm)) {
      put(m_face_index, f, std::uint32_t(m_faces.size()));
      m_faces.push_back(f);
    }
  }

  TriangleMesh& mesh() { return *m_tm; }
  const TriangleMesh& mesh() const { return *m_tm; }
  const Vertex_point_map& vertex_point_map() const { return m_vpm; }
  std::size_t vertex_count() const { return m_vertices.size(); }
  std::size_t face_count() const { return m_faces.size(); }
  vertex_descriptor vertex_at(std::uint32_t v) const { return m_vertices[v]; }
  face_descriptor face_at(std::uint32_t f) const { return m_faces[f]; }
  std::uint32_t face_index(face_descriptor f) const { return get(m_face_index, f); }
  const std::vector<Eigen::Vector3d>& points() const { return m_points; }
  const std::vector<Fit_face_corners>& corners() const { return m_corners; }
  // Across the edge from corner k to corner k + 1 of face f lies neighbours()[f][k] (or
  // kFitNoFace).
  const std::vector<Fit_face_corners>& neighbours() const { return m_neighbours; }

  void move(std::uint32_t v, const Eigen::Vector3d& p) {
    put(m_vpm, m_vertices[v], to_point<Point>(p));
    m_points[v] = p;
  }

  void set_points(const std::vector<Eigen::Vector3d>& points) {
    m_points = points;
    for (std::uint32_t v = 0; v < m_vertices.size(); ++v)
      put(m_vpm, m_vertices[v], to_point<Point>(m_points[v]));
  }

  // Every face's corners and neighbours as the mesh is now.
  void refresh_faces() {
    m_corners.resize(m_faces.size());
    m_neighbours.resize(m_faces.size());
    for (std::uint32_t f = 0; f < m_faces.size(); ++f) {
      int k = 0;
      for (halfedge_descriptor h :
           CGAL::halfedges_around_face(halfedge(m_faces[f], *m_tm), *m_tm)) {
        m_corners[f][k] = get(m_vertex_index, target(h, *m_tm));
        const face_descriptor g = face(opposite(next(h, *m_tm), *m_tm), *m_tm);
        m_neighbours[f][k++] = g == Graph_traits::null_face() ? kFitNoFace : get(m_face_index, g);
      }
    }
  }

  // Face f's corners only, after a flip changed them; its neighbours wait for refresh_faces().
  void refresh_corners(std::uint32_t f) {
    int k = 0;
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(m_faces[f], *m_tm), *m_tm))
      m_corners[f][k++] = get(m_vertex_index, v);
  }

  Indexed_triangle triangle(std::uint32_t f) const {
    Indexed_triangle t;
    for (int k = 0; k < 3; ++k) {
      t.vertices[k] = m_corners[f][k];
      t.points[k] = m_points[m_corners[f][k]];
    }
    return t;
  }

  // The triangle (x, y, z), which need not be a face.
  Indexed_triangle triangle(vertex_descriptor x, vertex_descriptor y, vertex_descriptor z) const {
    Indexed_triangle t;
    const std::array<vertex_descriptor, 3> corners = {x, y, z};
    for (int k = 0; k < 3; ++k) {
      t.vertices[k] = get(m_vertex_index, corners[k]);
      t.points[k] = m_points[t.vertices[k]];
    }
    return t;
  }

  double squared_distance(const Eigen::Vector3d& p, std::uint32_t f) const {
    return squared_distance_to_triangle(p, m_points[m_corners[f][0]], m_points[m_corners[f][1]],
                                        m_points[m_corners[f][2]]);
  }

  double area() const {
    double area = 0;
    for (std::uint32_t f = 0; f < m_faces.size(); ++f) area += triangle_area(triangle(f));
    return area;
  }

 private:
  TriangleMesh* m_tm;
  Vertex_point_map m_vpm;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::uint32_t>>::type
      m_vertex_index;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::uint32_t>>::type
      m_face_index;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<face_descriptor> m_faces;
  std::vector<Eigen::Vector3d> m_points;
  std::vector<Fit_face_corners> m_corners, m_neighbours;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_OUTPUT_MESH_H
