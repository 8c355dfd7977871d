#include "Streamed_mesh_file.h"

#include "Asset_folder.h"
#include "Io_error.h"
#include "material_texture.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string_view>
#include <vector>

namespace cgal_policies {
namespace io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, path + ": " + cause);
}

// The bytes of a file from an offset on, through a buffer of a few MiB.
class Buffered_bytes {
 public:
  Buffered_bytes(const std::string& path, std::size_t offset)
      : m_path(path), m_file(std::fopen(path.c_str(), "rb"), &std::fclose) {
    if (!m_file || std::fseek(m_file.get(), long(offset), SEEK_SET) != 0) fail(path, "cannot open");
  }

  // The next n bytes (n at most 8); the file must hold them.
  const unsigned char* take(std::size_t n) {
    if (m_end - m_at < n) refill();
    if (m_end - m_at < n) fail(m_path, "truncated: the data ends before the header's elements");
    const unsigned char* bytes = m_buffer.data() + m_at;
    m_at += n;
    return bytes;
  }

  void skip(std::size_t n) {
    const std::size_t buffered = std::min(n, m_end - m_at);
    m_at += buffered;
    if (n > buffered && std::fseek(m_file.get(), long(n - buffered), SEEK_CUR) != 0)
      fail(m_path, "truncated: the data ends before the header's elements");
  }

 private:
  void refill() {
    std::copy(m_buffer.begin() + std::ptrdiff_t(m_at), m_buffer.begin() + std::ptrdiff_t(m_end),
              m_buffer.begin());
    m_end -= m_at;
    m_at = 0;
    m_end += std::fread(m_buffer.data() + m_end, 1, m_buffer.size() - m_end, m_file.get());
  }

  std::string m_path;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> m_file;
  std::vector<unsigned char> m_buffer = std::vector<unsigned char>(std::size_t(4) << 20);
  std::size_t m_at = 0, m_end = 0;
};

// The values of a binary PLY body, one at a time.
class Ply_reader {
 public:
  Ply_reader(const std::string& path, const Ply_header& header)
      : m_bytes(path, header.body), m_big_endian(header.format == Ply_format::big_endian) {}

  double next(const Ply_type& type) {
    unsigned char raw[8];
    std::copy_n(m_bytes.take(type.size), type.size, raw);
    if (m_big_endian) std::reverse(raw, raw + type.size);
    return type.decode(raw);
  }

  // Reads a list's count, which must be a whole number of at most `most`.
  std::size_t count(const std::string& path, const Ply_property& list, std::size_t most) {
    const double n = next(*list.count_type);
    if (!(n >= 0 && n <= double(most) && n == std::floor(n)))
      fail(path, "a list count of " + std::to_string(n) + " is out of range");
    return std::size_t(n);
  }

  void skip(const std::string& path, const Ply_property& property) {
    if (property.count_type)
      m_bytes.skip(count(path, property, std::size_t(1) << 30) * property.type->size);
    else
      m_bytes.skip(property.type->size);
  }

  void skip(const std::string& path, const Ply_element& element) {
    const bool fixed = std::none_of(element.properties.begin(), element.properties.end(),
                                    [](const Ply_property& p) { return p.count_type; });
    if (!fixed) {
      for (std::size_t row = 0; row < element.count; ++row)
        for (const Ply_property& p : element.properties) skip(path, p);
      return;
    }
    std::size_t row_size = 0;
    for (const Ply_property& p : element.properties) row_size += p.type->size;
    m_bytes.skip(element.count * row_size);
  }

 private:
  Buffered_bytes m_bytes;
  bool m_big_endian;
};

const Ply_element* find_element(const Ply_header& header, const char* name) {
  for (const Ply_element& element : header.elements)
    if (element.name == name) return &element;
  return nullptr;
}

int scalar_slot(const Ply_element& element, std::string_view name) {
  for (std::size_t p = 0; p < element.properties.size(); ++p)
    if (element.properties[p].name == name && !element.properties[p].count_type) return int(p);
  return -1;
}

int index_list_slot(const Ply_element& element) {
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const Ply_property& property = element.properties[p];
    if (property.count_type &&
        (property.name == "vertex_indices" || property.name == "vertex_index"))
      return int(p);
  }
  return -1;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

bool parse_number(std::string_view token, double& value) {
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() && !token.empty();
}

constexpr std::size_t kNoEntry = Corner_tables::kNoEntry;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<double, 4> kNoColor{kNaN, kNaN, kNaN, kNaN};

// The next token of `line` from `at` on, blanks skipped.
std::string_view next_token(std::string_view line, std::size_t& at) {
  while (at < line.size() && is_blank(line[at])) ++at;
  const std::size_t start = at;
  while (at < line.size() && !is_blank(line[at])) ++at;
  return line.substr(start, at - start);
}

}  // namespace

Streamed_mesh_file::Streamed_mesh_file(std::string path, Corner_attribute_reading attributes)
    : m_path(std::move(path)), m_keep(attributes == Corner_attribute_reading::keep) {
  std::ifstream file(m_path, std::ios::binary);
  if (!file) fail(m_path, "cannot open");
  std::string start(4, '\0');
  file.read(start.data(), 4);
  start.resize(std::size_t(file.gcount()));
  std::string extension = std::filesystem::path(m_path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (start != "ply\n" && start != "ply\r") {
    if (extension != ".obj") fail(m_path, "--out-of-core reads binary PLY and OBJ files only");
    m_obj = true;
    return;
  }
  // The header ends at end_header; a header longer than 1 MiB is no real one.
  file.seekg(0);
  std::string header;
  for (std::string line; header.size() < (std::size_t(1) << 20) && std::getline(file, line);) {
    header += line + '\n';
    if (line.rfind("end_header", 0) == 0) break;
  }
  m_header = parse_ply_header(m_path, header, std::filesystem::file_size(m_path));
  if (m_header.format == Ply_format::ascii)
    fail(m_path, "an ASCII PLY cannot be read out of core; write it as binary PLY first");
  const Ply_element* vertex = find_element(m_header, "vertex");
  if (!vertex) fail(m_path, "no vertex element");
  for (const char* axis : {"x", "y", "z"})
    if (scalar_slot(*vertex, axis) < 0) fail(m_path, "the vertex element has no x, y and z");
  const Ply_element* face = find_element(m_header, "face");
  if (!face || index_list_slot(*face) < 0)
    fail(m_path, "no faces (no face element with vertex_indices)");
}

std::size_t Streamed_mesh_file::declared_faces() const {
  const Ply_element* face = m_obj ? nullptr : find_element(m_header, "face");
  return face ? face->count : 0;
}

void Streamed_mesh_file::for_each_point(
    const std::function<void(double, double, double)>& f) const {
  m_points = 0;
  m_kinds = {};
  m_uvs.clear();
  m_normals.clear();
  m_colors.clear();
  m_material_libraries.clear();
  m_material_names.clear();
  const auto counted = [&](double x, double y, double z) {
    if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      fail(m_path, "vertex " + std::to_string(m_points) + ": a coordinate is not finite");
    ++m_points;
    f(x, y, z);
  };
  if (m_obj)
    for_each_obj_point(counted);
  else
    for_each_ply_point(counted);
  if (m_colors.size() > 0) m_colors.resize(m_points, kNoColor);
  m_kinds.uvs = !m_uvs.empty();
  m_kinds.normals = !m_normals.empty();
  m_kinds.colors = !m_colors.empty();
  m_kinds.materials = !m_material_names.empty();
}

Streamed_mesh_file::Kinds Streamed_mesh_file::corner_kinds() const { return m_kinds; }

bool Streamed_mesh_file::has_corner_values() const {
  return m_kinds.uvs || m_kinds.normals || m_kinds.colors;
}

Material_references Streamed_mesh_file::materials(const std::string& asset_root,
                                                  std::vector<std::string>& left_out) const {
  const Asset_folder folder(m_path, asset_root);
  Material_references materials;
  materials.libraries = material_library_paths(m_path, m_material_libraries, folder, left_out);
  materials.asset_root = folder.root().string();
  materials.names = m_material_names;
  return materials;
}

void Streamed_mesh_file::for_each_obj_point(
    const std::function<void(double, double, double)>& f) const {
  for_each_obj_line([&](std::size_t number, std::string_view line) {
    std::size_t at = 0;
    const std::string_view keyword = next_token(line, at);
    const auto numbers = [&](double* values, std::size_t most) {
      std::size_t n = 0;
      for (std::string_view token = next_token(line, at); !token.empty() && n < most;
           token = next_token(line, at))
        if (!parse_number(token, values[n++]) || !std::isfinite(values[n - 1]))
          fail(m_path, "line " + std::to_string(number) + ": '" + std::string(token.substr(0, 20)) +
                           "' is not a finite number");
      return n;
    };
    if (keyword == "v") {
      // x y z, then a weight w (skipped) or a colour r g b [a], as the reader of whole files.
      double values[7] = {0, 0, 0, 0, 0, 0, 1};
      const std::size_t n = numbers(values, 7);
      if (n < 3) fail(m_path, "line " + std::to_string(number) + ": a vertex needs three numbers");
      if (m_keep && n >= 6) {
        m_colors.resize(m_points, kNoColor);
        m_colors.push_back({values[3], values[4], values[5], values[6]});
      }
      f(values[0], values[1], values[2]);
    } else if (!m_keep) {
      return;
    } else if (keyword == "vt") {
      double uv[3] = {0, 0, 0};
      if (numbers(uv, 3) < 1)
        fail(m_path, "line " + std::to_string(number) + ": a texture coordinate needs u [v]");
      m_uvs.push_back({uv[0], uv[1]});
    } else if (keyword == "vn") {
      double normal[3];
      if (numbers(normal, 3) < 3)
        fail(m_path, "line " + std::to_string(number) + ": a normal needs three numbers, x y z");
      m_normals.push_back({normal[0], normal[1], normal[2]});
    } else if (keyword == "mtllib") {
      for (std::string_view name = next_token(line, at); !name.empty(); name = next_token(line, at))
        m_material_libraries.emplace_back(name);
    } else if (keyword == "usemtl") {
      const std::string_view name = next_token(line, at);
      if (name.empty())
        fail(m_path, "line " + std::to_string(number) + ": usemtl needs a material name");
      if (std::find(m_material_names.begin(), m_material_names.end(), name) ==
          m_material_names.end())
        m_material_names.emplace_back(name);
    }
  });
}

Corner_attributes<Point>::Values Streamed_mesh_file::corner_values(std::uint32_t v, std::size_t uv,
                                                                   std::size_t normal) const {
  Corner_attributes<Point>::Values values = Corner_attributes<Point>::no_values();
  if (m_kinds.uvs && uv != kNoEntry) values.uv = m_uvs[uv];
  if (m_kinds.normals && normal != kNoEntry)
    values.normal =
        Kernel::Vector_3(m_normals[normal][0], m_normals[normal][1], m_normals[normal][2]);
  if (m_kinds.colors) values.color = m_colors[v];
  return values;
}

void Streamed_mesh_file::for_each_triangle(const Triangle_function& f) const {
  if (m_obj)
    for_each_obj_triangle(f);
  else
    for_each_ply_triangle(f);
}

void Streamed_mesh_file::for_each_obj_triangle(const Triangle_function& f) const {
  // The entries before the line, which negative indices count back from.
  std::size_t points = 0, uvs = 0, normals = 0;
  std::uint32_t material = Corner_attributes<Point>::kNoMaterial;
  std::vector<std::array<std::size_t, 3>> polygon;  // point, uv and normal of each corner
  Corners corners;
  corners.values.fill(Corner_attributes<Point>::no_values());
  for_each_obj_line([&](std::size_t number, std::string_view line) {
    std::size_t at = 0;
    const std::string_view keyword = next_token(line, at);
    if (keyword == "v") ++points;
    if (keyword == "vt") ++uvs;
    if (keyword == "vn") ++normals;
    if (keyword == "usemtl" && m_kinds.materials) {
      const std::string_view name = next_token(line, at);
      material = std::uint32_t(std::find(m_material_names.begin(), m_material_names.end(), name) -
                               m_material_names.begin());
    }
    if (keyword != "f") return;
    polygon.clear();
    for (std::string_view token = next_token(line, at); !token.empty();
         token = next_token(line, at)) {
      const auto bad = [&](const char* why) {
        fail(m_path, "line " + std::to_string(number) + ": '" + std::string(token.substr(0, 20)) +
                         "' " + why);
      };
      std::array<std::size_t, 3> corner = {kNoEntry, kNoEntry, kNoEntry};
      // Negative indices count back from the entries before the line; a point may come later.
      const std::array<std::size_t, 3> read = {points, uvs, normals},
                                       bound = {m_points, uvs, normals};
      std::string_view rest = token;
      for (std::size_t field = 0; field < 3 && (field == 0 || !rest.empty()); ++field) {
        const std::size_t slash = rest.find('/');
        const std::string_view index = rest.substr(0, slash);
        rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
        if (field > 0 && index.empty()) continue;  // v//vn, or v/vt/
        const std::optional<std::size_t> entry = obj_index(index, read[field]);
        if (!entry || *entry >= bound[field])
          bad(field == 0   ? "names no vertex"
              : field == 1 ? "names a texture coordinate (vt) that is not read before it"
                           : "names a normal (vn) that is not read before it");
        corner[field] = *entry;
      }
      polygon.push_back(corner);
    }
    if (polygon.size() < 3)
      fail(m_path, "line " + std::to_string(number) + ": a face needs at least three corners");
    corners.material = material;
    for (std::size_t k = 2; k < polygon.size(); ++k) {
      const std::array<std::size_t, 3>* fan[3] = {&polygon[0], &polygon[k - 1], &polygon[k]};
      if (has_corner_values())
        for (int c = 0; c < 3; ++c)
          corners.values[std::size_t(c)] =
              corner_values(std::uint32_t((*fan[c])[0]), (*fan[c])[1], (*fan[c])[2]);
      f(std::uint32_t(polygon[0][0]), std::uint32_t(polygon[k - 1][0]),
        std::uint32_t(polygon[k][0]), corners);
    }
  });
}

void Streamed_mesh_file::for_each_ply_point(
    const std::function<void(double, double, double)>& f) const {
  Ply_reader values(m_path, m_header);
  for (const Ply_element& element : m_header.elements) {
    if (element.name != "vertex") {
      values.skip(m_path, element);
      continue;
    }
    Ply_vertex_slots slots = ply_vertex_slots(element);
    if (!m_keep) slots.normal[0] = slots.uv[0] = slots.color[0] = -1;
    for (std::size_t row = 0; row < element.count; ++row) {
      Ply_vertex_row vertex;
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Ply_property& property = element.properties[p];
        if (property.count_type)
          values.skip(m_path, property);
        else
          slots.place(int(p), values.next(*property.type), *property.type, vertex);
      }
      const std::string non_finite = slots.non_finite(vertex);
      if (!non_finite.empty()) fail(m_path, "vertex " + std::to_string(row) + ": " + non_finite);
      if (slots.normal[0] >= 0)
        m_normals.push_back({vertex.normal[0], vertex.normal[1], vertex.normal[2]});
      if (slots.uv[0] >= 0) m_uvs.push_back({vertex.uv[0], vertex.uv[1]});
      if (slots.color[0] >= 0) m_colors.push_back(vertex.color);
      f(vertex.xyz[0], vertex.xyz[1], vertex.xyz[2]);
    }
    return;
  }
}

void Streamed_mesh_file::for_each_ply_triangle(const Triangle_function& f) const {
  Ply_reader values(m_path, m_header);
  std::vector<std::uint32_t> polygon;
  Corners corners;
  corners.values.fill(Corner_attributes<Point>::no_values());
  for (const Ply_element& element : m_header.elements) {
    if (element.name != "face") {
      values.skip(m_path, element);
      continue;
    }
    const int indices = index_list_slot(element);
    for (std::size_t row = 0; row < element.count; ++row)
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Ply_property& property = element.properties[p];
        if (int(p) != indices) {
          values.skip(m_path, property);
          continue;
        }
        polygon.resize(values.count(m_path, property, std::size_t(1) << 20));
        for (std::uint32_t& corner : polygon) {
          const double index = values.next(*property.type);
          if (!(index >= 0 && index < double(m_points) && index == std::floor(index)))
            fail(m_path, "face " + std::to_string(row) + ": " + std::to_string(index) +
                             " is not a vertex index");
          corner = std::uint32_t(index);
        }
        if (polygon.size() < 3)
          fail(m_path, "face " + std::to_string(row) + ": a face needs at least three corners");
        for (std::size_t k = 2; k < polygon.size(); ++k) {
          const std::uint32_t fan[3] = {polygon[0], polygon[k - 1], polygon[k]};
          if (has_corner_values())  // per vertex
            for (int c = 0; c < 3; ++c)
              corners.values[std::size_t(c)] = corner_values(fan[c], fan[c], fan[c]);
          f(fan[0], fan[1], fan[2], corners);
        }
      }
    return;
  }
}

void Streamed_mesh_file::for_each_obj_line(
    const std::function<void(std::size_t, std::string_view)>& f) const {
  std::ifstream file(m_path, std::ios::binary);
  if (!file) fail(m_path, "cannot open");
  std::size_t number = 0;
  for (std::string line; std::getline(file, line);) f(++number, line);
}

}  // namespace io
}  // namespace cgal_policies
