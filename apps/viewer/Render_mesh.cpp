#include "Render_mesh.h"

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>

namespace apps {

Mesh_frame Mesh_frame::of(const Indexed_mesh& original) {
  CGAL::Bbox_3 box;
  for (const auto& t : original.triangles)
    for (std::uint32_t v : t) box += original.points[v].bbox();
  Mesh_frame frame;
  if (original.triangles.empty()) return frame;
  frame.center = Point((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                       (box.zmin() + box.zmax()) / 2);
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  frame.scale = diagonal > 0 ? 1 / diagonal : 1;
  return frame;
}

std::array<float, 3> heat_color(double t) {
  static constexpr std::array<std::array<float, 3>, 5> kStops = {{{0.10f, 0.20f, 0.85f},
                                                                  {0.10f, 0.75f, 0.90f},
                                                                  {0.20f, 0.80f, 0.25f},
                                                                  {0.95f, 0.85f, 0.10f},
                                                                  {0.85f, 0.10f, 0.10f}}};
  const double x = std::clamp(t, 0.0, 1.0) * double(kStops.size() - 1);
  const std::size_t i = std::min(std::size_t(x), kStops.size() - 2);
  const float w = float(x - double(i));
  std::array<float, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = (1 - w) * kStops[i][k] + w * kStops[i + 1][k];
  return c;
}

Render_mesh make_render_mesh(const Indexed_mesh& mesh, const Mesh_frame& frame,
                             const std::vector<double>& values, double max_value) {
  // Area-weighted vertex normals: the cross product's length is twice the area.
  std::vector<Kernel::Vector_3> normals(mesh.points.size(), CGAL::NULL_VECTOR);
  for (const auto& t : mesh.triangles) {
    const Kernel::Vector_3 n = CGAL::cross_product(mesh.points[t[1]] - mesh.points[t[0]],
                                                   mesh.points[t[2]] - mesh.points[t[0]]);
    for (std::uint32_t v : t) normals[v] = normals[v] + n;
  }
  Render_mesh result;
  result.vertices.reserve(mesh.points.size() * Render_mesh::kFloatsPerVertex);
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    const Kernel::Vector_3 p = (mesh.points[v] - frame.center) * frame.scale;
    const double length = std::sqrt(normals[v].squared_length());
    const Kernel::Vector_3 n = length > 0 ? normals[v] / length : CGAL::NULL_VECTOR;
    const std::array<float, 3> color =
        values.empty() ? kSurfaceColor : heat_color(max_value > 0 ? values[v] / max_value : 0);
    for (double x : {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()}) result.vertices.push_back(float(x));
    result.vertices.insert(result.vertices.end(), color.begin(), color.end());
    result.vertices.insert(result.vertices.end(), {0.0f, 0.0f});
  }
  result.indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    result.indices.insert(result.indices.end(), t.begin(), t.end());
  return result;
}

Render_mesh make_corner_render_mesh(const Mesh& mesh, const Mesh_frame& frame) {
  const cgal_policies::Corner_attributes<Point> attributes(mesh);
  CGAL_precondition(attributes.uvs || attributes.colors);
  std::vector<Kernel::Vector_3> normals(mesh.num_vertices(), CGAL::NULL_VECTOR);
  for (const auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                &c = mesh.point(mesh.target(mesh.next(h)));
    const Kernel::Vector_3 n = CGAL::cross_product(b - a, c - a);
    for (const auto corner : CGAL::halfedges_around_face(h, mesh))
      normals[std::size_t(mesh.target(corner))] = normals[std::size_t(mesh.target(corner))] + n;
  }
  Render_mesh result;
  for (const auto f : mesh.faces())
    for (const auto corner : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const auto v = mesh.target(corner);
      const Kernel::Vector_3 p = (mesh.point(v) - frame.center) * frame.scale;
      const double length = std::sqrt(normals[std::size_t(v)].squared_length());
      const Kernel::Vector_3 n = length > 0 ? normals[std::size_t(v)] / length : CGAL::NULL_VECTOR;
      const auto values = attributes.values(corner);
      for (double x : {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()})
        result.vertices.push_back(float(x));
      if (attributes.colors && !std::isnan(values.color[0]))
        for (int c = 0; c < 3; ++c) result.vertices.push_back(float(values.color[std::size_t(c)]));
      else
        result.vertices.insert(result.vertices.end(), kSurfaceColor.begin(), kSurfaceColor.end());
      const bool has_uv = attributes.uvs && !std::isnan(values.uv[0]);
      result.vertices.insert(result.vertices.end(), {has_uv ? float(values.uv[0]) : 0.0f,
                                                     has_uv ? float(1 - values.uv[1]) : 0.0f});
      result.indices.push_back(std::uint32_t(result.indices.size()));
    }
  return result;
}

}  // namespace apps
