#include "mesh_io.h"

#include "Asset_folder.h"
#include "Io_error.h"
#include "atomic_write.h"
#include "clean_triangle_soup.h"
#include "declared_counts.h"
#include "gltf_io.h"
#include "gltf_material_library.h"
#include "material_library_copy.h"
#include "material_texture.h"
#include "obj_writer.h"
#include "ply_writer.h"
#include "soup_readers.h"
#include "soup_repair.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <cgal_policies/Corner_attributes.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string_view>

namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {
namespace {

using Polygon = std::vector<std::size_t>;

[[noreturn]] void fail_input(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unreadable_input, path + ": " + cause);
}

void check_readable_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) fail_input(path, "cannot open: no such file");
  if (fs::is_directory(status)) fail_input(path, "cannot open: is a directory");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) fail_input(path, std::string("cannot open: ") + std::strerror(errno));
  if (probe.peek() == std::ifstream::traits_type::eof()) fail_input(path, "empty file");
  if (!has_supported_mesh_extension(path))
    fail_input(path, "unsupported format '" + lower_extension(path) +
                         "' (supported: .off, .obj, .ply, .stl, .gltf, .glb)");
}

// The whole file, read at once.
std::string file_bytes(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) fail_input(path, std::string("cannot open: ") + std::strerror(errno));
  std::string bytes;
  std::error_code size_unknown;
  const std::uintmax_t size = fs::file_size(path, size_unknown);
  if (!size_unknown) bytes.reserve(std::size_t(size));
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.append(buffer, got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) fail_input(path, "cannot read: an I/O error");
  return bytes;
}

void check_points_finite(const std::string& path, const std::vector<Point>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      fail_input(path, "non-finite coordinate at vertex " + std::to_string(i));
  }
}

void check_index(const std::string& path, std::size_t face, std::size_t index,
                 std::size_t point_count) {
  if (index >= point_count)
    fail_input(path, "face " + std::to_string(face) + " refers to vertex " + std::to_string(index) +
                         " but there are only " + std::to_string(point_count));
}

void check_soup(const std::string& path, const std::vector<Point>& points,
                const std::vector<Polygon>& polygons) {
  if (polygons.empty()) fail_input(path, "no faces");
  check_points_finite(path, points);
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (std::size_t index : polygons[f]) check_index(path, f, index, points.size());
}

std::string unused_vertices_removed(std::size_t count) {
  return "removed " + std::to_string(count) + " unused vertices";
}

using Attributes = cgal_policies::Corner_attributes<Point>;

// The maps a soup's corner tables fill.
Attributes::Kinds kinds_of(const Corner_tables& corners) {
  return {!corners.polygon_uvs.empty(),        !corners.polygon_normals.empty(),
          !corners.polygon_colors.empty(),     !corners.polygon_materials.empty(),
          !corners.polygon_second_uvs.empty(), !corners.polygon_skins.empty()};
}

bool has_corner_attributes(const Corner_tables* corners) {
  if (!corners) return false;
  const Attributes::Kinds kinds = kinds_of(*corners);
  return kinds.uvs || kinds.normals || kinds.colors || kinds.materials || kinds.second_uvs ||
         kinds.skins;
}

// Puts the attributes of `corners` on the mesh built from `polygons`, whose face i is polygon i;
// is_corner(p, v) says whether the polygon's corner at point p is the face's corner at vertex v.
template <typename Is_corner>
void set_corner_attributes(Mesh& mesh, const std::vector<Polygon>& polygons,
                           const Corner_tables& corners, const Is_corner& is_corner) {
  const Attributes attributes = Attributes::add(mesh, kinds_of(corners));
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
    if (attributes.materials) (*attributes.materials)[face] = corners.polygon_materials[f];
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(face), mesh)) {
      std::size_t k = 0;
      while (!is_corner(polygons[f][k], mesh.target(h))) ++k;
      // The corner takes the table entry its polygon names, if the mesh has the map and it names
      // one.
      const auto copy = [&](const auto& map, const auto& polygon_entries, const auto& table) {
        if (map && polygon_entries[f][k] != Corner_tables::kNoEntry)
          (*map)[h] = table[polygon_entries[f][k]];
      };
      copy(attributes.uvs, corners.polygon_uvs, corners.uvs);
      copy(attributes.normals, corners.polygon_normals, corners.normals);
      copy(attributes.colors, corners.polygon_colors, corners.colors);
      copy(attributes.second_uvs, corners.polygon_second_uvs, corners.second_uvs);
      copy(attributes.skins, corners.polygon_skins, corners.skins);
    }
  }
}

// The general path, for triangle soups that are not a clean mesh as they stand: the soup repaired
// (soup_repair.h), built, its border edges stitched.
Mesh repaired_triangle_mesh(const std::string& path, std::vector<Point>& points,
                            std::vector<Polygon>& polygons, Corner_tables* corners,
                            std::vector<std::string>& repairs) {
  repair_triangle_soup(points, polygons, corners, repairs);
  if (polygons.empty()) fail_input(path, "no faces left after dropping degenerate ones");
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  // Orienting cuts the soup wherever it is not manifold, more than it must; stitching puts back
  // together the border edges that can be joined without breaking manifoldness.
  if (const std::size_t stitched = PMP::stitch_borders(mesh))
    repairs.push_back("stitched " + std::to_string(stitched) + " border edge pairs back together");
  const std::size_t isolated = PMP::remove_isolated_vertices(mesh);
  if (isolated > 0) repairs.push_back(unused_vertices_removed(isolated));
  mesh.collect_garbage();
  if (!CGAL::is_valid_polygon_mesh(mesh)) fail_input(path, "not a valid polygon mesh");
  // Stitching keeps the faces but not their halfedges, nor which vertex is which: a corner is
  // found by its point, which differs between a repaired triangle's corners.
  if (corners)
    set_corner_attributes(mesh, polygons, *corners, [&](std::size_t p, Mesh::Vertex_index v) {
      return points[p] == mesh.point(v);
    });
  return mesh;
}

bool is_gltf(const std::string& extension) { return extension == ".gltf" || extension == ".glb"; }

// read_triangle_mesh's reading of a PLY file. A file of triangles whose vertices carry no values
// to keep is parsed into one flat list (parse_ply_triangles), without a polygon a face, checked as
// check_soup checks a soup, and built straight into the mesh when it is clean as it stands.
// Otherwise nothing, and `soup` holds the file for the general path, which repairs it: those
// triangles as polygons, or, for any other file, parse_ply's soup.
std::optional<Mesh> read_clean_ply(const std::string& path, std::string_view bytes,
                                   Read_report* report, Corner_attribute_reading attributes,
                                   std::size_t threads, Polygon_soup& soup) {
  std::optional<Ply_triangles> ply =
      parse_ply_triangles(path, bytes, attributes == Corner_attribute_reading::keep);
  if (!ply) {
    soup = parse_ply(path, bytes);
    return std::nullopt;
  }
  if (!ply->corners.empty()) {
    check_points_finite(path, ply->points);
    for (std::size_t k = 0; k < ply->corners.size(); ++k)
      check_index(path, k / 3, ply->corners[k], ply->points.size());
    Mesh mesh;
    std::size_t unused_points = 0;
    if (build_mesh_from_clean_triangles(ply->points, ply->corners, mesh, unused_points, nullptr,
                                        threads)) {
      if (report) {
        report->repairs.clear();
        if (unused_points > 0) report->repairs.push_back(unused_vertices_removed(unused_points));
        report->left_out.clear();
      }
      return mesh;
    }
  }
  soup.points = std::move(ply->points);
  soup.polygons.reserve(ply->corners.size() / 3);
  for (std::size_t k = 0; k < ply->corners.size(); k += 3)
    soup.polygons.push_back({ply->corners[k], ply->corners[k + 1], ply->corners[k + 2]});
  return std::nullopt;
}

// The mesh of `soup`, read from `path` (any format but STL; a glTF file's `gltf_looks`), as
// read_triangle_mesh makes it with `options`; its errors name `source`. An OBJ file's material
// libraries outside the asset folder get a line in `left_out`.
Mesh mesh_of_soup(const std::string& path, const std::string& source, Polygon_soup& soup,
                  std::shared_ptr<const tinygltf::Model> gltf_looks, Read_report* report,
                  const Read_options& options, std::vector<std::string>& left_out) {
  if (options.attributes == Corner_attribute_reading::drop)
    return triangle_mesh_from_soup(source, soup.points, soup.polygons, report, nullptr,
                                   options.threads);
  const Corner_tables& tables = soup.corners;
  if (lower_extension(path) == ".ply" &&
      !(tables.uvs.empty() && tables.normals.empty() && tables.colors.empty()))
    join_equal_points(soup);
  Mesh mesh = triangle_mesh_from_soup(source, soup.points, soup.polygons, report, &soup.corners,
                                      options.threads);
  const Attributes kept(mesh);
  if (report && (kept.materials || kept.skins)) {  // a glTF file's looks hold its skeleton too
    const Asset_folder folder(path, options.asset_root);
    report->materials.libraries =
        material_library_paths(path, soup.corners.material_libraries, folder, left_out);
    report->materials.asset_root = folder.root().string();
    report->materials.names = soup.corners.material_names;
    report->materials.gltf = std::move(gltf_looks);
  }
  return mesh;
}

bool write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), std::streamsize(bytes.size()));
  return bool(file.flush());
}

// One glTF file holding the levels (gltf_bytes); returns the textures left out.
std::vector<std::string> write_gltf_atomically(const std::vector<Lod_level>& levels,
                                               const std::string& path,
                                               const Material_references& materials,
                                               Gltf_encoding encoding) {
  std::vector<std::string> left_out;
  const std::string bytes = gltf_bytes(levels, lower_extension(path) == ".glb", encoding, materials,
                                       fs::absolute(path).parent_path().string(), left_out);
  write_atomically(path,
                   [&](const std::string& temporary) { return write_bytes(temporary, bytes); });
  return left_out;
}

// The materials the faces of `levels` use among `count` materials: those that the OBJ files'
// usemtl lines name (obj_text).
std::vector<bool> used_materials(const std::vector<Lod_level>& levels, std::size_t count) {
  std::vector<bool> used(count, false);
  for (const Lod_level& level : levels)
    if (const auto materials = Attributes(*level.mesh).materials)
      for (const auto f : level.mesh->faces())
        if ((*materials)[f] < count) used[(*materials)[f]] = true;
  return used;
}

// Level k into paths[k], all or none, in any format but glTF (write_mesh_atomically); OBJ files of
// a glTF input's mesh with the material library and images of gltf_material_library, named after
// `path`, in the same go; an OBJ input's libraries named from the files' folder, or copied beside
// them with their textures when they lie outside it (material_library_copy), so that the files
// name nothing outside their folder. Returns the textures left out.
std::vector<std::string> write_files_atomically(const std::vector<Lod_level>& levels,
                                                const std::string& path,
                                                const std::vector<std::string>& paths,
                                                const Material_references& materials) {
  const std::string extension = lower_extension(path);
  const bool obj = extension == ".obj";
  Gltf_material_library library;
  if (obj && materials.gltf)
    library = gltf_material_library(*materials.gltf, materials.names,
                                    used_materials(levels, materials.names.size()), path);
  Material_library_copy copy;
  if (obj) copy = material_library_copy(materials, path);
  std::vector<std::string> files = paths, left_out = library.left_out;
  for (const Gltf_material_library::File& file : library.files) files.push_back(file.path);
  for (const Material_library_copy::File& file : copy.files) files.push_back(file.path);
  left_out.insert(left_out.end(), copy.left_out.begin(), copy.left_out.end());
  if (materials.gltf) check_no_image_of(*materials.gltf, files);
  check_no_source_of(copy, files);
  if (files.size() > kMaxFilesWrittenAtOnce)
    throw Io_error(Io_error::Kind::unwritable_output,
                   path + ": cannot write " + std::to_string(files.size()) +
                       " files at once (levels, material library and images); at most " +
                       std::to_string(kMaxFilesWrittenAtOnce));
  // A glTF input's library, beside the files; an OBJ input's, named from their folder.
  std::vector<std::string> libraries = copy.names;
  if (!library.files.empty())
    libraries.insert(libraries.begin(), fs::path(library.files.front().path).filename().string());
  write_all_atomically(files, [&](std::size_t k, const std::string& temporary) {
    if (k >= levels.size() + library.files.size())
      return write_bytes(temporary, copy.files[k - levels.size() - library.files.size()].bytes);
    if (k >= levels.size()) return write_bytes(temporary, library.files[k - levels.size()].bytes);
    const Mesh& mesh = *levels[k].mesh;
    if (obj && Attributes(mesh).any())
      return write_bytes(temporary, obj_text(mesh, libraries, materials.names));
    if (extension == ".ply" && Attributes(mesh).any_corner_values())
      return write_bytes(temporary, ply_bytes(wedge_mesh(mesh)));
    return CGAL::IO::write_polygon_mesh(temporary, mesh, CGAL::parameters::stream_precision(17));
  });
  // OBJ and PLY hold one set of texture coordinates and no skin; the others no corner values at
  // all.
  if (!obj && extension != ".ply") return left_out;
  const auto any_level = [&levels](auto has) {
    return std::any_of(levels.begin(), levels.end(),
                       [&has](const Lod_level& level) { return has(Attributes(*level.mesh)); });
  };
  const std::string format = obj ? "OBJ" : "PLY";
  if (any_level([](const Attributes& a) { return a.second_uvs.has_value(); }))
    left_out.push_back(path + ": the second texture coordinates (glTF's TEXCOORD_1); " + format +
                       " holds one set, written without them");
  if (any_level([](const Attributes& a) { return a.skins.has_value(); }))
    left_out.push_back(path + ": the skin (glTF's JOINTS_0 and WEIGHTS_0); " + format +
                       " holds none, written without it");
  return left_out;
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

bool writes_corner_attributes(const std::string& path) {
  const std::string extension = lower_extension(path);
  return extension == ".obj" || extension == ".ply" || is_gltf(extension);
}

bool has_supported_mesh_extension(const std::string& path) {
  static const char* const kExtensions[] = {".off", ".obj", ".ply", ".stl", ".gltf", ".glb"};
  const std::string ext = lower_extension(path);
  return std::any_of(std::begin(kExtensions), std::end(kExtensions),
                     [&](const char* known) { return ext == known; });
}

Mesh read_triangle_mesh(const std::string& path, Read_report* report,
                        Corner_attribute_reading attributes, std::size_t threads) {
  return read_triangle_mesh(path, Read_options{attributes, threads, {}}, report);
}

Mesh read_triangle_mesh(const std::string& path, const Read_options& options, Read_report* report) {
  check_readable_file(path);
  check_declared_counts(path);
  const std::string extension = lower_extension(path);
  if (extension != ".stl") {
    std::shared_ptr<const tinygltf::Model> gltf_looks;
    std::vector<std::string> left_out;
    Polygon_soup soup;
    if (is_gltf(extension)) {
      Gltf_soup read = read_gltf(path, extension == ".glb", options.asset_root);
      gltf_looks = std::move(read.looks);
      left_out = std::move(read.left_out);
      soup = std::move(read.soup);
    } else {
      const std::string bytes = file_bytes(path);
      if (extension != ".ply")
        soup = extension == ".obj" ? parse_obj(path, bytes) : parse_off(path, bytes);
      else if (std::optional<Mesh> mesh =
                   read_clean_ply(path, bytes, report, options.attributes, options.threads, soup))
        return std::move(*mesh);
    }
    Mesh mesh = mesh_of_soup(path, path, soup, std::move(gltf_looks), report, options, left_out);
    if (report) report->left_out = std::move(left_out);
    return mesh;
  }
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool parsed = false;
  try {
    parsed = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch (const std::exception& e) {
    fail_input(path, std::string("cannot parse: ") + e.what());
  }
  if (!parsed)
    fail_input(path, "cannot parse: not a valid " + extension + " file (malformed or truncated)");
  return triangle_mesh_from_soup(path, points, polygons, report);
}

Mesh triangle_mesh_from_soup(const std::string& path, std::vector<Point>& points,
                             std::vector<Polygon>& polygons, Read_report* report,
                             Corner_tables* corners, std::size_t threads) {
  check_soup(path, points, polygons);
  if (!has_corner_attributes(corners)) corners = nullptr;
  Mesh mesh;
  std::size_t unused_points = 0;
  std::vector<std::string> repairs;
  triangulate_polygons(points, polygons, corners, repairs);
  std::vector<Mesh::Vertex_index> vertex_of_point;
  if (build_mesh_from_clean_triangles(points, polygons, mesh, unused_points,
                                      corners ? &vertex_of_point : nullptr, threads)) {
    if (unused_points > 0) repairs.push_back(unused_vertices_removed(unused_points));
    if (corners)
      set_corner_attributes(mesh, polygons, *corners, [&](std::size_t p, Mesh::Vertex_index v) {
        return vertex_of_point[p] == v;
      });
  } else {
    mesh = repaired_triangle_mesh(path, points, polygons, corners, repairs);
  }
  if (report) report->repairs = repairs;
  return mesh;
}

std::vector<Mesh> read_lod_chain(const std::string& path, const Read_options& options,
                                 Read_report* report) {
  Read_options one_thread = options;
  one_thread.threads = 1;
  std::vector<Mesh> levels;
  if (!is_gltf_file(path)) {
    levels.push_back(read_triangle_mesh(path, one_thread, report));
    return levels;
  }
  check_readable_file(path);
  std::vector<Gltf_soup> soups =
      read_gltf_levels(path, lower_extension(path) == ".glb", options.asset_root);
  for (std::size_t k = 0; k < soups.size(); ++k) {
    const std::string level = "level " + std::to_string(k);
    Read_report level_report;
    levels.push_back(mesh_of_soup(path, k == 0 ? path : path + " (" + level + ")", soups[k].soup,
                                  soups[k].looks, report ? &level_report : nullptr, one_thread,
                                  soups[k].left_out));
    if (!report) continue;
    if (k == 0) {
      *report = std::move(level_report);     // its materials are every level's
      report->left_out = soups[k].left_out;  // as are its lines: the file's
      continue;
    }
    for (const std::string& repair : level_report.repairs)
      report->repairs.push_back(level + ": " + repair);
  }
  return levels;
}

std::vector<std::string> write_mesh_atomically(const Mesh& mesh, const std::string& path,
                                               const Material_references& materials,
                                               Gltf_encoding encoding) {
  const std::vector<Lod_level> level = {{&mesh, 0}};
  if (is_gltf(lower_extension(path)))
    return write_gltf_atomically(level, path, materials, encoding);
  return write_files_atomically(level, path, {path}, materials);
}

bool is_gltf_file(const std::string& path) { return is_gltf(lower_extension(path)); }

std::optional<Gltf_encoding> gltf_encoding_named(const std::string& name) {
  if (name == "float") return Gltf_encoding::float32;
  if (name == "quantized") return Gltf_encoding::quantized;
  if (name == "meshopt") return Gltf_encoding::meshopt;
  return std::nullopt;
}

bool holds_lod_chain(const std::string& path) { return is_gltf_file(path); }

std::vector<std::string> lod_level_paths(const std::string& path, std::size_t levels) {
  if (holds_lod_chain(path)) return {path};
  const fs::path file(path);
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < levels; ++k)
    paths.push_back((file.parent_path() / (file.stem().string() + "_lod" + std::to_string(k) +
                                           file.extension().string()))
                        .string());
  return paths;
}

std::vector<std::string> write_lod_chain_atomically(const std::vector<Lod_level>& levels,
                                                    const std::string& path,
                                                    const Material_references& materials,
                                                    Gltf_encoding encoding) {
  if (holds_lod_chain(path)) return write_gltf_atomically(levels, path, materials, encoding);
  return write_files_atomically(levels, path, lod_level_paths(path, levels.size()), materials);
}

}  // namespace io
}  // namespace cgal_policies
