#include "Python_mesh.h"

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace cgal_policies {
namespace python {
namespace {

using Attributes = Corner_attributes<io::Point>;

// `array` as a C-contiguous array of T with `shape` (-1: any length), converted once if it is
// not one already; ValueError naming it otherwise. Integer arrays only where T is an integer,
// so that a float array of faces is refused rather than truncated.
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> checked_array(
    const py::array& array, const std::vector<py::ssize_t>& shape, const char* what,
    const char* expected) {
  const bool wants_integers = std::is_integral<T>::value;
  const char kind = array.dtype().kind();
  const bool integers = kind == 'i' || kind == 'u';
  bool fits = array.ndim() == py::ssize_t(shape.size()) &&
              (wants_integers ? integers : integers || kind == 'f');
  for (std::size_t d = 0; fits && d < shape.size(); ++d)
    fits = shape[d] < 0 || array.shape(py::ssize_t(d)) == shape[d];
  if (!fits) throw py::value_error(std::string(what) + " must be " + expected);
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(array);
}

// The halfedges of face f in the order of Python_mesh::faces.
std::array<io::Mesh::Halfedge_index, 3> corners_of(const io::Mesh& mesh, io::Mesh::Face_index f) {
  const auto h = mesh.halfedge(f);
  return {h, mesh.next(h), mesh.next(mesh.next(h))};
}

// The (m, 3, k) array of a corner map, or nothing when the mesh has no such map.
template <std::size_t K, class Map, class Read>
std::optional<py::array_t<double>> corner_array(const io::Mesh& mesh, const std::optional<Map>& map,
                                                const Read& read) {
  if (!map) return std::nullopt;
  py::array_t<double> out({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3), py::ssize_t(K)});
  double* value = out.mutable_data();
  for (const auto f : mesh.faces())
    for (const auto h : corners_of(mesh, f))
      for (std::size_t k = 0; k < K; ++k) *value++ = read((*map)[h], k);
  return out;
}

// Adds the table of one kind of corner value: entry 3f + k for corner k of face f.
template <std::size_t K, class Entry, class Make>
void add_corner_table(const std::optional<py::array>& given, std::size_t faces, const char* what,
                      const char* expected, std::vector<Entry>& table,
                      std::vector<std::vector<std::size_t>>& polygon_entries, const Make& make) {
  if (!given) return;
  const auto values =
      checked_array<double>(*given, {py::ssize_t(faces), 3, py::ssize_t(K)}, what, expected);
  const double* v = values.data();
  table.reserve(3 * faces);
  polygon_entries.reserve(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    for (std::size_t k = 0; k < 3; ++k, v += K) table.push_back(make(v));
    polygon_entries.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
}

}  // namespace

Python_mesh::Python_mesh(io::Mesh mesh_, io::Read_report read)
    : mesh(std::move(mesh_)),
      references(std::move(read.materials)),
      repairs(std::move(read.repairs)) {}

Python_mesh Python_mesh::from_arrays(const py::array& vertices, const py::array& faces,
                                     const Corner_arrays& corners) {
  const auto points =
      checked_array<double>(vertices, {-1, 3}, "vertices", "an (n, 3) array of floats");
  const auto triangles =
      checked_array<std::int64_t>(faces, {-1, 3}, "faces", "an (m, 3) array of integers");
  const std::size_t face_count = std::size_t(triangles.shape(0));
  io::Corner_tables tables;
  add_corner_table<2>(corners.uv, face_count, "uv", "an (m, 3, 2) array of floats", tables.uvs,
                      tables.polygon_uvs, [](const double* v) {
                        return std::array<double, 2>{v[0], v[1]};
                      });
  add_corner_table<3>(corners.normals, face_count, "normals", "an (m, 3, 3) array of floats",
                      tables.normals, tables.polygon_normals,
                      [](const double* v) { return io::Kernel::Vector_3(v[0], v[1], v[2]); });
  add_corner_table<4>(corners.colors, face_count, "colors", "an (m, 3, 4) array of floats",
                      tables.colors, tables.polygon_colors, [](const double* v) {
                        return std::array<double, 4>{v[0], v[1], v[2], v[3]};
                      });
  if (corners.materials) {
    const auto materials = checked_array<std::int64_t>(
        *corners.materials, {py::ssize_t(face_count)}, "materials", "an (m,) array of integers");
    for (std::size_t f = 0; f < face_count; ++f) {
      const std::int64_t m = materials.data()[f];
      if (m < -1 || m >= std::int64_t(corners.material_names.size()))
        throw py::value_error("materials must index material_names, or be -1 for none");
      tables.polygon_materials.push_back(m < 0 ? Attributes::kNoMaterial : std::uint32_t(m));
    }
  }
  io::Read_report read;
  read.materials.names = corners.material_names;
  read.materials.libraries = corners.material_libraries;
  io::Mesh mesh;
  {
    py::gil_scoped_release released;
    std::vector<io::Point> soup_points;
    const double* xyz = points.data();
    soup_points.reserve(std::size_t(points.shape(0)));
    for (py::ssize_t i = 0; i < points.shape(0); ++i, xyz += 3)
      soup_points.emplace_back(xyz[0], xyz[1], xyz[2]);
    // A negative index wraps to one far out of range, which the reader's check names.
    const std::int64_t* corner = triangles.data();
    std::vector<std::vector<std::size_t>> polygons(face_count);
    for (std::size_t f = 0; f < face_count; ++f, corner += 3)
      polygons[f] = {std::size_t(corner[0]), std::size_t(corner[1]), std::size_t(corner[2])};
    mesh = io::triangle_mesh_from_soup("mesh", soup_points, polygons, &read, &tables);
  }
  return Python_mesh(std::move(mesh), std::move(read));
}

py::array_t<double> Python_mesh::vertices() const {
  py::array_t<double> out({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
  double* value = out.mutable_data();
  for (const auto v : mesh.vertices()) {
    const io::Point& p = mesh.point(v);
    *value++ = p.x();
    *value++ = p.y();
    *value++ = p.z();
  }
  return out;
}

py::array_t<std::int64_t> Python_mesh::faces() const {
  py::array_t<std::int64_t> out({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3)});
  std::int64_t* index = out.mutable_data();
  for (const auto f : mesh.faces())
    for (const auto h : corners_of(mesh, f)) *index++ = std::int64_t(std::size_t(mesh.target(h)));
  return out;
}

std::optional<py::array_t<double>> Python_mesh::uv() const {
  return corner_array<2>(mesh, Attributes(mesh).uvs,
                         [](const Attributes::Uv& uv, std::size_t k) { return uv[k]; });
}

std::optional<py::array_t<double>> Python_mesh::normals() const {
  return corner_array<3>(mesh, Attributes(mesh).normals,
                         [](const Attributes::Vector& n, std::size_t k) { return n[int(k)]; });
}

std::optional<py::array_t<double>> Python_mesh::colors() const {
  return corner_array<4>(mesh, Attributes(mesh).colors,
                         [](const Attributes::Color& c, std::size_t k) { return c[k]; });
}

std::optional<py::array_t<std::int64_t>> Python_mesh::materials() const {
  const auto map = Attributes(mesh).materials;
  if (!map) return std::nullopt;
  py::array_t<std::int64_t> out(py::ssize_t(mesh.number_of_faces()));
  std::int64_t* index = out.mutable_data();
  for (const auto f : mesh.faces())
    *index++ = (*map)[f] == Attributes::kNoMaterial ? -1 : std::int64_t((*map)[f]);
  return out;
}

}  // namespace python
}  // namespace cgal_policies
