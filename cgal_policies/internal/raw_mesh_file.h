// A CGAL::Surface_mesh (no garbage) written as it is held: its points, its connectivity index by
// index, the vertex maps of a part (part_vertex_maps.h) and the corner attributes. Read back, it is
// the same mesh down to the numbering of its halfedges, which the policies' order of collapses
// follows; so a step of a partitioned job that reads a part another step wrote computes what an
// in-memory run computes.
#ifndef CGAL_POLICIES_INTERNAL_RAW_MESH_FILE_H
#define CGAL_POLICIES_INTERNAL_RAW_MESH_FILE_H

#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/Binary_file.h>
#include <cgal_policies/internal/part_vertex_maps.h>

#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace cgal_policies {
namespace internal {

// Version 2 holds the second set of texture coordinates, version 3 the skin influences.
constexpr std::uint64_t kRawMeshMagic = 0x33485345'4d574152;  // "RAWMESH3"

template <class Point>
void write_raw_mesh(const CGAL::Surface_mesh<Point>& mesh, const std::filesystem::path& path) {
  using Vertex = CGAL::SM_Vertex_index;
  Binary_file file(path, Binary_file::Mode::write);
  file.put(kRawMeshMagic);
  file.put(std::array<std::size_t, 3>{mesh.number_of_vertices(), mesh.number_of_edges(),
                                      mesh.number_of_faces()});
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    file.put(std::array<double, 3>{p.x(), p.y(), p.z()});
    file.put(std::uint32_t(mesh.halfedge(v)));
  }
  for (const auto h : mesh.halfedges())
    file.put(std::array<std::uint32_t, 3>{
        std::uint32_t(mesh.next(h)), std::uint32_t(mesh.target(h)), std::uint32_t(mesh.face(h))});
  for (const auto f : mesh.faces()) file.put(std::uint32_t(mesh.halfedge(f)));

  const auto lock = find_vertex_map<bool>(mesh, kLockedVertexMap);
  const auto origin = find_vertex_map<Vertex>(mesh, kOriginVertexMap);
  const Corner_attributes<Point> attributes(mesh);
  const auto kinds = attributes.kinds();
  file.put(std::array<bool, 8>{bool(lock), bool(origin), kinds.uvs, kinds.normals, kinds.colors,
                               kinds.materials, kinds.second_uvs, kinds.skins});
  for (const auto v : mesh.vertices()) {
    if (lock) file.put(bool((*lock)[v]));
    if (origin) file.put(std::uint32_t((*origin)[v]));
  }
  if (attributes.any_corner_values())
    for (const auto h : mesh.halfedges()) {
      const auto values = attributes.values(h);
      if (kinds.uvs) file.put(values.uv);
      if (kinds.normals)
        file.put(std::array<double, 3>{values.normal.x(), values.normal.y(), values.normal.z()});
      if (kinds.colors) file.put(values.color);
      if (kinds.second_uvs) file.put(values.second_uv);
      if (kinds.skins) {
        file.put(values.skin.joints);
        file.put(values.skin.weights);
      }
    }
  if (kinds.materials)
    for (const auto f : mesh.faces()) file.put((*attributes.materials)[f]);
  file.close();
}

template <class Point>
CGAL::Surface_mesh<Point> read_raw_mesh(const std::filesystem::path& path) {
  using Mesh = CGAL::Surface_mesh<Point>;
  using Vertex = CGAL::SM_Vertex_index;
  using Halfedge = CGAL::SM_Halfedge_index;
  using Face = CGAL::SM_Face_index;
  Binary_file file(path, Binary_file::Mode::read);
  if (file.get<std::uint64_t>() != kRawMeshMagic) file.fail("not a mesh in");
  const auto [vertices, edges, faces] = file.get<std::array<std::size_t, 3>>();
  const std::size_t halfedges = 2 * edges;
  const std::uintmax_t least_size = vertices * 28 + halfedges * 12 + faces * 4;
  if (vertices >= UINT32_MAX || halfedges >= UINT32_MAX || faces >= UINT32_MAX ||
      std::filesystem::file_size(path) < least_size)
    file.fail("not a mesh in");
  // Each index in range, or null where null is allowed.
  const auto checked = [&](std::uint32_t index, std::size_t count, bool null_allowed) {
    if (index >= count && !(null_allowed && index == std::uint32_t(-1))) file.fail("not a mesh in");
    return index;
  };

  Mesh mesh;
  mesh.reserve(vertices, edges, faces);
  std::vector<std::uint32_t> vertex_halfedge(vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto p = file.get<std::array<double, 3>>();
    mesh.add_vertex(Point(p[0], p[1], p[2]));
    vertex_halfedge[v] = checked(file.get<std::uint32_t>(), halfedges, true);
  }
  for (std::size_t e = 0; e < edges; ++e) mesh.add_edge();
  for (std::size_t f = 0; f < faces; ++f) mesh.add_face();
  for (std::size_t h = 0; h < halfedges; ++h) {
    const auto [next, target, face] = file.get<std::array<std::uint32_t, 3>>();
    mesh.set_next(Halfedge(h), Halfedge(checked(next, halfedges, false)));
    mesh.set_target(Halfedge(h), Vertex(checked(target, vertices, false)));
    mesh.set_face(Halfedge(h), Face(checked(face, faces, true)));
  }
  for (std::size_t v = 0; v < vertices; ++v)
    mesh.set_halfedge(Vertex(v), Halfedge(vertex_halfedge[v]));
  for (const auto f : mesh.faces())
    mesh.set_halfedge(f, Halfedge(checked(file.get<std::uint32_t>(), halfedges, false)));

  const auto [has_lock, has_origin, uvs, normals, colors, materials, second_uvs, skins] =
      file.get<std::array<bool, 8>>();
  std::optional<typename Mesh::template Property_map<Vertex, bool>> lock;
  std::optional<typename Mesh::template Property_map<Vertex, Vertex>> origin;
  if (has_lock) lock = mesh.template add_property_map<Vertex, bool>(kLockedVertexMap, false).first;
  if (has_origin) origin = mesh.template add_property_map<Vertex, Vertex>(kOriginVertexMap).first;
  for (const auto v : mesh.vertices()) {
    if (lock) (*lock)[v] = file.get<bool>();
    if (origin) (*origin)[v] = Vertex(file.get<std::uint32_t>());
  }
  const auto attributes =
      Corner_attributes<Point>::add(mesh, {uvs, normals, colors, materials, second_uvs, skins});
  if (attributes.any_corner_values())
    for (const auto h : mesh.halfedges()) {
      auto values = Corner_attributes<Point>::no_values();
      if (uvs) values.uv = file.get<typename Corner_attributes<Point>::Uv>();
      if (normals) {
        const auto n = file.get<std::array<double, 3>>();
        values.normal = typename Corner_attributes<Point>::Vector(n[0], n[1], n[2]);
      }
      if (colors) values.color = file.get<typename Corner_attributes<Point>::Color>();
      if (second_uvs) values.second_uv = file.get<typename Corner_attributes<Point>::Uv>();
      if (skins) {
        values.skin.joints = file.get<std::array<std::uint16_t, 4>>();
        values.skin.weights = file.get<std::array<double, 4>>();
      }
      attributes.set_values(h, values);
    }
  if (materials)
    for (const auto f : mesh.faces()) (*attributes.materials)[f] = file.get<std::uint32_t>();
  return mesh;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_RAW_MESH_FILE_H
