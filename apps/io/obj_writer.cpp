#include "obj_writer.h"

#include <cgal_policies/Corner_attributes.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>

namespace cgal_policies {
namespace io {
namespace {

using Attributes = cgal_policies::Corner_attributes<Point>;

void append_number(std::string& text, double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;  // shortest exact
  text.push_back(' ');
  text.append(buffer, end);
}

// Distinct values numbered from 1 in the order they are first met, as OBJ counts them.
template <std::size_t N>
class Obj_table {
 public:
  // The value's number; 0 for a value with NaN, which names none.
  std::size_t number(const std::array<double, N>& value) {
    for (double c : value)
      if (std::isnan(c)) return 0;
    const auto [it, added] = m_numbers.emplace(value, m_order.size() + 1);
    if (added) m_order.push_back(value);
    return it->second;
  }
  void write(std::string& text, const char* keyword) const {
    for (const auto& value : m_order) {
      text += keyword;
      for (double c : value) append_number(text, c);
      text.push_back('\n');
    }
  }

 private:
  std::map<std::array<double, N>, std::size_t> m_numbers;
  std::vector<std::array<double, N>> m_order;
};

// OBJ colours are per point: the first corner of v that has one gives it, as r g b, or r g b a
// when not opaque.
void append_vertex_color(std::string& text, const Mesh& mesh, const Attributes::Color_map& colors,
                         Mesh::Vertex_index v) {
  for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
    const Attributes::Color& color = colors[h];
    if (mesh.is_border(h) || std::isnan(color[0])) continue;
    for (int k = 0; k < (color[3] == 1 ? 3 : 4); ++k) append_number(text, color[k]);
    return;
  }
}

}  // namespace

std::string obj_text(const Mesh& mesh, const std::vector<std::string>& material_libraries,
                     const std::vector<std::string>& material_names) {
  const Attributes attributes(mesh);
  std::string text = "# written by cgal_policies\n";
  for (const std::string& library : material_libraries) text += "mtllib " + library + "\n";

  std::vector<std::size_t> vertex_number(mesh.number_of_vertices() +
                                         mesh.number_of_removed_vertices());
  std::size_t vertices = 0;
  for (const auto v : mesh.vertices()) {
    vertex_number[v] = ++vertices;
    const Point& p = mesh.point(v);
    text += 'v';
    for (double c : {p.x(), p.y(), p.z()}) append_number(text, c);
    if (attributes.colors) append_vertex_color(text, mesh, *attributes.colors, v);
    text.push_back('\n');
  }

  Obj_table<2> uvs;
  Obj_table<3> normals;
  std::string faces;
  std::uint32_t material = Attributes::kNoMaterial;
  for (const auto f : mesh.faces()) {
    if (attributes.materials) {
      const std::uint32_t face_material = (*attributes.materials)[f];
      if (face_material != material && face_material < material_names.size())
        faces += "usemtl " + material_names[face_material] + "\n";
      material = face_material;
    }
    faces += 'f';
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t uv = attributes.uvs ? uvs.number((*attributes.uvs)[h]) : 0;
      std::size_t normal = 0;
      if (attributes.normals) {
        const auto& n = (*attributes.normals)[h];
        normal = normals.number({n.x(), n.y(), n.z()});
      }
      faces += ' ' + std::to_string(vertex_number[mesh.target(h)]);
      if (uv == 0 && normal == 0) continue;
      faces += '/';
      if (uv > 0) faces += std::to_string(uv);
      if (normal > 0) faces += '/' + std::to_string(normal);
    }
    faces.push_back('\n');
  }
  uvs.write(text, "vt");
  normals.write(text, "vn");
  return text + faces;
}

std::string mtl_text(const std::vector<Mtl_material>& materials) {
  std::string text = "# written by cgal_policies\n";
  for (const Mtl_material& material : materials) {
    text += "\nnewmtl " + material.name + "\nKd";
    for (double c : material.diffuse) append_number(text, c);
    text.push_back('\n');
    if (material.opacity < 1) {
      text += 'd';
      append_number(text, material.opacity);
      text.push_back('\n');
    }
    if (!material.diffuse_map.empty()) text += "map_Kd " + material.diffuse_map + "\n";
  }
  return text;
}

}  // namespace io
}  // namespace cgal_policies
