#include "soup_readers.h"

#include "Io_error.h"
#include "ply_header.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>

namespace cgal_policies {
namespace io {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, source + ": " + cause);
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }

// A number of text, or nothing unless the whole token is one; from_chars takes no leading '+',
// which files do write. As a size_t it is a count or an index: whole and at least 0.
template <typename Number>
std::optional<Number> number_of(std::string_view token) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  Number value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// Whitespace-separated tokens of a piece of text.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : m_text(text) {}
  // The next token; empty at the end.
  std::string_view next() {
    while (m_at < m_text.size() && is_blank(m_text[m_at])) ++m_at;
    const std::size_t start = m_at;
    while (m_at < m_text.size() && !is_blank(m_text[m_at])) ++m_at;
    return m_text.substr(start, m_at - start);
  }

 private:
  std::string_view m_text;
  std::size_t m_at = 0;
};

// The lines of a text one by one, with OFF's and OBJ's # comments cut off; lines left blank are
// skipped.
class Content_lines {
 public:
  explicit Content_lines(std::string_view text) : m_text(text) {}
  std::optional<std::string_view> next() {
    while (m_at < m_text.size()) {
      std::size_t end = m_text.find('\n', m_at);
      if (end == std::string_view::npos) end = m_text.size();
      std::string_view line = m_text.substr(m_at, end - m_at);
      m_at = end + 1;
      ++m_number;
      line = line.substr(0, line.find('#'));
      if (std::any_of(line.begin(), line.end(), [](char c) { return !is_blank(c); })) return line;
    }
    return std::nullopt;
  }
  // The number of the line `next` gave last, from 1.
  std::size_t number() const { return m_number; }

 private:
  std::string_view m_text;
  std::size_t m_at = 0, m_number = 0;
};

// The next three tokens as x y z; nothing unless all three are numbers.
std::optional<Point> next_point(Tokens& tokens) {
  double xyz[3];
  for (double& c : xyz) {
    const std::optional<double> value = number_of<double>(tokens.next());
    if (!value) return std::nullopt;
    c = *value;
  }
  return Point(xyz[0], xyz[1], xyz[2]);
}

// --- OFF ---

// "OFF" with any of the prefixes ST, C and N, in that order.
bool is_off_keyword(std::string_view keyword) {
  for (const char* prefix : {"ST", "C", "N"})
    if (keyword.substr(0, std::strlen(prefix)) == prefix)
      keyword.remove_prefix(std::strlen(prefix));
  return keyword == "OFF";
}

}  // namespace

Polygon_soup parse_off(const std::string& source, std::string_view bytes) {
  Content_lines lines(bytes);
  const std::optional<std::string_view> first = lines.next();
  if (!first) fail(source, "not an OFF file (no header)");
  Tokens header(*first);
  const std::string_view keyword = header.next();
  if (!is_off_keyword(keyword))
    fail(source, "not an OFF file: the header is '" + std::string(keyword.substr(0, 20)) +
                     "' (OFF, COFF, NOFF or STOFF; 4OFF, nOFF and binary OFF are not read)");
  Tokens counts(first->substr(std::size_t(keyword.data() - first->data()) + keyword.size()));
  std::string_view vertices_token = counts.next();
  if (vertices_token.empty()) {
    const std::optional<std::string_view> line = lines.next();
    if (!line) fail(source, "truncated: no vertex and face counts");
    counts = Tokens(*line);
    vertices_token = counts.next();
  }
  if (vertices_token == "BINARY") fail(source, "binary OFF is not read (write it as text)");
  const std::optional<std::size_t> vertices = number_of<std::size_t>(vertices_token);
  const std::optional<std::size_t> faces = number_of<std::size_t>(counts.next());
  if (!vertices || !faces) fail(source, "the vertex and face counts are not whole numbers");
  // Each vertex and face takes at least two bytes: a larger count is a forged or cut header.
  if (*vertices > bytes.size() / 2 || *faces > bytes.size() / 2)
    fail(source, "declares " + std::to_string(*vertices) + " vertices and " +
                     std::to_string(*faces) + " faces in a file of " +
                     std::to_string(bytes.size()) + " bytes");

  Polygon_soup soup;
  soup.points.reserve(*vertices);
  for (std::size_t i = 0; i < *vertices; ++i) {
    const std::optional<std::string_view> line = lines.next();
    if (!line) fail(source, "truncated: vertex " + std::to_string(i) + " is missing");
    Tokens tokens(*line);
    const std::optional<Point> point = next_point(tokens);
    if (!point) fail(source, "vertex " + std::to_string(i) + ": x y z are not three numbers");
    soup.points.push_back(*point);  // what follows (normal, colour) is skipped
  }
  soup.polygons.reserve(*faces);
  for (std::size_t f = 0; f < *faces; ++f) {
    const std::optional<std::string_view> line = lines.next();
    if (!line) fail(source, "truncated: face " + std::to_string(f) + " is missing");
    Tokens tokens(*line);
    const std::optional<std::size_t> corners = number_of<std::size_t>(tokens.next());
    if (!corners || *corners < 3 || *corners > line->size())
      fail(source, "face " + std::to_string(f) + ": the corner count is not a number of 3 or more");
    std::vector<std::size_t> polygon(*corners);
    for (std::size_t& index : polygon) {
      const std::optional<std::size_t> value = number_of<std::size_t>(tokens.next());
      if (!value) fail(source, "face " + std::to_string(f) + ": a corner is not a vertex index");
      index = *value;
    }
    soup.polygons.push_back(std::move(polygon));  // a colour after the corners is skipped
  }
  return soup;
}

namespace {

// --- OBJ ---

constexpr std::size_t kNoEntry = Corner_tables::kNoEntry;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<double, 4> kNoColor{kNaN, kNaN, kNaN, kNaN};

// A corner of an OBJ face, "v", "v/vt", "v//vn" or "v/vt/vn".
struct Obj_corner {
  std::size_t point = 0, uv = kNoEntry, normal = kNoEntry;
};

// The corner, or the reason it is not one. A texture coordinate or normal must be read before
// the face that names it; a point may come after (the reader checks every index at the end).
std::optional<Obj_corner> obj_corner(std::string_view token, const Polygon_soup& soup,
                                     std::string& why) {
  const std::size_t first_slash = token.find('/');
  Obj_corner corner;
  const std::optional<std::size_t> point =
      obj_index(token.substr(0, first_slash), soup.points.size());
  if (!point) {
    why = "is not a vertex index (1 and up, or negative to count back)";
    return std::nullopt;
  }
  corner.point = *point;
  if (first_slash == std::string_view::npos) return corner;
  const std::string_view rest = token.substr(first_slash + 1);
  const std::size_t second_slash = rest.find('/');
  const std::string_view uv = rest.substr(0, second_slash);
  const std::string_view normal =
      second_slash == std::string_view::npos ? std::string_view() : rest.substr(second_slash + 1);
  // The entry `index` names among the `read` entries of its table read so far.
  const auto entry = [&](std::string_view index, std::size_t read, const char* what,
                         std::size_t& found) {
    const std::optional<std::size_t> named = obj_index(index, read);
    if (named && *named < read) {
      found = *named;
      return true;
    }
    why = std::string("names a ") + what + " that is not read before it";
    return false;
  };
  if (!uv.empty() && !entry(uv, soup.corners.uvs.size(), "texture coordinate (vt)", corner.uv))
    return std::nullopt;
  if (!normal.empty() && !entry(normal, soup.corners.normals.size(), "normal (vn)", corner.normal))
    return std::nullopt;
  if (uv.empty() && (second_slash == std::string_view::npos || normal.empty())) {
    why = "has a slash but names no texture coordinate or normal";
    return std::nullopt;
  }
  return corner;
}

// Appends a polygon's entries to `lists` (one list per polygon), which stays empty until some
// polygon names an entry; the polygons before that one get lists of `none`.
template <typename Entry>
void add_polygon_entries(std::vector<Entry> entries, Entry none, const Polygon_soup& soup,
                         std::vector<std::vector<Entry>>& lists) {
  if (lists.empty() &&
      std::all_of(entries.begin(), entries.end(), [&](const Entry& e) { return e == none; }))
    return;
  for (std::size_t f = lists.size(); f < soup.polygons.size(); ++f)
    lists.emplace_back(soup.polygons[f].size(), none);
  lists.push_back(std::move(entries));
}

// Pads `lists`, when not empty, with lists of `none` up to one per polygon.
template <typename Entry>
void pad_polygon_entries(Entry none, const Polygon_soup& soup,
                         std::vector<std::vector<Entry>>& lists) {
  if (lists.empty()) return;
  for (std::size_t f = lists.size(); f < soup.polygons.size(); ++f)
    lists.emplace_back(soup.polygons[f].size(), none);
}

}  // namespace

std::optional<std::size_t> obj_index(std::string_view token, std::size_t so_far) {
  const std::optional<long long> index = number_of<long long>(token);
  if (!index || *index == 0) return std::nullopt;
  if (*index > 0) return std::size_t(*index - 1);
  const auto back = std::size_t(-(*index + 1)) + 1;  // no overflow at the lowest long long
  if (back > so_far) return std::nullopt;
  return so_far - back;
}

Polygon_soup parse_obj(const std::string& source, std::string_view bytes) {
  Polygon_soup soup;
  Corner_tables& corners = soup.corners;
  std::uint32_t material = Corner_tables::kNoMaterial;
  Content_lines lines(bytes);
  for (std::optional<std::string_view> line = lines.next(); line; line = lines.next()) {
    Tokens tokens(*line);
    const std::string_view keyword = tokens.next();
    const auto where = [&] { return "line " + std::to_string(lines.number()) + ": "; };
    if (keyword == "v") {
      const std::optional<Point> point = next_point(tokens);
      if (!point) fail(source, where() + "a vertex needs three numbers, x y z");
      soup.points.push_back(*point);
      // After x y z: a weight w (skipped), or a colour r g b [a] (MeshLab's and others' custom).
      std::array<double, 4> color{0, 0, 0, 1};
      int channels = 0;
      for (std::string_view token = tokens.next(); !token.empty() && channels < 4;
           token = tokens.next()) {
        const std::optional<double> value = number_of<double>(token);
        if (!value || !std::isfinite(*value))
          fail(source, where() + "a vertex's colour needs three or four finite numbers");
        color[std::size_t(channels++)] = *value;
      }
      if (channels >= 3) {
        corners.colors.resize(soup.points.size() - 1, kNoColor);
        corners.colors.push_back(color);
      }
    } else if (keyword == "vt") {
      const std::optional<double> u = number_of<double>(tokens.next());
      const std::string_view v_token = tokens.next();
      const std::optional<double> v = v_token.empty() ? 0.0 : number_of<double>(v_token);
      if (!u || !v || !std::isfinite(*u) || !std::isfinite(*v))
        fail(source, where() + "a texture coordinate needs one or two finite numbers, u [v]");
      corners.uvs.push_back({*u, *v});  // a w after them is skipped
    } else if (keyword == "vn") {
      const std::optional<Point> normal = next_point(tokens);
      if (!normal || !std::isfinite(normal->x()) || !std::isfinite(normal->y()) ||
          !std::isfinite(normal->z()))
        fail(source, where() + "a normal needs three finite numbers, x y z");
      corners.normals.push_back(*normal - CGAL::ORIGIN);
    } else if (keyword == "f") {
      std::vector<std::size_t> polygon, uvs, normals;
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        std::string why;
        const std::optional<Obj_corner> corner = obj_corner(token, soup, why);
        if (!corner) fail(source, where() + "'" + std::string(token.substr(0, 20)) + "' " + why);
        polygon.push_back(corner->point);
        uvs.push_back(corner->uv);
        normals.push_back(corner->normal);
      }
      if (polygon.size() < 3) fail(source, where() + "a face needs at least three corners");
      add_polygon_entries(std::move(uvs), kNoEntry, soup, corners.polygon_uvs);
      add_polygon_entries(std::move(normals), kNoEntry, soup, corners.polygon_normals);
      // The list starts at the first face that has a material, which may be the file's first.
      if (material != Corner_tables::kNoMaterial || !corners.polygon_materials.empty()) {
        corners.polygon_materials.resize(soup.polygons.size(), Corner_tables::kNoMaterial);
        corners.polygon_materials.push_back(material);
      }
      soup.polygons.push_back(std::move(polygon));
    } else if (keyword == "mtllib") {
      for (std::string_view name = tokens.next(); !name.empty(); name = tokens.next())
        corners.material_libraries.emplace_back(name);
    } else if (keyword == "usemtl") {
      const std::string_view name = tokens.next();
      if (name.empty()) fail(source, where() + "usemtl needs a material name");
      const auto known =
          std::find(corners.material_names.begin(), corners.material_names.end(), name);
      material = std::uint32_t(known - corners.material_names.begin());
      if (known == corners.material_names.end()) corners.material_names.emplace_back(name);
    }
    // Groups, smoothing groups, lines and the rest say nothing about the surface.
  }
  pad_polygon_entries(kNoEntry, soup, corners.polygon_uvs);
  pad_polygon_entries(kNoEntry, soup, corners.polygon_normals);
  if (!corners.colors.empty()) {  // per point: every corner takes its point's entry
    corners.colors.resize(soup.points.size(), kNoColor);
    corners.polygon_colors = soup.polygons;
  }
  if (!corners.polygon_materials.empty())
    corners.polygon_materials.resize(soup.polygons.size(), Corner_tables::kNoMaterial);
  return soup;
}

namespace {

// --- PLY ---

template <typename T>
double decode_as(const unsigned char* raw) {
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return double(value);
}

template <typename T>
constexpr double largest() {
  return double(std::numeric_limits<T>::max());
}

const Ply_type kPlyTypes[] = {
    {"char", "int8", 1, decode_as<std::int8_t>, largest<std::int8_t>()},
    {"uchar", "uint8", 1, decode_as<std::uint8_t>, largest<std::uint8_t>()},
    {"short", "int16", 2, decode_as<std::int16_t>, largest<std::int16_t>()},
    {"ushort", "uint16", 2, decode_as<std::uint16_t>, largest<std::uint16_t>()},
    {"int", "int32", 4, decode_as<std::int32_t>, largest<std::int32_t>()},
    {"uint", "uint32", 4, decode_as<std::uint32_t>, largest<std::uint32_t>()},
    {"float", "float32", 4, decode_as<float>, 1},
    {"double", "float64", 8, decode_as<double>, 1}};

// The type of that name; nullptr for none.
const Ply_type* ply_type(std::string_view name) {
  for (const Ply_type& type : kPlyTypes)
    if (name == type.name || name == type.sized_name) return &type;
  return nullptr;
}

}  // namespace

Ply_vertex_slots ply_vertex_slots(const Ply_element& vertex) {
  const auto slot = [&](std::string_view name) {
    for (std::size_t p = 0; p < vertex.properties.size(); ++p)
      if (vertex.properties[p].name == name && !vertex.properties[p].count_type) return int(p);
    return -1;
  };
  Ply_vertex_slots slots;
  for (int axis = 0; axis < 3; ++axis) {
    slots.xyz[axis] = slot(std::string(1, char('x' + axis)));
    slots.normal[axis] = slot("n" + std::string(1, char('x' + axis)));
  }
  if (std::count(slots.normal, slots.normal + 3, -1) > 0) slots.normal[0] = -1;
  // The names texture coordinates go by in the PLY files of common tools.
  for (const auto& [u, v] : {std::pair<const char*, const char*>{"s", "t"},
                             {"u", "v"},
                             {"texture_u", "texture_v"},
                             {"texture_s", "texture_t"}})
    if (slots.uv[0] < 0 && slot(u) >= 0 && slot(v) >= 0) {
      slots.uv[0] = slot(u);
      slots.uv[1] = slot(v);
    }
  // Colours: red, green and blue (alpha if there), with or without MeshLab's "diffuse_".
  for (const std::string prefix : {"", "diffuse_"}) {
    if (slots.color[0] >= 0) break;
    for (int k = 0; k < 4; ++k)
      slots.color[k] = slot(prefix + std::array{"red", "green", "blue", "alpha"}[k]);
    if (std::count(slots.color, slots.color + 3, -1) > 0) slots.color[0] = -1;
  }
  return slots;
}

void Ply_vertex_slots::place(int p, double value, const Ply_type& type, Ply_vertex_row& row) const {
  for (int axis = 0; axis < 3; ++axis) {
    if (xyz[axis] == p) row.xyz[axis] = value;
    if (normal[axis] == p) row.normal[axis] = value;
  }
  for (int k = 0; k < 2; ++k)
    if (uv[k] == p) row.uv[k] = value;
  for (int k = 0; k < 4; ++k)
    if (color[k] == p) row.color[std::size_t(k)] = value / type.full_intensity;
}

std::string Ply_vertex_slots::non_finite(const Ply_vertex_row& row) const {
  const auto finite = [](const double* values, std::size_t n) {
    return std::all_of(values, values + n, [](double x) { return std::isfinite(x); });
  };
  if (normal[0] >= 0 && !finite(row.normal, 3)) return "its normal is not finite";
  if (uv[0] >= 0 && !finite(row.uv, 2)) return "its texture coordinate is not finite";
  if (color[0] >= 0 && !finite(row.color.data(), 4)) return "its colour is not finite";
  return "";
}

Ply_header parse_ply_header(const std::string& source, std::string_view bytes,
                            std::size_t file_size) {
  if (bytes.substr(0, 4) != "ply\n" && bytes.substr(0, 5) != "ply\r\n")
    fail(source, "not a PLY file (it does not start with 'ply')");
  Ply_header header;
  bool has_format = false;
  std::size_t at = bytes.find('\n') + 1;
  for (std::size_t line_number = 2;; ++line_number) {
    const std::size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos) fail(source, "truncated header (no end_header)");
    Tokens tokens(bytes.substr(at, end - at));
    at = end + 1;
    const std::string_view keyword = tokens.next();
    const std::string where = "header line " + std::to_string(line_number) + ": ";
    if (keyword == "end_header") break;
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "format") {
      const std::string_view format = tokens.next();
      if (format == "ascii")
        header.format = Ply_format::ascii;
      else if (format == "binary_little_endian")
        header.format = Ply_format::little_endian;
      else if (format == "binary_big_endian")
        header.format = Ply_format::big_endian;
      else
        fail(source, where + "unknown format '" + std::string(format.substr(0, 30)) + "'");
      has_format = true;
    } else if (keyword == "element") {
      Ply_element element;
      element.name = tokens.next();
      const std::optional<std::size_t> count = number_of<std::size_t>(tokens.next());
      if (element.name.empty() || !count) fail(source, where + "expected 'element NAME COUNT'");
      // Each element takes at least one byte of the body.
      if (*count > file_size) fail(source, where + "declares more elements than the file holds");
      element.count = *count;
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail(source, where + "a property before any element");
      Ply_property property;
      std::string_view type = tokens.next();
      if (type == "list") {
        property.count_type = ply_type(tokens.next());
        if (!property.count_type) fail(source, where + "unknown list count type");
        type = tokens.next();
      }
      property.type = ply_type(type);
      property.name = tokens.next();
      if (!property.type || property.name.empty())
        fail(source, where + "expected 'property TYPE NAME'");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail(source, where + "unknown keyword '" + std::string(keyword.substr(0, 30)) + "'");
    }
  }
  if (!has_format) fail(source, "the header has no format line");
  header.body = at;
  return header;
}

namespace {

// The values of a PLY body, one by one, in either encoding; all of them are read as doubles,
// which hold every PLY integer exactly.
class Ply_values {
 public:
  Ply_values(const std::string& source, std::string_view body, Ply_format format)
      : m_source(source), m_body(body), m_format(format), m_tokens(body) {}

  double next(const Ply_type& type) {
    if (m_format == Ply_format::ascii) {
      const std::string_view token = m_tokens.next();
      if (token.empty()) fail(m_source, "truncated: the data ends before the header's elements");
      const std::optional<double> value = number_of<double>(token);
      if (!value) fail(m_source, "'" + std::string(token.substr(0, 30)) + "' is not a number");
      return *value;
    }
    if (m_body.size() - m_at < type.size)
      fail(m_source, "truncated: the data ends before the header's elements");
    unsigned char raw[8];
    std::memcpy(raw, m_body.data() + m_at, type.size);
    m_at += type.size;
    if (m_format == Ply_format::big_endian) std::reverse(raw, raw + type.size);
    return type.decode(raw);
  }

  // An upper bound of the values left: a list longer than that is a forged count.
  std::size_t values_left() const { return m_body.size() - m_at; }

 private:
  const std::string& m_source;
  std::string_view m_body;
  Ply_format m_format;
  Tokens m_tokens;       // ascii
  std::size_t m_at = 0;  // binary
};

bool is_index_list(const Ply_property& p) {
  return p.count_type && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// Where the PLY reader puts faces: polygons of any size, one vector each...
struct Polygon_faces {
  std::vector<std::vector<std::size_t>>& polygons;

  void reserve(std::size_t more) { polygons.reserve(polygons.size() + more); }
  bool add_polygon(const std::vector<double>& corners) {
    polygons.emplace_back(corners.begin(), corners.end());
    return true;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) { polygons.push_back({a, b, c}); }
};

// ... or triangles, three corners each in one list, without an allocation a face; a polygon of
// another size is refused.
struct Flat_triangle_faces {
  std::vector<std::size_t>& corners;

  void reserve(std::size_t more) { corners.reserve(corners.size() + 3 * more); }
  bool add_polygon(const std::vector<double>& polygon) {
    if (polygon.size() != 3) return false;
    corners.insert(corners.end(), polygon.begin(), polygon.end());
    return true;
  }
  void add_triangle(std::size_t a, std::size_t b, std::size_t c) {
    corners.insert(corners.end(), {a, b, c});
  }
};

// Triangles of a strip, alternately turned so that all face the same way; -1 restarts the strip,
// and the degenerate triangles strips use to turn are left out.
template <class Faces>
void add_strip_triangles(const std::vector<double>& strip, Faces& faces) {
  std::size_t run_start = 0;
  for (std::size_t k = 0; k < strip.size(); ++k) {
    if (strip[k] < 0) {
      run_start = k + 1;
      continue;
    }
    if (k < run_start + 2) continue;
    std::size_t a = std::size_t(strip[k - 2]), b = std::size_t(strip[k - 1]);
    const std::size_t c = std::size_t(strip[k]);
    if ((k - run_start) % 2 == 1) std::swap(a, b);
    if (a != b && b != c && a != c) faces.add_triangle(a, b, c);
  }
}

// The body of parse_ply: the points into `points`, the vertices' normals, texture coordinates
// and colours into `values` (left out when null), the faces into `faces`. False as soon as
// `faces` refuses a face, or, with `no_values`, when the vertices carry values.
template <class Faces>
bool read_ply(const std::string& source, std::string_view bytes, std::vector<Point>& points,
              Corner_tables* values, bool no_values, Faces faces) {
  const Ply_header header = parse_ply_header(source, bytes, bytes.size());
  Ply_values reader(source, bytes.substr(header.body), header.format);
  bool has_points = false, has_faces = false;
  std::vector<double> list;
  for (const Ply_element& element : header.elements) {
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face",
               is_strip = element.name == "tristrips";
    const Ply_vertex_slots slots = is_vertex ? ply_vertex_slots(element) : Ply_vertex_slots();
    if (is_vertex) {
      if (std::count(slots.xyz, slots.xyz + 3, -1) > 0)
        fail(source, "the vertex element has no x, y and z");
      has_points = true;
      if (no_values && (slots.normal[0] >= 0 || slots.uv[0] >= 0 || slots.color[0] >= 0))
        return false;
      points.reserve(element.count);
    }
    if (is_face) faces.reserve(element.count);
    has_faces = has_faces ||
                ((is_face || is_strip) &&
                 std::any_of(element.properties.begin(), element.properties.end(), is_index_list));
    for (std::size_t row = 0; row < element.count; ++row) {
      Ply_vertex_row vertex;
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Ply_property& property = element.properties[p];
        if (!property.count_type) {
          slots.place(int(p), reader.next(*property.type), *property.type, vertex);
          continue;
        }
        const double count = reader.next(*property.count_type);
        if (!(count >= 0 && count <= double(reader.values_left())) || count != std::floor(count))
          fail(source, element.name + " " + std::to_string(row) + ": a list count of " +
                           std::to_string(count) + " does not fit in the file");
        list.resize(std::size_t(count));
        for (double& item : list) item = reader.next(*property.type);
        if (!((is_face || is_strip) && is_index_list(property))) continue;
        for (const double index : list)
          if (!(index == std::floor(index) && index < 1e18 &&
                (index >= 0 || (is_strip && index == -1))))
            fail(source, element.name + " " + std::to_string(row) + ": " + std::to_string(index) +
                             " is not a vertex index");
        if (is_strip)
          add_strip_triangles(list, faces);
        else if (!faces.add_polygon(list))
          return false;
      }
      if (!is_vertex) continue;
      points.emplace_back(vertex.xyz[0], vertex.xyz[1], vertex.xyz[2]);
      const std::string non_finite = slots.non_finite(vertex);
      if (!non_finite.empty()) fail(source, "vertex " + std::to_string(row) + ": " + non_finite);
      if (!values) continue;
      if (slots.normal[0] >= 0)
        values->normals.emplace_back(vertex.normal[0], vertex.normal[1], vertex.normal[2]);
      if (slots.uv[0] >= 0) values->uvs.push_back({vertex.uv[0], vertex.uv[1]});
      if (slots.color[0] >= 0) values->colors.push_back(vertex.color);
    }
  }
  if (!has_points) fail(source, "no vertex element");
  if (!has_faces) fail(source, "no faces (no face or tristrips element with vertex_indices)");
  return true;
}

}  // namespace

Polygon_soup parse_ply(const std::string& source, std::string_view bytes) {
  Polygon_soup soup;
  read_ply(source, bytes, soup.points, &soup.corners, false, Polygon_faces{soup.polygons});
  // Per-vertex values: every corner takes its vertex's entry.
  if (!soup.corners.normals.empty()) soup.corners.polygon_normals = soup.polygons;
  if (!soup.corners.uvs.empty()) soup.corners.polygon_uvs = soup.polygons;
  if (!soup.corners.colors.empty()) soup.corners.polygon_colors = soup.polygons;
  return soup;
}

std::optional<Ply_triangles> parse_ply_triangles(const std::string& source, std::string_view bytes,
                                                 bool values_wanted) {
  Ply_triangles triangles;
  if (!read_ply(source, bytes, triangles.points, nullptr, values_wanted,
                Flat_triangle_faces{triangles.corners}))
    return std::nullopt;
  return triangles;
}

void join_equal_points(Polygon_soup& soup) {
  // Hashes the exact bits, with -0 made +0 so that equal coordinates share a hash.
  struct Point_hash {
    std::size_t operator()(const Point& p) const {
      std::size_t hash = 0;
      for (const double c : {p.x() + 0.0, p.y() + 0.0, p.z() + 0.0}) {
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        hash = (hash ^ std::hash<std::uint64_t>()(bits)) * 0x9E3779B97F4A7C15ull;
      }
      return hash;
    }
  };
  std::unordered_map<Point, std::size_t, Point_hash> number_of_point;
  number_of_point.reserve(soup.points.size());
  std::vector<std::size_t> joined(soup.points.size());
  std::vector<Point> points;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const auto [it, added] = number_of_point.emplace(soup.points[i], points.size());
    if (added) points.push_back(soup.points[i]);
    joined[i] = it->second;
  }
  if (points.size() == soup.points.size()) return;
  for (auto& polygon : soup.polygons)
    for (std::size_t& index : polygon)
      if (index < joined.size()) index = joined[index];  // one out of range is reported later
  soup.points = std::move(points);
}

}  // namespace io
}  // namespace cgal_policies
