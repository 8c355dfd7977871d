#include "ply_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace cgal_policies {
namespace io {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the PLY body is written in the machine's byte order");

template <typename T>
void append_raw(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

void append_values(std::string& bytes, std::initializer_list<double> values) {
  for (const double value : values) append_raw(bytes, std::isnan(value) ? 0.0 : value);
}

std::uint8_t channel_byte(double channel) {
  if (std::isnan(channel)) return 0;
  return std::uint8_t(std::lround(std::clamp(channel, 0.0, 1.0) * 255));
}

}  // namespace

std::string ply_bytes(const Wedge_mesh& mesh) {
  const bool normals = !mesh.normals.empty(), uvs = !mesh.uvs.empty(),
             colors = !mesh.colors.empty();
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment written by cgal_policies\n";
  bytes += "element vertex " + std::to_string(mesh.points.size()) + "\n";
  for (const char* name : {"x", "y", "z"}) bytes += std::string("property double ") + name + "\n";
  if (normals)
    for (const char* name : {"nx", "ny", "nz"})
      bytes += std::string("property double ") + name + "\n";
  if (uvs) bytes += "property double s\nproperty double t\n";
  if (colors)
    for (const char* name : {"red", "green", "blue", "alpha"})
      bytes += std::string("property uchar ") + name + "\n";
  bytes += "element face " + std::to_string(mesh.triangles.size()) + "\n";
  bytes += "property list uchar uint vertex_indices\nend_header\n";

  const std::size_t vertex_size = 8 * (3 + (normals ? 3 : 0) + (uvs ? 2 : 0)) + (colors ? 4 : 0);
  bytes.reserve(bytes.size() + mesh.points.size() * vertex_size + mesh.triangles.size() * 13);
  for (std::size_t w = 0; w < mesh.points.size(); ++w) {
    const Point& p = mesh.points[w];
    append_values(bytes, {p.x(), p.y(), p.z()});
    if (normals)
      append_values(bytes, {mesh.normals[w].x(), mesh.normals[w].y(), mesh.normals[w].z()});
    if (uvs) append_values(bytes, {mesh.uvs[w][0], mesh.uvs[w][1]});
    if (colors)
      for (const double channel : mesh.colors[w]) append_raw(bytes, channel_byte(channel));
  }
  for (const auto& triangle : mesh.triangles) {
    append_raw(bytes, std::uint8_t(3));
    for (const std::uint32_t index : triangle) append_raw(bytes, index);
  }
  return bytes;
}

}  // namespace io
}  // namespace cgal_policies
