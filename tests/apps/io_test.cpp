// The io layer (apps/io/, the package's cgal_policies::io): the readers of OBJ, OFF, PLY, STL and
// glTF on hand-written files, the soup repairs, polygons and their crossings, corner attributes
// read and written back exactly, and the glTF reader and writer.
#include "gltf_builder.h"
#include "test_meshes.h"

#include <cgal_policies/small_components.h>
#include "app_types.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/atomic_write.h"
#include "io/clean_triangle_soup.h"
#include "io/gltf_io.h"
#include "io/material_texture.h"
#include "io/mesh_io.h"
#include "io/obj_writer.h"
#include "io/polygon_crossing.h"
#include "io/polygon_triangulation.h"
#include "io/soup_readers.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>

#include <cgal_policies/Corner_attributes.h>

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>
#include <vector>

// The OFF and PLY readers (apps/io/soup_readers.h), on hand-written files.
namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

namespace readers {

using apps::Polygon_soup;
using Polygons = std::vector<std::vector<std::size_t>>;

std::vector<std::array<double, 3>> coordinates(const Polygon_soup& soup) {
  std::vector<std::array<double, 3>> result;
  for (const apps::Point& p : soup.points) result.push_back({p.x(), p.y(), p.z()});
  return result;
}

const std::vector<std::array<double, 3>> kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

void expect_square(const Polygon_soup& soup, const Polygons& polygons) {
  EXPECT_EQ(coordinates(soup), kSquare);
  EXPECT_EQ(soup.polygons, polygons);
}

// The cause of the bad-input error that parsing `bytes` gives; "" when it parses.
template <typename Parse>
std::string refusal(Parse parse, const std::string& bytes) {
  try {
    parse("f", bytes);
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("f: ", 0), 0u) << message;
    return message;
  }
  return "";
}

TEST(Readers, ObjCornersWithTexturesNormalsAndNegativeIndices) {
  const Polygon_soup soup =
      apps::parse_obj("f",
                      "# a square\nmtllib a.mtl\nv 0 0 0\nv 1 0 0 1.0\nv +1 1 0e0 0.5 0.5 0.5\r\n"
                      "vt 0 0\nvn 0 0 1\ng square\nusemtl red\nf 1/1/1 2/1/1 3//1\n"
                      "v 0 1 0 # last\nl 1 2\nf -4 -2 -1\n");
  expect_square(soup, {{0, 1, 2}, {0, 2, 3}});
}

TEST(Readers, OffSkipsCommentsColoursAndNormals) {
  const Polygon_soup soup =
      apps::parse_off("f",
                      "# a square\nCOFF 4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255 # red\n\n"
                      "+1 1 0e0 0 0 255 255\n0 1 0 1 1 1 1\n3 0 1 2 0.5 0.5 0.5\n3 0 2 3\n");
  expect_square(soup, {{0, 1, 2}, {0, 2, 3}});
}

TEST(Readers, PlyAsciiSkipsOtherPropertiesAndElements) {
  const Polygon_soup soup = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\nproperty double x\n"
      "property float nx\nproperty float y\nproperty float z\nelement face 1\n"
      "property uchar flags\nproperty list uchar int vertex_indices\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nend_header\n"
      "0 9 0 0\n1 9 0 0\n1 9 1 0\n0 9 1 0\n7 4 0 1 2 3\n0 2\n");
  expect_square(soup, {{0, 1, 2, 3}});
}

// The same square in both byte orders, with a uint16 list count and uint32 indices.
std::string binary_square(bool big_endian) {
  std::string bytes = std::string("ply\nformat binary_") + (big_endian ? "big" : "little") +
                      "_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 2\n"
                      "property list ushort uint vertex_indices\nend_header\n";
  const auto append = [&](const void* value, std::size_t size) {
    std::string raw(static_cast<const char*>(value), size);
    if (big_endian) std::reverse(raw.begin(), raw.end());
    bytes += raw;
  };
  for (const auto& p : kSquare)
    for (double c : p) {
      const float f = float(c);
      append(&f, 4);
    }
  for (const std::array<std::uint32_t, 3>& face :
       {std::array<std::uint32_t, 3>{0, 1, 2}, std::array<std::uint32_t, 3>{0, 2, 3}}) {
    const std::uint16_t count = 3;
    append(&count, 2);
    for (std::uint32_t index : face) append(&index, 4);
  }
  return bytes;
}

TEST(Readers, PlyBinaryInBothByteOrders) {
  for (bool big_endian : {false, true}) {
    expect_square(apps::parse_ply("f", binary_square(big_endian)), {{0, 1, 2}, {0, 2, 3}});
  }
}

// Stanford's scans store faces as strips: every other triangle is turned back, -1 restarts, and
// the degenerate triangles that turn a strip are left out.
TEST(Readers, PlyTristripsBecomeTrianglesFacingOneWay) {
  const Polygon_soup soup = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 5 0\n6 5 0\n5 6 0\n"
      "10 0 1 2 3 3 -1 4 5 6 6\n");
  EXPECT_EQ(soup.polygons, (Polygons{{0, 1, 2}, {2, 1, 3}, {4, 5, 6}}));
}

// A PLY file of triangles also comes as one flat list, without a vector a face; a polygon of
// another size, or vertex values that are wanted, leave it to parse_ply.
TEST(Readers, PlyTrianglesComeAsOneFlatList) {
  for (bool big_endian : {false, true}) {
    const std::optional<apps::Ply_triangles> square =
        apps::parse_ply_triangles("f", binary_square(big_endian), true);
    ASSERT_TRUE(square);
    EXPECT_EQ(coordinates(Polygon_soup{square->points, {}, {}}), kSquare);
    EXPECT_EQ(square->corners, (std::vector<std::size_t>{0, 1, 2, 0, 2, 3}));
  }
  const std::optional<apps::Ply_triangles> strips = apps::parse_ply_triangles(
      "f",
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 5 0\n6 5 0\n5 6 0\n"
      "10 0 1 2 3 3 -1 4 5 6 6\n",
      false);
  ASSERT_TRUE(strips);
  EXPECT_EQ(strips->corners, (std::vector<std::size_t>{0, 1, 2, 2, 1, 3, 4, 5, 6}));

  const std::string quad =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  EXPECT_FALSE(apps::parse_ply_triangles("f", quad, false));
  const std::string coloured =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n";
  EXPECT_FALSE(apps::parse_ply_triangles("f", coloured, true));
  const std::optional<apps::Ply_triangles> uncoloured =
      apps::parse_ply_triangles("f", coloured, false);
  ASSERT_TRUE(uncoloured);
  EXPECT_EQ(uncoloured->corners, (std::vector<std::size_t>{0, 1, 2}));
  const auto flat = [](const std::string& source, const std::string& bytes) {
    return apps::parse_ply_triangles(source, bytes, false);
  };
  EXPECT_EQ(
      refusal(flat, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n"),
      "f: the vertex element has no x, y and z");
}

TEST(Readers, MalformedFilesAreOneBadInputLine) {
  const auto off = [](const std::string& source, const std::string& bytes) {
    return apps::parse_off(source, bytes);
  };
  const auto ply = [](const std::string& source, const std::string& bytes) {
    return apps::parse_ply(source, bytes);
  };
  const auto obj = [](const std::string& source, const std::string& bytes) {
    return apps::parse_obj(source, bytes);
  };
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv inf 1\nf 1 2 3\n"), "");  // two coordinates
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 1,5 1 0\nf 1 2 3\n"), "");
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "");   // indices start at 1
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), "");  // back too far
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n"), "");
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nf 1 2\n"), "");  // two corners
  EXPECT_EQ(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
  EXPECT_NE(refusal(off, "OFF\n4 1 0\n0 0 0\n"), "");                          // truncated
  EXPECT_NE(refusal(off, "OFF\n900000 1 0\n0 0 0\n"), "");                     // forged count
  EXPECT_NE(refusal(off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n"), "");  // negative index
  EXPECT_NE(refusal(off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1.2 0 1\n"), "");  // bad corner count
  EXPECT_NE(refusal(off, "4OFF\n"), "");
  std::string cut = binary_square(false);
  cut.resize(cut.size() - 3);
  EXPECT_NE(refusal(ply, cut), "");
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nelement vertex 1\n"), "");  // no end_header
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nelemply\nend_header\n"), "");
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nproperty float x\nend_header\n"), "");
  EXPECT_NE(refusal(ply,
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"),
            "");  // a negative index outside a strip
  EXPECT_NE(refusal(ply,
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "end_header\n0 0 0\n200 0 0 0\n"),
            "");  // a list longer than the file
}

}  // namespace readers

// The reader's fast path (apps/io/clean_triangle_soup.h): it takes exactly the soups CGAL's
// check calls polygon meshes (when all are triangles), and builds the mesh CGAL's path builds.
namespace clean_soups {

using Polygons = std::vector<std::vector<std::size_t>>;
using apps::Mesh;
using apps::Point;

const std::vector<Point> kPoints = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                    {1, 1, 1}, {2, 0, 0}, {0, 2, 0}, {5, 5, 5}};

bool builds(const Polygons& polygons, Mesh& mesh, std::size_t& unused) {
  const bool built = apps::build_mesh_from_clean_triangles(kPoints, polygons, mesh, unused);
  if (!built) {
    EXPECT_TRUE(mesh.is_empty());
  }
  return built;
}

bool builds(const Polygons& polygons) {
  Mesh mesh;
  std::size_t unused = 0;
  return builds(polygons, mesh, unused);
}

Mesh built_by_cgal(const std::vector<Point>& points, const Polygons& polygons) {
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  return mesh;
}

TEST(CleanSoups, AClosedAndAnOpenMeshAreBuiltAsCgalBuildsThem) {
  const Polygons tetrahedron = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const Polygons fan_with_unused_points = {{0, 1, 2}, {0, 2, 6}, {5, 1, 0}};  // 3, 4, 7 unused
  for (const Polygons& polygons : {tetrahedron, fan_with_unused_points}) {
    Mesh mesh;
    std::size_t unused = 0;
    ASSERT_TRUE(builds(polygons, mesh, unused));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_TRUE(mesh.is_valid(false));
    test_meshes::expect_same_connectivity(mesh, built_by_cgal(kPoints, polygons));
    for (auto v : mesh.vertices())
      EXPECT_EQ(CGAL::is_border(v, mesh).has_value(), mesh.is_border(mesh.halfedge(v)));
  }
  Mesh fan;
  std::size_t unused = 0;
  ASSERT_TRUE(builds(fan_with_unused_points, fan, unused));
  EXPECT_EQ(unused, 3u);
  EXPECT_EQ(fan.number_of_vertices(), 5u);
  EXPECT_EQ(test_meshes::border_edge_count(fan), 5u);
}

TEST(CleanSoups, SoupsThatNeedRepairAreLeftToCgal) {
  EXPECT_FALSE(builds({}));                                 // nothing to build
  EXPECT_FALSE(builds({{0, 1, 2, 3}}));                     // not a triangle
  EXPECT_FALSE(builds({{0, 1, 1}}));                        // a corner twice
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 1, 2}}));             // a face twice
  EXPECT_FALSE(builds({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));  // an edge of three faces
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 1, 3}}));             // faces facing apart
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 5, 6}}));             // a bowtie
  EXPECT_FALSE(builds({{0, 2, 1},
                       {0, 1, 3},
                       {1, 2, 3},
                       {0, 3, 2},  // two tetrahedra that
                       {0, 5, 6},
                       {0, 7, 5},
                       {5, 7, 6},
                       {0, 6, 7}}));  // share a point
}

// Every shipped mesh the fast path takes is built as CGAL builds it; the others are left whole.
TEST(CleanSoups, ShippedMeshesAreBuiltAsCgalBuildsThem) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  std::size_t taken = 0;
  for (const std::string name :
       {"alligator.obj", "bob_tri.obj", "bunny.obj", "cow.obj", "dragon.ply", "dragon_res2.ply",
        "fandisk.obj", "nefertiti.obj", "rocker-arm.obj", "spot.obj", "teapot.obj", "woody.obj"}) {
    SCOPED_TRACE(name);
    std::vector<Point> points;
    Polygons polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(test_meshes::data_file(name), points, polygons));
    const bool all_triangles =
        std::all_of(polygons.begin(), polygons.end(), [](const auto& p) { return p.size() == 3; });
    const bool cgal_takes =
        all_triangles && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
    Mesh mesh;
    std::size_t unused = 0;
    ASSERT_EQ(apps::build_mesh_from_clean_triangles(points, polygons, mesh, unused), cgal_takes);
    if (!cgal_takes) continue;
    ++taken;
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    test_meshes::expect_same_connectivity(mesh, built_by_cgal(points, polygons));
  }
  EXPECT_GE(taken, 6u);
}

// Expects read_triangle_mesh to build from the PLY file at `path` the mesh that the polygon path
// builds from parse_ply's soup, halfedge for halfedge, with the same repairs; returns its report.
apps::Read_report expect_read_as_the_polygon_path_reads(const std::string& path) {
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh(path, &report);
  apps::Polygon_soup soup = apps::parse_ply(path, read_text(path));
  apps::Read_report general_report;
  const Mesh general =
      apps::triangle_mesh_from_soup(path, soup.points, soup.polygons, &general_report);
  test_meshes::expect_same_connectivity(mesh, general);
  EXPECT_EQ(report.repairs, general_report.repairs);
  return report;
}

// A PLY file of triangles is read without a polygon a face (parse_ply_triangles): into the mesh
// that the general path builds from parse_ply's soup, halfedge for halfedge, with the same repairs.
TEST(CleanSoups, PlyTrianglesAreReadAsThePolygonPathBuildsThem) {
  const fs::path folder = fs::temp_directory_path() / ("ply_flat_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string spare_point = (folder / "spare_point.ply").string();
  std::ofstream(spare_point)
      << "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n1 1 0\n9 9 9\n0 1 0\n3 0 1 2\n3 0 2 4\n";
  std::vector<std::string> paths = {spare_point};
  if (!test_meshes::real_meshes_skipped())
    paths.push_back(test_meshes::data_file("dragon_res2.ply"));
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    expect_read_as_the_polygon_path_reads(path);
  }
  apps::Read_report report;
  EXPECT_EQ(apps::read_triangle_mesh(spare_point, &report).number_of_vertices(), 4u);
  EXPECT_EQ(report.repairs, std::vector<std::string>{"removed 1 unused vertices"});
  fs::remove_all(folder);
}

// A PLY file of triangles that needs repair, or that is bad input, fares as through the
// polygon path: the same repaired mesh and repairs, the same one error line.
TEST(CleanSoups, PlyTrianglesThePolygonPathRepairsOrRefusesFareTheSame) {
  const fs::path folder = fs::temp_directory_path() / ("ply_repair_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const auto ply = [&](const std::string& name, const std::string& points, const std::string& faces,
                       std::size_t face_count) {
    std::istringstream rows(points);
    std::size_t point_count = 0;
    for (std::string row; std::getline(rows, row);) ++point_count;
    const std::string path = (folder / name).string();
    std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex " << point_count
                        << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
                        << face_count << "\nproperty list uchar int vertex_indices\nend_header\n"
                        << points << faces;
    return path;
  };
  // Two triangles that touch at a point, one of them twice, and one with a repeated corner.
  const std::string repaired = ply("repaired.ply", "0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n",
                                   "3 0 1 2\n3 0 3 4\n3 0 3 4\n3 1 1 2\n", 4);
  EXPECT_FALSE(expect_read_as_the_polygon_path_reads(repaired).repairs.empty());

  const auto refusal = [](const std::string& path) -> std::string {
    try {
      apps::read_triangle_mesh(path);
    } catch (const apps::Io_error& e) {
      EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
      return e.what();
    }
    return "";
  };
  const std::string far = ply("far.ply", "0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n3 0 2 7\n", 2);
  EXPECT_EQ(refusal(far), far + ": face 1 refers to vertex 7 but there are only 3");
  const std::string not_finite = ply("not_finite.ply", "0 0 0\n1 0 0\nnan 1 0\n", "3 0 1 2\n", 1);
  EXPECT_EQ(refusal(not_finite), not_finite + ": non-finite coordinate at vertex 2");
  const std::string faceless = ply("faceless.ply", "0 0 0\n1 0 0\n0 1 0\n", "", 0);
  EXPECT_EQ(refusal(faceless), faceless + ": no faces");
  fs::remove_all(folder);
}

}  // namespace clean_soups

// ---------------------------------------------------------------------------------------------
// Polygons that cross themselves are kept from CGAL's triangulation, and triangulated all the same.
namespace polygon_crossing {

using apps::Point;

std::vector<Point> in_plane(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Point> corners;
  for (const auto& p : xy) corners.emplace_back(p[0], p[1], 0.0);
  return corners;
}

bool crosses(const std::vector<std::array<double, 2>>& xy) {
  return apps::polygon_crosses_itself(in_plane(xy), apps::Kernel::Vector_3(0, 0, 1));
}

TEST(PolygonCrossing, SimplePolygonsPass) {
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {3, 1}, {1, 2}, {-1, 1}}));         // convex pentagon
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}));  // an L
  EXPECT_FALSE(crosses({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));          // a corner mid-edge
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}}));          // a notch to the centre
}

TEST(PolygonCrossing, CrossingsTouchesAndFoldsAreFound) {
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {0, 2}, {2, 2}}));                    // a bowtie
  EXPECT_TRUE(crosses({{0, 2}, {2, -1}, {-1, 1}, {1, 1}, {-2, -1}}));        // a pentagram
  EXPECT_TRUE(crosses({{0, 0}, {4, 0}, {4, 2}, {2, 0}, {0, 2}}));            // a corner on an edge
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));                    // folds back
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {2, 2}, {0, 0}, {-2, 2}, {-2, 0}}));  // a corner twice
}

TEST(PolygonCrossing, IsJudgedAlongTheNormal) {
  // A pentagon whose corners alternate between two heights: simple seen from above, its edges
  // cross seen from the side.
  std::vector<Point> corners = in_plane({{0, 0}, {2, 0}, {3, 1}, {1, 2}, {-1, 1}});
  for (std::size_t i = 0; i < corners.size(); ++i)
    corners[i] = Point(corners[i].x(), corners[i].y(), 0.1 * double(i % 2));
  EXPECT_FALSE(apps::polygon_crosses_itself(corners, apps::Kernel::Vector_3(0, 0, 1)));
  EXPECT_TRUE(apps::polygon_crosses_itself(corners, apps::Kernel::Vector_3(0, 1, 0)));
}

// The cause the reader gives for the soup, "" when it reads it.
std::string refusal(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Point> points = in_plane(xy);
  std::vector<std::vector<std::size_t>> polygons(1);
  for (std::size_t i = 0; i < points.size(); ++i) polygons[0].push_back(i);
  try {
    const apps::Mesh mesh = apps::triangle_mesh_from_soup("soup", points, polygons);
    EXPECT_EQ(mesh.number_of_faces(), points.size() - 2);
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
    return e.what();
  }
  return "";
}

// A polygon that crosses itself, or has no area, is triangulated all the same, by its boundary in
// 3D (a pentagram, whose triangulate_face could loop), or as a fan (five points on a line).
TEST(PolygonCrossing, TheReaderTriangulatesEveryPolygonWhateverItsShape) {
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), "");
  EXPECT_EQ(refusal({{0, 2}, {2, -1}, {-1, 1}, {1, 1}, {-2, -1}}), "");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}), "");
}

// A soup whose only polygon has two corners has no triangle to build: a bad input, not a mesh
// without faces (found by fuzz_repair).
TEST(PolygonCrossing, ASoupOfNoTriangleIsRefused) {
  EXPECT_EQ(refusal({{0, 0}, {1, 0}}), "soup: no faces left after dropping degenerate ones");
}

// A star of 601 corners, each joined to the one 300 steps round, which crosses itself everywhere:
// beyond 500 corners the boundary triangulation (cubic time) gives way to a fan.
TEST(PolygonCrossing, ALargePolygonThatCrossesItselfBecomesAFan) {
  std::vector<Point> star;
  for (std::size_t i = 0; i < 601; ++i) {
    const double angle = 2 * M_PI * double(i * 300 % 601) / 601;
    star.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  std::vector<std::array<std::size_t, 3>> fan;
  for (std::size_t i = 1; i + 1 < star.size(); ++i) fan.push_back({0, i, i + 1});
  EXPECT_EQ(apps::polygon_triangles(star), fan);
}

// The quad's split: the diagonal whose triangles do not fold onto each other, else the one whose
// smallest angle is larger.
TEST(PolygonCrossing, AQuadIsSplitAlongItsBetterDiagonal) {
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  // Folded over its diagonal 1-3: the triangles 1 2 3 and 1 3 0 would face away from each other.
  const std::vector<Point> folded = {{0, 0, 0}, {1, 0, 0}, {0.25, 0.25, 0.5}, {0, 1, 0}};
  EXPECT_EQ(apps::polygon_triangles(folded), (Triangles{{0, 1, 2}, {0, 2, 3}}));
  // A ribbon's section twisted by more than a right angle, which crosses itself seen along its
  // normal: either split folds it, and the diagonal 0-2 keeps its smallest angle at 35.3 degrees
  // where 1-3 would make one of 17.7.
  const std::vector<Point> twisted = {{0, -1, 0}, {1, 0, -0.5}, {1, -1, -1}, {0, 1, 0}};
  EXPECT_EQ(apps::polygon_triangles(twisted), (Triangles{{0, 1, 2}, {0, 2, 3}}));
  // Flat and convex: the short diagonal, which leaves the sharp corners 0 and 2 whole.
  const std::vector<Point> kite = {{0, 0, 0}, {10, -1, 0}, {20, 0, 0}, {10, 1, 0}};
  EXPECT_EQ(apps::polygon_triangles(kite), (Triangles{{1, 2, 3}, {1, 3, 0}}));
  // A flat concave dart: only the diagonal through its inner corner 3 keeps both triangles up.
  const std::vector<Point> dart = {{2, 4, 0}, {0, 0, 0}, {4, 0, 0}, {2, 1, 0}};
  EXPECT_EQ(apps::polygon_triangles(dart), (Triangles{{1, 2, 3}, {1, 3, 0}}));
  EXPECT_EQ(apps::polygon_triangles(in_plane({{0, 0}, {2, 0}, {2, 2}, {0, 2}})),
            (Triangles{{0, 1, 2}, {0, 2, 3}}));  // a square: a tie, the diagonal from corner 0
}

}  // namespace polygon_crossing

// ---------------------------------------------------------------------------------------------
// Texture coordinates, normals and materials of OBJ corners: read onto the mesh, written back.
namespace corner_attributes {

using gltf_fixtures::Gltf_builder;
using gltf_fixtures::kFloat;
constexpr int kUnsignedByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kUnsignedShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
using gltf_fixtures::triangles;
using gltf_fixtures::two_primitive_square;

using apps::Corner_tables;
using apps::Mesh;
using Attributes = cgal_policies::Corner_attributes<apps::Point>;
constexpr std::size_t kNone = Corner_tables::kNoEntry;

TEST(CornerAttributes, ObjTablesAndTheEntriesOfEachCorner) {
  const apps::Polygon_soup soup = apps::parse_obj(
      "f",
      "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nvt 0 0\nvt 1 0\n"
      "vt 1 1 0\nvn 0 0 1\nusemtl red\nf 1/1 3/-1/1 4//-1\nusemtl blue\nf 1/1/1 2/2 3\n"
      "usemtl red\nf 4 1 3\n");
  const Corner_tables& t = soup.corners;
  EXPECT_EQ(t.uvs, (std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {1, 1}}));
  ASSERT_EQ(t.normals.size(), 1u);
  EXPECT_EQ(t.normals[0], apps::Kernel::Vector_3(0, 0, 1));
  EXPECT_EQ(t.polygon_uvs,
            (std::vector<std::vector<std::size_t>>{
                {kNone, kNone, kNone}, {0, 2, kNone}, {0, 1, kNone}, {kNone, kNone, kNone}}));
  EXPECT_EQ(t.polygon_normals,
            (std::vector<std::vector<std::size_t>>{
                {kNone, kNone, kNone}, {kNone, 0, 0}, {0, kNone, kNone}, {kNone, kNone, kNone}}));
  EXPECT_EQ(t.material_libraries, (std::vector<std::string>{"a.mtl", "b.mtl"}));
  EXPECT_EQ(t.material_names, (std::vector<std::string>{"red", "blue"}));
  EXPECT_EQ(t.polygon_materials, (std::vector<std::uint32_t>{Corner_tables::kNoMaterial, 0, 1, 0}));
}

TEST(CornerAttributes, AFileWithoutThemHasEmptyLists) {
  const apps::Polygon_soup soup =
      apps::parse_obj("f", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n");
  EXPECT_TRUE(soup.corners.polygon_uvs.empty());
  EXPECT_TRUE(soup.corners.polygon_normals.empty());
  EXPECT_TRUE(soup.corners.polygon_materials.empty());
}

// A PLY file's per-vertex normals and texture coordinates become the values of every corner of
// their vertex, on the mesh and in an OBJ file written from it; one that is not finite is bad
// input.
TEST(CornerAttributes, PlyVertexNormalsAndTextureCoordinatesGoToEveryCorner) {
  const auto square = [](const std::string& third_u) {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
           "property float texture_u\nproperty float texture_v\nelement face 2\n"
           "property list uchar int vertex_indices\nend_header\n"
           "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 0.5 0\n1 1 0 0 0 1 " +
           third_u + " 0.5\n0 1 0 0 0 1 0 0.5\n3 0 1 2\n3 0 2 3\n";
  };
  const apps::Polygon_soup soup = apps::parse_ply("f", square("0.5"));
  EXPECT_EQ(soup.corners.uvs,
            (std::vector<std::array<double, 2>>{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}));
  EXPECT_EQ(soup.corners.normals, std::vector<apps::Kernel::Vector_3>(4, {0, 0, 1}));
  EXPECT_EQ(soup.corners.polygon_uvs, soup.polygons);
  EXPECT_EQ(soup.corners.polygon_normals, soup.polygons);

  const fs::path folder = fs::temp_directory_path() / ("ply_corners_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "square.ply") << square("0.5");
  const Mesh mesh = apps::read_triangle_mesh((folder / "square.ply").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  apps::write_mesh_atomically(mesh, (folder / "square.obj").string());
  const Mesh reread = apps::read_triangle_mesh((folder / "square.obj").string(), nullptr,
                                               apps::Corner_attribute_reading::keep);
  for (const Mesh* m : {&mesh, &reread}) {
    const Attributes attributes(*m);
    ASSERT_TRUE(attributes.uvs && attributes.normals);
    for (const auto h : m->halfedges()) {
      if (m->is_border(h)) continue;
      const apps::Point& p = m->point(m->target(h));
      EXPECT_EQ((*attributes.uvs)[h], (std::array<double, 2>{p.x() / 2, p.y() / 2}));
      EXPECT_EQ((*attributes.normals)[h], apps::Kernel::Vector_3(0, 0, 1));
    }
  }
  fs::remove_all(folder);

  try {
    apps::parse_ply("f", square("nan"));
    ADD_FAILURE() << "a texture coordinate of nan was read";
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
    EXPECT_EQ(std::string(e.what()), "f: vertex 2: its texture coordinate is not finite");
  }
}

// Colours of PLY vertices (integer channels scaled by their type's largest value, float ones kept,
// alpha 1 when absent) and of OBJ points (r g b [a]) become the values of every corner of their
// vertex; one that is not finite is bad input.
TEST(CornerAttributes, PlyAndObjVertexColoursGoToEveryCorner) {
  const std::string triangle_faces = "element face 1\nproperty list uchar int vertex_indices\n";
  const apps::Polygon_soup bytes = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" +
          triangle_faces + "end_header\n0 0 0 255 0 51\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_EQ(bytes.corners.colors,
            (std::vector<std::array<double, 4>>{{1, 0, 0.2, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}}));
  EXPECT_EQ(bytes.corners.polygon_colors, bytes.polygons);
  const auto float_ply = [&](const std::string& first_red) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nproperty float diffuse_red\nproperty float diffuse_green\n"
           "property float diffuse_blue\nproperty float diffuse_alpha\n" +
           triangle_faces + "end_header\n0 0 0 " + first_red +
           " 0 0 0.5\n1 0 0 0 0.25 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n";
  };
  EXPECT_EQ(apps::parse_ply("f", float_ply("0.75")).corners.colors,
            (std::vector<std::array<double, 4>>{{0.75, 0, 0, 0.5}, {0, 0.25, 0, 1}, {0, 0, 1, 1}}));
  const apps::Polygon_soup obj = apps::parse_obj(
      "f", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0 0.5\nv 0 1 0\nv 1 1 0 1\nf 1 2 3\nf 2 4 3\n");
  ASSERT_EQ(obj.corners.colors.size(), 4u);
  EXPECT_EQ(obj.corners.colors[0], (std::array<double, 4>{1, 0, 0, 1}));
  EXPECT_EQ(obj.corners.colors[1], (std::array<double, 4>{0, 1, 0, 0.5}));
  for (const std::size_t without : {2, 3})  // no colour, and a w
    for (const double channel : obj.corners.colors[without]) EXPECT_TRUE(std::isnan(channel));
  EXPECT_EQ(obj.corners.polygon_colors, obj.polygons);

  const auto cause = [](auto&& parse) {
    try {
      parse();
    } catch (const apps::Io_error& e) {
      EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(cause([&] { apps::parse_ply("f", float_ply("nan")); }),
            "f: vertex 0: its colour is not finite");
  EXPECT_EQ(cause([] { apps::parse_obj("f", "v 0 0 0 1 red 0\n"); }),
            "f: line 1: a vertex's colour needs three or four finite numbers");
}

TEST(CornerAttributes, BadEntriesAreOneBadInputLine) {
  const auto cause = [](const std::string& bytes) {
    try {
      apps::parse_obj("f", bytes);
    } catch (const apps::Io_error& e) {
      EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(cause(triangle + "vt 0 0\nf 1/2 2/1 3/1\n"),
            "f: line 5: '1/2' names a texture coordinate (vt) that is not read before it");
  EXPECT_EQ(cause(triangle + "f 1//1 2 3\nvn 0 0 1\n"),
            "f: line 4: '1//1' names a normal (vn) that is not read before it");
  EXPECT_EQ(cause(triangle + "vt nan 0\n"),
            "f: line 4: a texture coordinate needs one or two finite numbers, u [v]");
  EXPECT_EQ(cause(triangle + "vn 0 1\n"), "f: line 4: a normal needs three finite numbers, x y z");
  EXPECT_EQ(cause(triangle + "f 1/ 2 3\n"),
            "f: line 4: '1/' has a slash but names no texture coordinate or normal");
  EXPECT_EQ(cause(triangle + "usemtl\n"), "f: line 4: usemtl needs a material name");
}

// Each face's corners as (point, uv, normal), starting at the lowest point, and its material.
struct Face_corners {
  std::vector<std::array<double, 12>> corners;
  std::uint32_t material;
  bool operator==(const Face_corners& o) const {
    // NaN marks a corner without a value: compare bit patterns, not numbers.
    return material == o.material && corners.size() == o.corners.size() &&
           std::memcmp(corners.data(), o.corners.data(), corners.size() * sizeof corners[0]) == 0;
  }
};

std::vector<Face_corners> face_corners(const Mesh& mesh) {
  const Attributes a(mesh);
  std::vector<Face_corners> faces;
  for (const auto f : mesh.faces()) {
    Face_corners face{{}, a.materials ? (*a.materials)[f] : Attributes::kNoMaterial};
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      const Attributes::Uv uv = a.uvs ? (*a.uvs)[h] : Attributes::Uv{-1, -1};
      const apps::Kernel::Vector_3 n =
          a.normals ? (*a.normals)[h] : apps::Kernel::Vector_3(-1, -1, -1);
      const Attributes::Color c = a.colors ? (*a.colors)[h] : Attributes::Color{-1, -1, -1, -1};
      face.corners.push_back(
          {p.x(), p.y(), p.z(), uv[0], uv[1], n.x(), n.y(), n.z(), c[0], c[1], c[2], c[3]});
    }
    std::rotate(face.corners.begin(), std::min_element(face.corners.begin(), face.corners.end()),
                face.corners.end());
    faces.push_back(face);
  }
  return faces;
}

fs::path scratch_folder(const std::string& name) {
  const fs::path folder =
      fs::path(testing::TempDir()) / ("corner_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder / "out");
  return folder;
}

TEST(CornerAttributes, APolygonsTrianglesKeepItsCornersAndMaterial) {
  const fs::path folder = scratch_folder("polygon");
  // A pentagon with a corner of each texture coordinate, beside a triangle of no material.
  std::ofstream(folder / "looks.mtl") << "newmtl wood\nKd 0.5 0.25 0\n";
  std::ofstream(folder / "in.obj")
      << "mtllib looks.mtl\nv 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 1 -1 0\n"
         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 1\nvt 0 1\nvn 0 0 1\nf 1 6 2\nusemtl wood\n"
         "f 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  ASSERT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(report.materials.names, std::vector<std::string>{"wood"});
  EXPECT_EQ(report.materials.libraries, std::vector<std::string>{(folder / "looks.mtl").string()});
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.normals && a.materials);
  std::size_t wood_corners = 0;
  for (const auto f : mesh.faces())
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      if ((*a.materials)[f] == Attributes::kNoMaterial) {
        EXPECT_TRUE(std::isnan((*a.uvs)[h][0]));
        continue;
      }
      ++wood_corners;
      EXPECT_EQ((*a.normals)[h], apps::Kernel::Vector_3(0, 0, 1));
      // The pentagon's texture coordinates go with its points.
      const std::map<std::pair<double, double>, Attributes::Uv> uv_of = {{{0, 0}, {0, 0}},
                                                                         {{2, 0}, {1, 0}},
                                                                         {{3, 1}, {1, 1}},
                                                                         {{1, 2}, {0.5, 1}},
                                                                         {{-1, 1}, {0, 1}}};
      EXPECT_EQ((*a.uvs)[h], uv_of.at({p.x(), p.y()}));
    }
  EXPECT_EQ(wood_corners, 9u);  // three triangles

  // Written into another folder and read back: the same corners, the material library copied
  // beside the file, which names nothing outside its folder.
  const fs::path out = folder / "out" / "again.obj";
  EXPECT_EQ(apps::write_mesh_atomically(mesh, out.string(), report.materials),
            std::vector<std::string>{});
  const std::string text = read_text(out);
  EXPECT_EQ(text.rfind("# written by cgal_policies\nmtllib again.mtl\n", 0), 0u) << text;
  EXPECT_EQ(read_text(folder / "out" / "again.mtl"), "newmtl wood\nKd 0.5 0.25 0\n");
  apps::Read_report again;
  EXPECT_EQ(face_corners(apps::read_triangle_mesh(out.string(), &again,
                                                  apps::Corner_attribute_reading::keep)),
            face_corners(mesh));
  EXPECT_EQ(again.materials.libraries,
            std::vector<std::string>{(folder / "out" / "again.mtl").string()});
  fs::remove_all(folder);
}

// The texture coordinate of each corner of `mesh`, by the corner's face (its three points, from
// the lowest) and point.
std::map<std::pair<std::array<double, 9>, std::array<double, 3>>, Attributes::Uv> uvs_by_corner(
    const Mesh& mesh) {
  const Attributes a(mesh);
  std::map<std::pair<std::array<double, 9>, std::array<double, 3>>, Attributes::Uv> uvs;
  for (const Face_corners& face : face_corners(mesh)) {
    std::array<double, 9> points{};
    for (std::size_t k = 0; k < 3; ++k)
      std::copy_n(face.corners[k].begin(), 3, points.begin() + std::ptrdiff_t(3 * k));
    for (const auto& c : face.corners) uvs[{points, {c[0], c[1], c[2]}}] = {c[3], c[4]};
  }
  return uvs;
}

// A twisted quad, which crosses itself seen along its normal, beside a pentagram: both are
// triangulated, and every triangle keeps its polygon's corners and material.
TEST(CornerAttributes, TwistedAndCrossingPolygonsKeepTheirCorners) {
  const fs::path folder = scratch_folder("twisted");
  std::ofstream(folder / "in.obj") << "v 0 -1 0\nv 1 0 -0.5\nv 1 -1 -1\nv 0 1 0\n"
                                      "v 10 2 0\nv 12 -1 0\nv 9 1 0\nv 11 1 0\nv 8 -1 0\n"
                                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nusemtl cloth\n"
                                      "f 1/1 2/2 3/3 4/4\nusemtl star\nf 5/1 6/2 7/3 8/4 9/5\n";
  {
    // The quad is one that the reader refused before it triangulated every polygon.
    const std::vector<apps::Point> corners = {{0, -1, 0}, {1, 0, -0.5}, {1, -1, -1}, {0, 1, 0}};
    Mesh quad;
    std::vector<Mesh::Vertex_index> v;
    for (const apps::Point& p : corners) v.push_back(quad.add_vertex(p));
    ASSERT_TRUE(apps::polygon_crosses_itself(
        corners, CGAL::Polygon_mesh_processing::compute_face_normal(quad.add_face(v), quad)));
  }
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  EXPECT_EQ(report.repairs, std::vector<std::string>{"triangulated 2 polygons"});
  ASSERT_EQ(mesh.number_of_faces(), 2u + 3u);
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.materials);
  // The quad along its diagonal 0-2 (PolygonCrossing.AQuadIsSplitAlongItsBetterDiagonal), each
  // corner with its coordinates.
  const std::array<double, 3> p0{0, -1, 0}, p1{1, 0, -0.5}, p2{1, -1, -1}, p3{0, 1, 0};
  const auto face = [](const std::array<double, 3>& u, const std::array<double, 3>& v,
                       const std::array<double, 3>& w) {
    return std::array<double, 9>{u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2]};
  };
  const auto uvs = uvs_by_corner(mesh);
  EXPECT_EQ(uvs.at({face(p0, p1, p2), p0}), (Attributes::Uv{0, 0}));
  EXPECT_EQ(uvs.at({face(p0, p1, p2), p1}), (Attributes::Uv{1, 0}));
  EXPECT_EQ(uvs.at({face(p0, p1, p2), p2}), (Attributes::Uv{1, 1}));
  EXPECT_EQ(uvs.at({face(p0, p2, p3), p0}), (Attributes::Uv{0, 0}));
  EXPECT_EQ(uvs.at({face(p0, p2, p3), p2}), (Attributes::Uv{1, 1}));
  EXPECT_EQ(uvs.at({face(p0, p2, p3), p3}), (Attributes::Uv{0, 1}));
  // The pentagram: its five corners keep their coordinates in each of the triangles they are in.
  const std::map<double, Attributes::Uv> star_uv = {
      {10, {0, 0}}, {12, {1, 0}}, {9, {1, 1}}, {11, {0, 1}}, {8, {0.5, 0.5}}};
  std::size_t star_corners = 0;
  for (const auto f : mesh.faces())
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const double x = mesh.point(mesh.target(h)).x();
      EXPECT_EQ((*a.materials)[f], x < 5 ? 0u : 1u);
      if (x < 5) continue;
      ++star_corners;
      EXPECT_EQ((*a.uvs)[h], star_uv.at(x));
    }
  EXPECT_EQ(star_corners, 9u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  fs::remove_all(folder);
}

// Every repair keeps every corner's values and every face's material: two triangles facing apart
// across their edge (one is turned), a point written twice, a degenerate and a duplicate face,
// and a third triangle that touches the others at one point only (that point is split).
TEST(CornerAttributes, ARepairKeepsEveryCornersValuesAndSaysWhatItDid) {
  const fs::path folder = scratch_folder("repair");
  std::ofstream(folder / "in.obj")
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 2 2 1\nv 1 2 1\n"
         "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 0.5 0.5\nvt 0.9 0.9\nvt 0.8 0.9\nvt 0.6 0.6\n"
         "vn 0 0 1\nusemtl a\nf 1/1/1 2/2/1 3/3/1\nusemtl b\nf 5/2/1 3/3/1 4/4/1\n"
         "f 1/1 1/1 2/2\nf 2/2 3/3 1/1\nusemtl c\nf 4/7 6/5 7/6\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  EXPECT_EQ(report.repairs,
            (std::vector<std::string>{"merged or dropped 1 duplicate or unused points",
                                      "dropped 2 degenerate or duplicate faces",
                                      "oriented the faces and split 1 non-manifold vertices"}));
  ASSERT_EQ(mesh.number_of_faces(), 3u);
  EXPECT_EQ(mesh.number_of_vertices(), 7u);  // point 4 twice: the third triangle touches there
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.normals && a.materials);
  // The first two faces give their common points the same coordinates.
  const std::map<std::array<double, 2>, Attributes::Uv> first_two = {
      {{0, 0}, {0, 0}}, {{1, 0}, {0.5, 0}}, {{0, 1}, {0, 0.5}}};
  for (const auto f : mesh.faces()) {
    const std::uint32_t material = (*a.materials)[f];
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      const Attributes::Uv uv = (*a.uvs)[h];
      if (material == 2) {  // the third triangle, as it was
        EXPECT_EQ(uv, (p == apps::Point(1, 1, 0)   ? Attributes::Uv{0.6, 0.6}
                       : p == apps::Point(2, 2, 1) ? Attributes::Uv{0.9, 0.9}
                                                   : Attributes::Uv{0.8, 0.9}));
        EXPECT_TRUE(std::isnan((*a.normals)[h].x()));
        continue;
      }
      EXPECT_EQ((*a.normals)[h], apps::Kernel::Vector_3(0, 0, 1));
      const Attributes::Uv expected = material == 1 && p == apps::Point(1, 1, 0)
                                          ? Attributes::Uv{0.5, 0.5}
                                          : first_two.at({p.x(), p.y()});
      EXPECT_EQ(uv, expected) << p;
    }
  }
  std::vector<std::uint32_t> materials;
  for (const auto f : mesh.faces()) materials.push_back((*a.materials)[f]);
  EXPECT_EQ(materials, (std::vector<std::uint32_t>{0, 1, 2}));
  // One of the first two faces was turned to face the other's way.
  const auto n0 = CGAL::Polygon_mesh_processing::compute_face_normal(Mesh::Face_index(0), mesh);
  const auto n1 = CGAL::Polygon_mesh_processing::compute_face_normal(Mesh::Face_index(1), mesh);
  EXPECT_GT(n0 * n1, 0);
  fs::remove_all(folder);
}

TEST(CornerAttributes, ShippedTexturedMeshesRoundTripExactly) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path folder = scratch_folder("shipped");
  for (const std::string name : {"spot.obj", "bob_tri.obj"}) {
    SCOPED_TRACE(name);
    apps::Read_report report;
    const Mesh mesh = apps::read_triangle_mesh(test_meshes::data_file(name), &report,
                                               apps::Corner_attribute_reading::keep);
    const Attributes a(mesh);
    ASSERT_TRUE(a.uvs.has_value());
    std::size_t corners_without_uv = 0;
    for (const auto h : mesh.halfedges())
      corners_without_uv += !mesh.is_border(h) && std::isnan((*a.uvs)[h][0]);
    EXPECT_EQ(corners_without_uv, 0u);
    const fs::path out = folder / "out" / name;
    apps::write_mesh_atomically(mesh, out.string(), report.materials);
    apps::Read_report again;
    EXPECT_EQ(face_corners(apps::read_triangle_mesh(out.string(), &again,
                                                    apps::Corner_attribute_reading::keep)),
              face_corners(mesh));
    EXPECT_EQ(again.materials.names, report.materials.names);
    // A library from another folder is copied beside the file, with its texture.
    if (report.materials.libraries.empty()) {
      EXPECT_TRUE(again.materials.libraries.empty());
    } else {
      const fs::path stem = out.parent_path() / out.stem();
      EXPECT_EQ(again.materials.libraries,
                std::vector<std::string>{fs::canonical(stem.string() + ".mtl").string()});
      std::vector<std::string> maps;
      for (const std::optional<apps::Diffuse_map>& map : apps::diffuse_maps(again.materials))
        if (map) maps.push_back(read_text(map->path));
      EXPECT_EQ(maps,
                std::vector<std::string>{read_text(test_meshes::data_file("bob_diffuse.png"))});
    }
  }
  fs::remove_all(folder);
}

// A mesh with texture coordinates, normals and colours, seams everywhere, written as PLY (a vertex
// per wedge) reads back as the same mesh, every corner's values exact and each seam whole.
TEST(CornerAttributes, PlyWrittenWithItsWedgesReadsBackExactly) {
  Mesh cube = test_meshes::six_sided_cube();
  test_meshes::paint_corners(
      cube,
      [&](Mesh::Face_index f, const apps::Point& p) {
        return test_meshes::cube_chart(test_meshes::cube_side(cube, f), p);
      },
      true);
  test_meshes::paint_colors(cube, [&](Mesh::Face_index f, const apps::Point& p) {
    // Whole steps of 1/255, which a byte holds exactly.
    return std::array<double, 4>{test_meshes::cube_side(cube, f) * 40 / 255.0, p.x() * 60 / 255.0,
                                 1, 1};
  });
  const fs::path folder = scratch_folder("ply_wedges");
  const std::string path = (folder / "cube.ply").string();
  apps::write_mesh_atomically(cube, path);
  const apps::Polygon_soup soup = apps::parse_ply(path, read_text(path));
  // A vertex per side it lies on: 3 at each of the 8 corners, 2 along the 12 edges' 3 inner
  // points, 1 at the 9 inner points of each side.
  EXPECT_EQ(soup.points.size(), 8u * 3 + 12u * 3 * 2 + 6u * 9);
  const Mesh reread = apps::read_triangle_mesh(path, nullptr, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(reread.number_of_vertices(), cube.number_of_vertices());
  EXPECT_TRUE(CGAL::is_closed(reread));
  EXPECT_EQ(face_corners(reread), face_corners(cube));
  // Every edge of the cube is a seam: 12 edges of 4 segments.
  EXPECT_EQ(apps::measure_attribute_error(cube, reread, 1000).seam_edges_b, 48u);
  fs::remove_all(folder);
}

// ---------------------------------------------------------------------------------------------
// glTF (.gltf, .glb): corners per glTF vertex, points welded, materials and images passed through.

// Each value as glTF stores it: through float, and v counted from the image's top (1 - v).
std::vector<Face_corners> through_float(std::vector<Face_corners> faces) {
  for (Face_corners& face : faces)
    for (auto& corner : face.corners) {
      const double v = corner[4];
      for (double& c : corner) c = double(float(c));
      corner[4] = 1 - double(float(1 - v));
    }
  return faces;
}

std::vector<Face_corners> sorted(std::vector<Face_corners> faces) {
  std::sort(faces.begin(), faces.end(), [](const Face_corners& a, const Face_corners& b) {
    return std::tie(a.corners, a.material) < std::tie(b.corners, b.material);
  });
  return faces;
}

std::size_t seam_edge_count(const Mesh& mesh) {
  const Attributes a(mesh);
  std::size_t seams = 0;
  for (const auto e : mesh.edges()) seams += a.is_seam_edge(mesh, mesh.halfedge(e));
  return seams;
}

// six_sided_cube(per_side) moved off the float grid, each side its own texture chart, its normal,
// its colour and one of two materials.
Mesh painted_cube(int per_side = 4) {
  Mesh mesh = test_meshes::six_sided_cube(per_side);
  for (const auto v : mesh.vertices())
    mesh.point(v) = mesh.point(v) + apps::Kernel::Vector_3(0.1, 0.2, 1.0 / 3);
  const Attributes a = Attributes::add(mesh, {true, true, true, true, false});
  for (const auto f : mesh.faces()) {
    const int side = test_meshes::cube_side(mesh, f);
    (*a.materials)[f] = std::uint32_t(side % 2);
    const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh);
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point p = mesh.point(mesh.target(h)) - apps::Kernel::Vector_3(0.1, 0.2, 1.0 / 3);
      (*a.uvs)[h] = test_meshes::cube_chart(side, p);
      (*a.uvs)[h][1] += 1.0 / 7;
      (*a.normals)[h] = n;
      (*a.colors)[h] = {side / 7.0, 0.3, 1.0 / 3, 0.9};
    }
  }
  return mesh;
}

TEST(Gltf, ARoundTripKeepsEveryCornerToFloatPrecision) {
  const fs::path folder = scratch_folder("gltf_round_trip");
  const Mesh cube = painted_cube();
  const apps::Material_references names{{}, {"even", "odd"}, nullptr, {}};
  for (const std::string name : {"cube.gltf", "cube.glb"}) {
    SCOPED_TRACE(name);
    const fs::path out = folder / name;
    apps::write_mesh_atomically(cube, out.string(), names);
    apps::Read_report report;
    const Mesh read =
        apps::read_triangle_mesh(out.string(), &report, apps::Corner_attribute_reading::keep);
    EXPECT_TRUE(report.repairs.empty());
    // One closed surface: the seams split no vertex of the mesh.
    EXPECT_EQ(read.number_of_vertices(), cube.number_of_vertices());
    EXPECT_EQ(read.number_of_faces(), 192u);
    EXPECT_EQ(test_meshes::border_edge_count(read), 0u);
    EXPECT_EQ(sorted(face_corners(read)), sorted(through_float(face_corners(cube))));
    EXPECT_EQ(seam_edge_count(read), 48u);  // the cube's 12 edges, 4 mesh edges each
    EXPECT_EQ(seam_edge_count(read), seam_edge_count(cube));
    EXPECT_EQ(report.materials.names, names.names);
    ASSERT_TRUE(report.materials.gltf);
    EXPECT_EQ(report.materials.gltf->materials.size(), 2u);
  }
  fs::remove_all(folder);
}

// A glTF or GLB file as tinygltf reads it, its images undecoded: their bytes stay in their views.
tinygltf::Model undecoded_gltf(const fs::path& path) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader([](tinygltf::Image*, int, std::string*, std::string*, int, int,
                           const unsigned char*, int, void*) { return true; },
                        nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool loaded = path.extension() == ".glb"
                          ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                          : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
  EXPECT_TRUE(loaded) << path << ": " << error;
  return model;
}

// The bytes of an image stored in a bufferView.
std::string view_bytes(const tinygltf::Model& model, const tinygltf::Image& image) {
  const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(image.bufferView));
  const std::vector<unsigned char>& data = model.buffers.at(std::size_t(view.buffer)).data;
  return std::string(data.begin() + std::ptrdiff_t(view.byteOffset),
                     data.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
}

// The JSON of a .gltf file, or of a GLB's JSON chunk.
nlohmann::json gltf_json(const fs::path& path) {
  const std::string bytes = read_text(path);
  if (path.extension() != ".glb") return nlohmann::json::parse(bytes);
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return nlohmann::json::parse(bytes.substr(20, length));
}

// painted_cube() with a normal leaning differently at every corner, and its texture coordinates
// (u, v) mapped to (a u + b, c v), `uv_map` being {a, b, c}.
Mesh leaning_cube(const std::array<double, 3>& uv_map) {
  Mesh cube = painted_cube();
  const Attributes a(cube);
  for (const auto h : cube.halfedges()) {
    if (cube.is_border(h)) continue;
    const apps::Point& p = cube.point(cube.target(h));
    const apps::Kernel::Vector_3 lean =
        (*a.normals)[h] + apps::Kernel::Vector_3(p.x() / 9, p.y() / 7, p.z() / 5);
    (*a.normals)[h] = lean / std::sqrt(lean.squared_length());
    (*a.uvs)[h] = {uv_map[0] * (*a.uvs)[h][0] + uv_map[1], uv_map[2] * (*a.uvs)[h][1]};
  }
  return cube;
}

// Each vertex of `read` matched to the nearest vertex of `source` (their largest coordinate
// difference), and the largest such distance.
std::pair<std::map<Mesh::Vertex_index, Mesh::Vertex_index>, double> nearest_vertices(
    const Mesh& read, const Mesh& source) {
  const auto distance = [](const apps::Point& p, const apps::Point& q) {
    return std::max({std::abs(p.x() - q.x()), std::abs(p.y() - q.y()), std::abs(p.z() - q.z())});
  };
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> match;
  double largest = 0;
  for (const auto v : read.vertices()) {
    Mesh::Vertex_index nearest;
    for (const auto w : source.vertices())
      if (nearest == Mesh::null_vertex() ||
          distance(read.point(v), source.point(w)) < distance(read.point(v), source.point(nearest)))
        nearest = w;
    match[v] = nearest;
    largest = std::max(largest, distance(read.point(v), source.point(nearest)));
  }
  return {match, largest};
}

// Each vertex of `read` matched to the nearest of `source`'s: one each, every point within
// `position_step` / 2 of its source, every face of `read` a face of `source` (each once), every
// corner's texture coordinates, normal and colour within `uv_tolerance`, 1 / 127 (normalized i8,
// renormalized on reading) and 1 / 510 (half a step of u8) of its source corner's, and the same
// material.
void expect_within_steps(const Mesh& source, const Mesh& read, double position_step,
                         double uv_tolerance) {
  ASSERT_EQ(read.number_of_vertices(), source.number_of_vertices());
  ASSERT_EQ(read.number_of_faces(), source.number_of_faces());
  auto [match, point_error] = nearest_vertices(read, source);
  std::set<Mesh::Vertex_index> matched;
  for (const auto& pair : match) matched.insert(pair.second);
  EXPECT_EQ(matched.size(), source.number_of_vertices());
  EXPECT_LE(point_error, position_step / 2 * (1 + 1e-9));
  const Attributes a(source), b(read);
  ASSERT_TRUE(a.uvs && b.uvs && a.normals && b.normals && a.colors && b.colors && a.materials &&
              b.materials);
  std::set<Mesh::Face_index> faces;
  double uv_error = 0, normal_error = 0, color_error = 0;
  for (const auto h : read.halfedges()) {
    if (read.is_border(h)) continue;
    const auto g = source.halfedge(match[read.source(h)], match[read.target(h)]);
    ASSERT_TRUE(g != Mesh::null_halfedge() && !source.is_border(g));
    faces.insert(source.face(g));
    EXPECT_EQ((*b.materials)[read.face(h)], (*a.materials)[source.face(g)]);
    for (int k : {0, 1}) uv_error = std::max(uv_error, std::abs((*b.uvs)[h][k] - (*a.uvs)[g][k]));
    for (int k : {0, 1, 2})
      normal_error = std::max(normal_error, std::abs((*b.normals)[h][k] - (*a.normals)[g][k]));
    for (int k : {0, 1, 2, 3})
      color_error = std::max(color_error, std::abs((*b.colors)[h][k] - (*a.colors)[g][k]));
  }
  EXPECT_EQ(faces.size(), source.number_of_faces());
  EXPECT_LE(uv_error, uv_tolerance);
  EXPECT_LE(normal_error, 1.0 / 127);
  EXPECT_LE(color_error, 0.5 / 255 + 1e-12);
}

// The leaning cube written quantized and meshopt-compressed, as .gltf and .glb, read back within
// a quantization step of every value (expect_within_steps): positions u16 on a grid of the cube's
// side / 65535 under the node's translation and uniform scale, normals i8, colours u8. Its
// texture coordinates, once glTF's v = 1 - v is taken, are normalized u16 when they lie in
// [0, 1], normalized i16 in [-1, 1], and float (read back to float precision) when they run past
// it, as the painted cube's do (u up to 6). The meshopt files read back exactly as the quantized
// ones.
TEST(Gltf, QuantizedAndMeshoptOutputsReadBackWithinAStep) {
  const fs::path folder = scratch_folder("gltf_encodings");
  const apps::Material_references names{{}, {"even", "odd"}, nullptr, {}};
  struct Uv_case {
    std::string name;
    std::array<double, 3> uv_map;
    int component_type;
    double tolerance;
  };
  for (const Uv_case& uv_case :
       {Uv_case{"uvs in [0, 1]", {1.0 / 6, 0, 0.5}, kUnsignedShort, 0.5 / 65535 + 1e-12},
        Uv_case{"uvs in [-1, 1]",
                {1.0 / 6, -0.5, 0.5},
                TINYGLTF_COMPONENT_TYPE_SHORT,
                0.5 / 32767 + 1e-12},
        Uv_case{"uvs past [-1, 1]", {1, 0, 1}, kFloat, 6.0 / (1 << 24)}}) {
    const Mesh cube = leaning_cube(uv_case.uv_map);
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(cube);
    const double step =
        std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) /
        65535;
    for (const std::string name : {"cube.gltf", "cube.glb"}) {
      std::map<apps::Gltf_encoding, std::vector<Face_corners>> read_back;
      for (const apps::Gltf_encoding encoding :
           {apps::Gltf_encoding::quantized, apps::Gltf_encoding::meshopt}) {
        const bool meshopt = encoding == apps::Gltf_encoding::meshopt;
        SCOPED_TRACE(name + (meshopt ? " meshopt, " : " quantized, ") + uv_case.name);
        const fs::path out = folder / name;
        apps::write_mesh_atomically(cube, out.string(), names, encoding);
        apps::Read_report report;
        const Mesh read =
            apps::read_triangle_mesh(out.string(), &report, apps::Corner_attribute_reading::keep);
        EXPECT_TRUE(report.repairs.empty());
        EXPECT_EQ(report.materials.names, names.names);
        expect_within_steps(cube, read, step, uv_case.tolerance);
        read_back[encoding] = face_corners(read);

        // tinygltf 2.7 cannot load a .gltf's fallback buffer (it has no uri): the JSON as it is.
        const nlohmann::json gltf = gltf_json(out);
        const std::vector<std::string> required =
            meshopt ? std::vector<std::string>{"KHR_mesh_quantization", "EXT_meshopt_compression"}
                    : std::vector<std::string>{"KHR_mesh_quantization"};
        EXPECT_EQ(gltf["extensionsRequired"], required);
        EXPECT_EQ(gltf["extensionsUsed"], required);
        ASSERT_EQ(gltf["nodes"].size(), 1u);
        EXPECT_EQ(gltf["nodes"][0]["translation"],
                  (std::vector<double>{box.xmin(), box.ymin(), box.zmin()}));
        EXPECT_EQ(gltf["nodes"][0]["scale"], std::vector<double>(3, step));
        const nlohmann::json& primitives = gltf["meshes"][0]["primitives"];
        ASSERT_EQ(primitives.size(), 2u);  // a primitive per material
        // An accessor's component type, whether it is normalized, and its view's byteStride.
        const auto layout = [&](int accessor) {
          const nlohmann::json& a = gltf["accessors"][std::size_t(accessor)];
          return std::make_tuple(
              a["componentType"].get<int>(), a.value("normalized", false),
              gltf["bufferViews"][a["bufferView"].get<std::size_t>()].value("byteStride", 0));
        };
        const nlohmann::json& attributes = primitives[0]["attributes"];
        EXPECT_EQ(layout(attributes["POSITION"]), std::make_tuple(kUnsignedShort, false, 8));
        EXPECT_EQ(layout(attributes["NORMAL"]),
                  std::make_tuple(TINYGLTF_COMPONENT_TYPE_BYTE, true, 4));
        EXPECT_EQ(layout(attributes["COLOR_0"]), std::make_tuple(kUnsignedByte, true, 4));
        EXPECT_EQ(layout(attributes["TEXCOORD_0"]),
                  std::make_tuple(uv_case.component_type, uv_case.component_type != kFloat,
                                  uv_case.component_type == kFloat ? 0 : 4));
        EXPECT_EQ(layout(primitives[0]["indices"]), std::make_tuple(kUnsignedShort, false, 0));
        // Meshopt: the four attributes' views and the indices' compressed, their fallback buffer
        // without data.
        std::size_t compressed = 0;
        for (const nlohmann::json& view : gltf["bufferViews"])
          compressed += view.contains("extensions");
        EXPECT_EQ(compressed, meshopt ? 5u : 0u);
        EXPECT_EQ(gltf["buffers"].size(), meshopt ? 2u : 1u);
        if (meshopt) {
          EXPECT_FALSE(gltf["buffers"][1].contains("uri"));
          EXPECT_EQ(gltf["buffers"][1]["extensions"]["EXT_meshopt_compression"]["fallback"], true);
        }
      }
      EXPECT_EQ(read_back[apps::Gltf_encoding::meshopt], read_back[apps::Gltf_encoding::quantized]);
    }
  }
  fs::remove_all(folder);
}

// A normal near the diagonal whose components all round up by almost half a step: its nearest
// bytes, (76, 78, 67), are 0.0068 too long for a unit vector, past the Khronos validator's 0.00674.
// The quantized file stores (76, 78, 66), the roundings' nearest in direction within it, on the
// three corners that have it, and (0, 0, 127) on every other corner (+z).
TEST(Gltf, QuantizedNormalsStayUnitWhereTheNearestBytesWouldNot) {
  const fs::path folder = scratch_folder("gltf_unit_normals");
  Mesh plane = test_meshes::textured_plane(true);
  const Attributes a(plane);
  const apps::Kernel::Vector_3 diagonal(0.59449212598425194, 0.61024015748031502,
                                        0.52362778988621739);
  for (const auto h : CGAL::halfedges_around_face(plane.halfedge(*plane.faces().begin()), plane))
    (*a.normals)[h] = diagonal;
  const fs::path out = folder / "plane.glb";
  apps::write_mesh_atomically(plane, out.string(), {}, apps::Gltf_encoding::quantized);
  const tinygltf::Model model = undecoded_gltf(out);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  const tinygltf::Accessor& normals =
      model.accessors.at(std::size_t(model.meshes[0].primitives[0].attributes.at("NORMAL")));
  const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(normals.bufferView));
  const std::vector<unsigned char>& data = model.buffers.at(std::size_t(view.buffer)).data;
  std::map<std::array<int, 3>, std::size_t> count;
  for (std::size_t i = 0; i < normals.count; ++i) {
    const std::size_t at = view.byteOffset + normals.byteOffset + i * view.byteStride;
    std::array<int, 3> bytes;
    for (std::size_t k = 0; k < 3; ++k) bytes[k] = int(std::int8_t(data.at(at + k)));
    ++count[bytes];
  }
  EXPECT_EQ(count, (std::map<std::array<int, 3>, std::size_t>{{{0, 0, 127}, normals.count - 3},
                                                              {{76, 78, 66}, 3}}));
  fs::remove_all(folder);
}

// bob as OBJ, written as GLB and as .gltf and read back: every corner as it was, to float
// precision, its v turned on the way out and back. bob's material names bob_diffuse.png (map_Kd):
// both files embed its bytes as they are, as the base colour texture of bob's one material, and
// name no other file.
TEST(Gltf, AnObjThroughGltfKeepsEveryCornerAndEmbedsItsTexture) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path folder = scratch_folder("gltf_bob");
  apps::Read_report report;
  const Mesh bob = apps::read_triangle_mesh(test_meshes::data_file("bob_tri.obj"), &report,
                                            apps::Corner_attribute_reading::keep);
  const std::string png = read_text(test_meshes::data_file("bob_diffuse.png"));
  for (const std::string name : {"bob.glb", "bob.gltf"}) {
    SCOPED_TRACE(name);
    const fs::path out = folder / "out" / name;
    EXPECT_EQ(apps::write_mesh_atomically(bob, out.string(), report.materials),
              std::vector<std::string>{});
    const Mesh read =
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
    EXPECT_EQ(read.number_of_faces(), bob.number_of_faces());
    EXPECT_EQ(sorted(face_corners(read)), sorted(through_float(face_corners(bob))));

    const tinygltf::Model model = undecoded_gltf(out);
    ASSERT_EQ(model.buffers.size(), 1u);  // a GLB's BIN chunk, a .gltf's data URI
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_EQ(model.images[0].mimeType, "image/png");
    EXPECT_EQ(model.images[0].uri, "");
    EXPECT_EQ(model.images[0].name, "bob_diffuse");
    EXPECT_EQ(view_bytes(model, model.images[0]), png);
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.textures[0].source, 0);
    EXPECT_EQ(model.textures[0].sampler, 0);
    ASSERT_EQ(model.samplers.size(), 1u);
    EXPECT_EQ(model.samplers[0].magFilter, TINYGLTF_TEXTURE_FILTER_LINEAR);
    EXPECT_EQ(model.samplers[0].minFilter, TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR);
    EXPECT_EQ(model.samplers[0].wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
    EXPECT_EQ(model.samplers[0].wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].name, "feathers");
    EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
    EXPECT_EQ(model.materials[0].pbrMetallicRoughness.baseColorTexture.texCoord, 0);
    EXPECT_EQ(read_text(out).find("bob_diffuse.png"), std::string::npos);
  }
  fs::remove_all(folder);
}

// Four squares' materials, each naming a map_Kd: a PNG named .jpg (after an option), a JPEG named
// .png, a file that is not there and a Targa file (which glTF cannot hold); a fifth material names
// the PNG again. The files are told by their first bytes, the PNG is embedded once, and each map
// that cannot be is one line; the same squares without texture coordinates get no texture.
TEST(Gltf, DiffuseMapsAreToldByTheirBytesAndTheMissingOnesAreLinesNotFailures) {
  const fs::path folder = scratch_folder("gltf_maps");
  const std::string jpeg = std::string("\xff\xd8\xff\xe0", 4) + "not decoded";
  std::ofstream(folder / "photo.jpg", std::ios::binary) << gltf_fixtures::kImageBytes;
  std::ofstream(folder / "scan.png", std::ios::binary) << jpeg;
  std::ofstream(folder / "skin.tga", std::ios::binary) << std::string(18, '\0');
  std::ofstream(folder / "looks.mtl")
      << "newmtl png\nmap_Kd -s 1 1 1 photo.jpg\nnewmtl jpeg\nmap_Kd scan.png\n"
         "newmtl missing\nmap_Kd missing.png\nnewmtl targa\nmap_Kd skin.tga\n"
         "newmtl png_again\nmap_Kd photo.jpg\n";
  std::ostringstream squares, bare;
  squares << "mtllib looks.mtl\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  bare << "mtllib looks.mtl\n";
  int x = 0;
  for (const std::string material : {"png", "jpeg", "missing", "targa", "png_again"}) {
    x += 2;
    for (std::ostringstream* obj : {&squares, &bare})
      *obj << "v " << x << " 0 0\nv " << x + 1 << " 0 0\nv " << x + 1 << " 1 0\nv " << x
           << " 1 0\nusemtl " << material << '\n';
    squares << "f -4/1 -3/2 -2/3 -1/4\n";
    bare << "f -4 -3 -2 -1\n";
  }
  std::ofstream(folder / "squares.obj") << squares.str();
  std::ofstream(folder / "bare.obj") << bare.str();
  const std::string library = (folder / "looks.mtl").string();

  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "squares.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  const fs::path out = folder / "out" / "squares.glb";
  EXPECT_EQ(apps::write_mesh_atomically(mesh, out.string(), report.materials),
            (std::vector<std::string>{
                library + ": texture 'missing.png' does not exist; written without it",
                library + ": texture 'skin.tga' is neither a PNG nor a JPEG image; written without "
                          "it"}));
  const tinygltf::Model model = undecoded_gltf(out);
  ASSERT_EQ(model.images.size(), 2u);
  EXPECT_EQ(model.images[0].mimeType, "image/png");
  EXPECT_EQ(view_bytes(model, model.images[0]), gltf_fixtures::kImageBytes);
  EXPECT_EQ(model.images[1].mimeType, "image/jpeg");
  EXPECT_EQ(view_bytes(model, model.images[1]), jpeg);
  ASSERT_EQ(model.textures.size(), 2u);
  EXPECT_EQ(model.textures[1].source, 1);
  std::vector<int> textures;
  for (const tinygltf::Material& material : model.materials)
    textures.push_back(material.pbrMetallicRoughness.baseColorTexture.index);
  EXPECT_EQ(textures, (std::vector<int>{0, 1, -1, -1, 0}));
  EXPECT_EQ(apps::read_triangle_mesh(out.string()).number_of_faces(), 10u);

  apps::Read_report bare_report;
  const Mesh bare_mesh = apps::read_triangle_mesh((folder / "bare.obj").string(), &bare_report,
                                                  apps::Corner_attribute_reading::keep);
  const fs::path bare_out = folder / "out" / "bare.glb";
  EXPECT_EQ(apps::write_mesh_atomically(bare_mesh, bare_out.string(), bare_report.materials),
            std::vector<std::string>{});
  const tinygltf::Model bare_model = undecoded_gltf(bare_out);
  EXPECT_EQ(bare_model.images.size(), 0u);
  EXPECT_EQ(bare_model.textures.size(), 0u);
  EXPECT_EQ(bare_model.samplers.size(), 0u);
  ASSERT_EQ(bare_model.materials.size(), 5u);
  EXPECT_EQ(bare_model.materials[0].pbrMetallicRoughness.baseColorTexture.index, -1);
  fs::remove_all(folder);
}

// A glTF model whose buffer 0 gets each array as an accessor of its own.

TEST(Gltf, TwoPrimitivesWithAUvSeamAreOneConnectedMesh) {
  const fs::path folder = scratch_folder("gltf_seam");
  const fs::path in = folder / "square.glb";
  two_primitive_square().write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.repairs.empty());
  ASSERT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(test_meshes::border_edge_count(mesh), 4u);  // the diagonal joins the two
  EXPECT_EQ(report.materials.names, (std::vector<std::string>{"paint", "material_1"}));
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.materials);
  EXPECT_FALSE(a.normals);
  // The node's translation moved the points; the second primitive's corners are its own.
  const auto diagonal =
      test_meshes::halfedge_between(mesh, apps::Point(10, 0, 0), apps::Point(11, 1, 0));
  const auto other = mesh.opposite(diagonal);
  EXPECT_TRUE(a.is_seam_edge(mesh, diagonal));
  const Mesh::Halfedge_index in_first = (*a.materials)[mesh.face(diagonal)] == 0 ? diagonal : other;
  const Mesh::Halfedge_index in_second = in_first == diagonal ? other : diagonal;
  EXPECT_EQ((*a.materials)[mesh.face(in_second)], 1u);
  const auto corner_at = [&](Mesh::Halfedge_index h, const apps::Point& p) {
    return mesh.point(mesh.target(h)) == p ? h : mesh.prev(h);
  };
  // glTF counts v from the image's top, the mesh from its bottom: the reader turns it.
  EXPECT_EQ((*a.uvs)[corner_at(in_first, {11, 1, 0})], (Attributes::Uv{0.5, 0.5}));
  EXPECT_EQ((*a.uvs)[corner_at(in_second, {11, 1, 0})], (Attributes::Uv{0.8, 1 - 0.8}));
  EXPECT_EQ((*a.uvs)[corner_at(in_first, {10, 0, 0})], (Attributes::Uv{0, 1}));
  EXPECT_EQ((*a.uvs)[corner_at(in_second, {10, 0, 0})], (Attributes::Uv{0, 1}));
  // Colours: the first primitive's, RGB with alpha 1; none on the second's corners.
  ASSERT_TRUE(a.colors);
  EXPECT_EQ((*a.colors)[corner_at(in_first, {10, 0, 0})], (Attributes::Color{0, 0.2, 1, 1}));
  EXPECT_TRUE(std::isnan((*a.colors)[corner_at(in_second, {10, 0, 0})][0]));
  fs::remove_all(folder);
}

// The names of the files in `folder`.
std::set<std::string> file_names(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder))
    names.insert(entry.path().filename().string());
  return names;
}

// The `vt` lines of an OBJ file's text.
std::set<std::string> texture_coordinate_lines(const std::string& obj) {
  std::set<std::string> lines;
  std::istringstream text(obj);
  for (std::string line; std::getline(text, line);)
    if (line.rfind("vt ", 0) == 0) lines.insert(line);
  return lines;
}

// textured_square() written as OBJ: a material library beside it defines the two materials its
// faces use (not "unused"), with their colours and images: paint's image, which the glTF file
// held (a PNG in a GLB's bufferView, a JPEG in a .gltf's data URI), becomes a file of its bytes
// beside the OBJ, and the other material's image file is named from the OBJ's folder. The texture
// coordinates are OBJ's, v from the image's bottom, and the OBJ reads back with the same ones, its
// images found through the library.
TEST(Gltf, AnObjOfAGltfGetsAMaterialLibraryAndTheImagesTheGltfHeld) {
  const fs::path folder = scratch_folder("gltf_to_obj");
  fs::create_directories(folder / "tex");
  std::ofstream(folder / "tex" / "skin.png") << gltf_fixtures::kImageBytes;
  using Case = std::tuple<std::string, int, std::string, std::string>;
  for (const auto& [name, paint_texture, image, bytes] :
       {Case{"glb", 0, "square_image0.png", gltf_fixtures::kImageBytes},
        Case{"gltf", 2, "square_image2.jpg", gltf_fixtures::kJpegBytes}}) {
    SCOPED_TRACE(name);
    const fs::path in = folder / ("square." + name);
    gltf_fixtures::textured_square(paint_texture, 2 - paint_texture).write(in);
    apps::Read_report report;
    const Mesh mesh =
        apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
    const fs::path out_folder = folder / ("from_" + name);
    fs::create_directories(out_folder);
    const fs::path out = out_folder / "square.obj";
    EXPECT_EQ(apps::write_mesh_atomically(mesh, out.string(), report.materials),
              std::vector<std::string>{});
    // The image file outside the OBJ's folder is copied beside it.
    EXPECT_EQ(file_names(out_folder),
              (std::set<std::string>{"square.obj", "square.mtl", image, "square_image1.png"}));
    EXPECT_EQ(read_text(out_folder / "square.mtl"),
              "# written by cgal_policies\n\nnewmtl paint\nKd 0.5 0.25 1\nmap_Kd " + image +
                  "\n\nnewmtl material_1\nKd 0.2 0.4 0.6\nd 0.5\nmap_Kd square_image1.png\n");
    EXPECT_EQ(read_text(out_folder / image), bytes);
    EXPECT_EQ(read_text(out_folder / "square_image1.png"), gltf_fixtures::kImageBytes);
    const std::string obj = read_text(out);
    EXPECT_EQ(obj.rfind("# written by cgal_policies\nmtllib square.mtl\n", 0), 0u) << obj;
    EXPECT_NE(obj.find("\nusemtl paint\n"), std::string::npos) << obj;
    EXPECT_NE(obj.find("\nusemtl material_1\n"), std::string::npos) << obj;
    // glTF's (0, 0), (0.5, 0), (0.5, 0.5) and (0, 0), (0.8, 0.8), (0, 1), v counted from the top.
    EXPECT_EQ(texture_coordinate_lines(obj),
              (std::set<std::string>{"vt 0 1", "vt 0.5 1", "vt 0.5 0.5",
                                     "vt 0.8 0.19999999999999996", "vt 0 0"}));

    apps::Read_report again;
    EXPECT_EQ(uvs_by_corner(apps::read_triangle_mesh(out.string(), &again,
                                                     apps::Corner_attribute_reading::keep)),
              uvs_by_corner(mesh));
    EXPECT_EQ(again.materials.names, (std::vector<std::string>{"paint", "material_1"}));
    std::vector<std::string> maps;
    for (const std::optional<apps::Diffuse_map>& map : apps::diffuse_maps(again.materials))
      maps.push_back(map ? map->path : "none");
    EXPECT_EQ(maps, (std::vector<std::string>{(out_folder / image).string(),
                                              (out_folder / "square_image1.png").string()}));
  }
  fs::remove_all(folder);
}

// The Io_error of writing `mesh` into `path`, of kind unwritable output; empty when it is written.
std::string write_failure(const Mesh& mesh, const fs::path& path,
                          const apps::Material_references& materials) {
  try {
    apps::write_mesh_atomically(mesh, path.string(), materials);
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(e.kind(), apps::Io_error::Kind::unwritable_output);
    return e.what();
  }
  return "";
}

// An OBJ of a glTF file, its library and images are written together or not at all: one that
// cannot be renamed into place (a folder of the library's name is there) leaves none of them, and
// one that would overwrite an image file of the input is refused before any is written.
// textured_square() as `folder`/square.glb, read back, its second image the file `uri` names in
// that folder, `file` (which holds "the input's").
Mesh square_naming_an_image_file(const fs::path& folder, const std::string& uri,
                                 const std::string& file, apps::Read_report& report) {
  Gltf_builder square = gltf_fixtures::textured_square(0, 2);
  square.model.images[1].uri = uri;
  square.write(folder / "square.glb");
  std::ofstream(folder / file) << "the input's";
  return apps::read_triangle_mesh((folder / "square.glb").string(), &report,
                                  apps::Corner_attribute_reading::keep);
}

TEST(Gltf, AnObjOfAGltfAndItsLibraryAreWrittenAllOrNothing) {
  const fs::path folder = scratch_folder("gltf_to_obj_failures");
  apps::Read_report report;
  const Mesh mesh =
      square_naming_an_image_file(folder, "square_image0.png", "square_image0.png", report);

  fs::create_directories(folder / "out" / "square.mtl");
  const std::string cause = write_failure(mesh, folder / "out" / "square.obj", report.materials);
  EXPECT_EQ(cause.rfind((folder / "out" / "square.mtl").string() + ": cannot write: ", 0), 0u)
      << cause;
  EXPECT_EQ(file_names(folder / "out"), std::set<std::string>{"square.mtl"});

  EXPECT_EQ(
      write_failure(mesh, folder / "square.obj", report.materials),
      (folder / "square_image0.png").string() + ": refusing to overwrite an image of the input");
  EXPECT_EQ(file_names(folder), (std::set<std::string>{"out", "square.glb", "square_image0.png"}));
  EXPECT_EQ(read_text(folder / "square_image0.png"), "the input's");
  fs::remove_all(folder);
}

// glTF's image uris are URI references: "a%20b_image0.png" names the file "a b_image0.png". An
// OBJ's library names that file as it is, a glTF file written beside it by its URI again, and an
// OBJ that would write its own image over it ("a b.obj" writes paint's as "a b_image0.png") is
// refused, the file as it was.
TEST(Gltf, ImageUrisNameTheFilesTheyEncode) {
  const fs::path folder = scratch_folder("gltf_encoded_uris");
  apps::Read_report report;
  const Mesh mesh =
      square_naming_an_image_file(folder, "a%20b_image0.png", "a b_image0.png", report);
  apps::write_mesh_atomically(mesh, (folder / "square.obj").string(), report.materials);
  const std::string library = read_text(folder / "square.mtl");
  EXPECT_NE(library.find("\nmap_Kd a b_image0.png\n"), std::string::npos) << library;
  apps::write_mesh_atomically(mesh, (folder / "square.gltf").string(), report.materials);
  EXPECT_EQ(gltf_json(folder / "square.gltf")["images"][1]["uri"], "a%20b_image0.png");
  EXPECT_EQ(write_failure(mesh, folder / "a b.obj", report.materials),
            (folder / "a b_image0.png").string() + ": refusing to overwrite an image of the input");
  EXPECT_EQ(read_text(folder / "a b_image0.png"), "the input's");
  fs::remove_all(folder);
}

// A base colour texture whose image is a WebP held in the file, or that has no image but in an
// extension (KHR_texture_basisu's), is left out of the library with a line each; the OBJ and the
// rest of the library are written.
TEST(Gltf, ATextureWithoutAPngOrJpegImageIsALineNotAFailure) {
  const fs::path folder = scratch_folder("gltf_to_obj_webp");
  Gltf_builder square = gltf_fixtures::textured_square(0, 2);
  square.model.materials[0].pbrMetallicRoughness.baseColorTexture.index =
      square.held_image(std::string("RIFF\0\0\0\0WEBP", 12), "image/webp");
  square.model.textures[1].source = -1;
  square.model.textures[1].extensions["KHR_texture_basisu"] =
      tinygltf::Value(tinygltf::Value::Object{{"source", tinygltf::Value(1)}});
  square.model.extensionsUsed.push_back("KHR_texture_basisu");
  square.write(folder / "square.glb");
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "square.glb").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  const fs::path library = folder / "out" / "square.mtl";
  const std::string cause =
      "': its base colour texture has no PNG or JPEG image; written without it";
  EXPECT_EQ(
      apps::write_mesh_atomically(mesh, (folder / "out" / "square.obj").string(), report.materials),
      (std::vector<std::string>{library.string() + ": material 'paint" + cause,
                                library.string() + ": material 'material_1" + cause}));
  EXPECT_EQ(read_text(library),
            "# written by cgal_policies\n\nnewmtl paint\nKd 0.5 0.25 1\n"
            "\nnewmtl material_1\nKd 0.2 0.4 0.6\nd 0.5\n");
  EXPECT_EQ(file_names(folder / "out"), (std::set<std::string>{"square.obj", "square.mtl"}));
  fs::remove_all(folder);
}

// OBJ levels of detail of a glTF file share one library and its images, named after the chain's
// path. With them, kMaxFilesWrittenAtOnce files are written at once; a chain of one more level is
// refused before any file is written.
TEST(Gltf, ObjLevelsOfAGltfShareOneLibraryWithinTheFileLimit) {
  const fs::path folder = scratch_folder("gltf_to_obj_levels");
  gltf_fixtures::textured_square(0, 2).write(folder / "square.glb");
  fs::create_directories(folder / "tex");
  std::ofstream(folder / "tex" / "skin.png", std::ios::binary) << gltf_fixtures::kImageBytes;
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "square.glb").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  // Beside the levels, the library, paint's image and a copy of the image file, which lies
  // outside the levels' folder.
  const std::size_t most = apps::kMaxFilesWrittenAtOnce - 3;
  std::vector<apps::Lod_level> levels(most, {&mesh, 0});
  EXPECT_EQ(apps::write_lod_chain_atomically(levels, (folder / "out" / "square.obj").string(),
                                             report.materials),
            std::vector<std::string>{});
  const std::set<std::string> written = file_names(folder / "out");
  EXPECT_EQ(written.size(), apps::kMaxFilesWrittenAtOnce);
  EXPECT_EQ(written.count("square.mtl") + written.count("square_image0.png") +
                written.count("square_image1.png"),
            3u);
  for (const std::size_t level : {std::size_t(0), most - 1}) {
    const std::string obj =
        read_text(folder / "out" / ("square_lod" + std::to_string(level) + ".obj"));
    EXPECT_EQ(obj.rfind("# written by cgal_policies\nmtllib square.mtl\n", 0), 0u) << level;
  }

  levels.push_back({&mesh, 0});
  fs::create_directories(folder / "more");
  try {
    apps::write_lod_chain_atomically(levels, (folder / "more" / "square.obj").string(),
                                     report.materials);
    ADD_FAILURE() << "written";
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(std::string(e.what()),
              (folder / "more" / "square.obj").string() + ": cannot write " +
                  std::to_string(most + 4) +
                  " files at once (levels, material library and images); at most " +
                  std::to_string(apps::kMaxFilesWrittenAtOnce));
  }
  EXPECT_TRUE(fs::is_empty(folder / "more"));
  fs::remove_all(folder);
}

// The unit square as KHR_mesh_quantization writes it: unnormalized u16 positions that the node
// scales by a half, sparse (all zero, three of them substituted), normalized i8 normals,
// unnormalized u8 texture coordinates that the base colour texture's KHR_texture_transform scales
// and moves, a second set of them (u8, 0 or 2) that the occlusion texture reads through a transform
// of its own (scaled by a half, moved by (1/4, 0)), which names the set, u8 indices.
Gltf_builder quantized_square() {
  Gltf_builder b;
  const int substitutes = b.accessor(std::vector<std::uint16_t>{2, 0, 0, 0, 2, 0, 2, 2, 0},
                                     kUnsignedShort, TINYGLTF_TYPE_VEC3);
  const int substituted =
      b.accessor(std::vector<std::uint8_t>{1, 2, 3}, kUnsignedByte, TINYGLTF_TYPE_SCALAR);
  tinygltf::Accessor sparse;
  sparse.bufferView = -1;
  sparse.componentType = kUnsignedShort;
  sparse.type = TINYGLTF_TYPE_VEC3;
  sparse.count = 4;
  sparse.sparse.isSparse = true;
  sparse.sparse.count = 3;
  sparse.sparse.indices = {0, b.model.accessors[std::size_t(substituted)].bufferView,
                           kUnsignedByte};
  sparse.sparse.values = {b.model.accessors[std::size_t(substitutes)].bufferView, 0};
  b.model.accessors.push_back(sparse);
  const int position = int(b.model.accessors.size() - 1);
  const int indices =
      b.accessor(std::vector<std::uint8_t>{0, 1, 3, 0, 3, 2}, kUnsignedByte, TINYGLTF_TYPE_SCALAR);
  const int uvs = b.accessor(std::vector<std::uint8_t>{0, 0, 4, 0, 0, 4, 4, 4}, kUnsignedByte,
                             TINYGLTF_TYPE_VEC2);
  tinygltf::Primitive square = triangles(position, indices, uvs, 0);
  square.attributes["TEXCOORD_1"] = b.accessor(std::vector<std::uint8_t>{0, 0, 2, 0, 0, 2, 2, 2},
                                               kUnsignedByte, TINYGLTF_TYPE_VEC2);
  square.attributes["NORMAL"] =
      b.accessor(std::vector<std::int8_t>{0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127},
                 TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, true);
  b.model.materials.resize(1);
  b.model.textures.resize(1);
  b.model.textures[0].name = "paint";
  b.model.materials[0].pbrMetallicRoughness.baseColorTexture.index = 0;
  tinygltf::Value::Object transform;
  transform["scale"] =
      tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.25), tinygltf::Value(0.125)});
  transform["offset"] =
      tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.0), tinygltf::Value(0.5)});
  b.model.materials[0].pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] =
      tinygltf::Value(transform);
  tinygltf::Value::Object lightmap_transform;
  lightmap_transform["scale"] =
      tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.5), tinygltf::Value(0.5)});
  lightmap_transform["offset"] =
      tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.25), tinygltf::Value(0.0)});
  lightmap_transform["texCoord"] = tinygltf::Value(1);
  b.model.materials[0].occlusionTexture.index = 0;
  b.model.materials[0].occlusionTexture.extensions["KHR_texture_transform"] =
      tinygltf::Value(lightmap_transform);
  b.place({square}, {});
  b.model.nodes[0].scale = {0.5, 0.5, 0.5};
  b.model.extensionsUsed = {"KHR_mesh_quantization", "KHR_texture_transform"};
  b.model.extensionsRequired = {"KHR_mesh_quantization"};
  return b;
}

// Each corner's point and texture coordinate, sorted, and whether every normal is +z.
std::vector<std::array<double, 5>> points_and_uvs(const Mesh& mesh, bool* normals_up = nullptr) {
  const Attributes a(mesh);
  std::vector<std::array<double, 5>> corners;
  if (normals_up) *normals_up = a.normals.has_value();
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    const apps::Point& p = mesh.point(mesh.target(h));
    corners.push_back({p.x(), p.y(), p.z(), (*a.uvs)[h][0], (*a.uvs)[h][1]});
    if (normals_up && (*a.normals)[h] != apps::Kernel::Vector_3(0, 0, 1)) *normals_up = false;
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

// The square's six corners: uv (u, v) / 4 scaled by (1, 1/2) and moved by (0, 1/2) by the
// transform, then v turned (1 - v).
const std::vector<std::array<double, 5>> kSquareCorners = {{0, 0, 0, 0, 0.5}, {0, 0, 0, 0, 0.5},
                                                           {0, 1, 0, 0, 0},   {1, 0, 0, 1, 0.5},
                                                           {1, 1, 0, 1, 0},   {1, 1, 0, 1, 0}};

// Whether every corner's second texture coordinate is what the square's second set gives at its
// vertex (x, y): 2 (x, y) scaled by a half and moved by (1/4, 0), then v turned: (x + 1/4, 1 - y),
// exactly.
bool square_second_uvs_are_exact(const Mesh& mesh) {
  const Attributes a(mesh);
  if (!a.second_uvs) return false;
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    const apps::Point& p = mesh.point(mesh.target(h));
    if ((*a.second_uvs)[h] != Attributes::Uv{p.x() + 0.25, 1 - p.y()}) return false;
  }
  return true;
}

TEST(Gltf, QuantizedSparseAndTransformedAccessorsReadAsTheirValues) {
  const fs::path folder = scratch_folder("gltf_quantized");
  const fs::path in = folder / "square.gltf";
  quantized_square().write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.repairs.empty());
  ASSERT_EQ(mesh.number_of_faces(), 2u);
  bool normals_up = false;
  EXPECT_EQ(points_and_uvs(mesh, &normals_up), kSquareCorners);
  EXPECT_TRUE(normals_up);
  EXPECT_TRUE(square_second_uvs_are_exact(mesh));
  // The transforms are in the coordinates now: a written file has neither them nor the
  // quantization, and the occlusion texture reads the set its transform named.
  ASSERT_TRUE(report.materials.gltf);
  const tinygltf::Material& material = report.materials.gltf->materials.at(0);
  EXPECT_TRUE(material.pbrMetallicRoughness.baseColorTexture.extensions.empty());
  EXPECT_TRUE(material.occlusionTexture.extensions.empty());
  EXPECT_EQ(material.occlusionTexture.texCoord, 1);
  EXPECT_TRUE(report.materials.gltf->extensionsUsed.empty());
  const fs::path out = folder / "out.glb";
  apps::write_mesh_atomically(mesh, out.string(), report.materials);
  const Mesh written =
      apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(points_and_uvs(written), kSquareCorners);
  EXPECT_TRUE(square_second_uvs_are_exact(written));
  EXPECT_EQ(read_text(out).find("KHR_"), std::string::npos);

  // Integer positions are glTF only with the extension; other required extensions are refused.
  const auto cause = [&](const Gltf_builder& b) {
    b.write(folder / "other.gltf");
    try {
      apps::read_gltf((folder / "other.gltf").string(), false);
    } catch (const apps::Io_error& e) {
      return std::string(e.what()).substr((folder / "other.gltf").string().size());
    }
    return std::string();
  };
  Gltf_builder plain = quantized_square();
  plain.model.extensionsUsed = {"KHR_texture_transform"};
  plain.model.extensionsRequired.clear();
  EXPECT_EQ(cause(plain),
            ": mesh 0 primitive 0 POSITION (accessor 2): unsupported element or component type");
  Gltf_builder instanced = quantized_square();
  instanced.model.extensionsUsed.push_back("EXT_mesh_gpu_instancing");
  instanced.model.extensionsRequired.push_back("EXT_mesh_gpu_instancing");
  EXPECT_EQ(cause(instanced),
            ": requires the extension EXT_mesh_gpu_instancing, which this reader does not "
            "support");
  fs::remove_all(folder);
}

// A second set of texture coordinates (a lightmap's) that is an affine function of the position:
// written in every encoding, each set in the accessor its values fit, and read back within a step;
// an OBJ or PLY file holds one set, and the writer says in one line that it left the second out.
TEST(Gltf, ASecondUvSetIsWrittenInEveryEncodingAndObjAndPlySayTheyLeaveItOut) {
  const fs::path folder = scratch_folder("gltf_second_uvs");
  Mesh mesh = test_meshes::flat_grid(4);
  const auto lightmap = [](const apps::Point& p) {
    return Attributes::Uv{p.x() / 8 + 0.25, p.y() / 5};
  };
  test_meshes::paint_corners(
      mesh,
      [](Mesh::Face_index, const apps::Point& p) {
        return Attributes::Uv{p.x(), p.y()};
      },
      false);
  test_meshes::paint_second_uvs(
      mesh, [&](Mesh::Face_index, const apps::Point& p) { return lightmap(p); });
  // Position steps are 4 / 65535: a point moves by half of one at most, its field by a fifth of
  // that.
  const double position_step = 4.0 / 65535;
  for (const auto& [encoding, tolerance, component_type] :
       {std::make_tuple(apps::Gltf_encoding::float32, 1e-7, kFloat),
        std::make_tuple(apps::Gltf_encoding::quantized, 0.5 / 65535 + position_step / 10 + 1e-12,
                        kUnsignedShort),
        std::make_tuple(apps::Gltf_encoding::meshopt, 0.5 / 65535 + position_step / 10 + 1e-12,
                        kUnsignedShort)}) {
    SCOPED_TRACE(int(encoding));
    const fs::path out = folder / "grid.gltf";
    EXPECT_TRUE(apps::write_mesh_atomically(mesh, out.string(), {}, encoding).empty());
    const nlohmann::json gltf = gltf_json(out);
    const nlohmann::json& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
    ASSERT_TRUE(attributes.contains("TEXCOORD_1"));
    const nlohmann::json& accessor = gltf["accessors"][attributes["TEXCOORD_1"].get<std::size_t>()];
    EXPECT_EQ(accessor["componentType"], component_type);
    EXPECT_EQ(accessor.value("normalized", false), component_type != kFloat);
    const Mesh read =
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
    const Attributes a(read);
    ASSERT_TRUE(a.uvs && a.second_uvs);
    EXPECT_EQ(read.number_of_faces(), mesh.number_of_faces());
    for (const auto h : read.halfedges()) {
      if (read.is_border(h)) continue;
      const Attributes::Uv expected = lightmap(read.point(read.target(h)));
      EXPECT_NEAR((*a.second_uvs)[h][0], expected[0], tolerance);
      EXPECT_NEAR((*a.second_uvs)[h][1], expected[1], tolerance);
    }
  }
  for (const auto& [extension, format] :
       {std::make_pair(".obj", "OBJ"), std::make_pair(".ply", "PLY")}) {
    const fs::path out = folder / (std::string("grid") + extension);
    EXPECT_EQ(apps::write_mesh_atomically(mesh, out.string()),
              std::vector<std::string>{
                  out.string() + ": the second texture coordinates (glTF's TEXCOORD_1); " +
                  std::string(format) + " holds one set, written without them"});
    const Attributes a(
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep));
    EXPECT_TRUE(a.uvs && !a.second_uvs);
  }
  fs::remove_all(folder);
}

// A second set that does not match its primitive is bad input, one line, as the first set is.
TEST(Gltf, ABadSecondUvSetIsOneBadInputLine) {
  const fs::path folder = scratch_folder("gltf_bad_second_uvs");
  const fs::path in = folder / "square.gltf";
  const auto cause = [&](Gltf_builder b, const tinygltf::Accessor& second) {
    b.model.accessors.push_back(second);
    b.model.meshes[0].primitives[0].attributes["TEXCOORD_1"] = int(b.model.accessors.size() - 1);
    b.write(in);
    try {
      apps::read_triangle_mesh(in.string(), nullptr, apps::Corner_attribute_reading::keep);
    } catch (const apps::Io_error& e) {
      EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
      return std::string(e.what()).substr(in.string().size());
    }
    return std::string("read");
  };
  const Gltf_builder square = quantized_square();
  const tinygltf::Accessor second = square.model.accessors.at(
      std::size_t(square.model.meshes[0].primitives[0].attributes.at("TEXCOORD_1")));
  tinygltf::Accessor short_one = second;
  short_one.count = 3;
  EXPECT_EQ(cause(square, short_one), ": mesh 0 primitive 0 TEXCOORD_1: 3 values for 4 vertices");
  tinygltf::Accessor scalar = second;
  scalar.type = TINYGLTF_TYPE_SCALAR;
  EXPECT_EQ(cause(square, scalar), ": mesh 0 primitive 0 TEXCOORD_1 (accessor " +
                                       std::to_string(square.model.accessors.size()) +
                                       "): unsupported element or component type");
  tinygltf::Accessor past = second;
  past.count = 5;
  EXPECT_EQ(cause(square, past), ": mesh 0 primitive 0 TEXCOORD_1 (accessor " +
                                     std::to_string(square.model.accessors.size()) +
                                     "): reaches past its bufferView");
  fs::remove_all(folder);
}

// The same square with EXT_meshopt_compression: float positions, u16 texture coordinates
// (normalized) and u16 indices, each view compressed by meshoptimizer's encoders into buffer 0,
// over a fallback buffer of zeros that a reader without the extension would read.
TEST(Gltf, MeshoptCompressedViewsAreDecoded) {
  Gltf_builder b;
  // tinygltf 2.7 writes no bufferView extensions: they are added to the JSON it writes.
  nlohmann::json compressions = nlohmann::json::object();
  const auto compressed_view = [&](const std::vector<unsigned char>& bytes, std::size_t count,
                                   std::size_t stride, const char* mode) {
    std::vector<unsigned char>& data = b.model.buffers[0].data;
    compressions[std::to_string(b.model.bufferViews.size())] = {{"buffer", 0},
                                                                {"byteOffset", data.size()},
                                                                {"byteLength", bytes.size()},
                                                                {"byteStride", stride},
                                                                {"count", count},
                                                                {"mode", mode}};
    data.insert(data.end(), bytes.begin(), bytes.end());
    data.resize((data.size() + 3) / 4 * 4);
    std::vector<unsigned char>& fallback = b.model.buffers[1].data;
    tinygltf::BufferView view;
    view.buffer = 1;
    view.byteOffset = fallback.size();
    view.byteLength = count * stride;
    if (std::string(mode) == "ATTRIBUTES") view.byteStride = stride;
    fallback.resize(fallback.size() + count * stride);
    b.model.bufferViews.push_back(view);
    return int(b.model.bufferViews.size() - 1);
  };
  const auto vertices = [](const auto& values, std::size_t count) {
    const std::size_t size = sizeof(values[0]) * values.size() / count;
    std::vector<unsigned char> bytes(meshopt_encodeVertexBufferBound(count, size));
    bytes.resize(
        meshopt_encodeVertexBuffer(bytes.data(), bytes.size(), values.data(), count, size));
    return bytes;
  };
  b.model.buffers.resize(2);
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<std::uint16_t> uvs = {0, 32768, 65535, 32768, 0, 65535, 65535, 65535};
  const std::vector<unsigned> indices = {0, 1, 3, 0, 3, 2};
  std::vector<unsigned char> index_bytes(meshopt_encodeIndexBufferBound(6, 4));
  index_bytes.resize(
      meshopt_encodeIndexBuffer(index_bytes.data(), index_bytes.size(), indices.data(), 6));
  const auto add_accessor = [&b](int view, int component_type, int type, bool normalized) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component_type;
    a.type = type;
    a.normalized = normalized;
    a.count = type == TINYGLTF_TYPE_SCALAR ? 6 : 4;
    b.model.accessors.push_back(a);
    return int(b.model.accessors.size() - 1);
  };
  const int position = add_accessor(compressed_view(vertices(positions, 4), 4, 12, "ATTRIBUTES"),
                                    kFloat, TINYGLTF_TYPE_VEC3, false);
  const int uv = add_accessor(compressed_view(vertices(uvs, 4), 4, 4, "ATTRIBUTES"), kUnsignedShort,
                              TINYGLTF_TYPE_VEC2, true);
  const int index = add_accessor(compressed_view(index_bytes, 6, 2, "TRIANGLES"), kUnsignedShort,
                                 TINYGLTF_TYPE_SCALAR, false);
  b.place({triangles(position, index, uv, -1)}, {});
  b.model.extensionsUsed = {"EXT_meshopt_compression"};
  b.model.extensionsRequired = {"EXT_meshopt_compression"};
  const fs::path folder = scratch_folder("gltf_meshopt");
  const auto write = [&](const fs::path& path) {
    b.write(path);
    nlohmann::json gltf = nlohmann::json::parse(read_text(path));
    for (const auto& [view, compression] : compressions.items())
      gltf["bufferViews"][std::stoul(view)]["extensions"]["EXT_meshopt_compression"] = compression;
    std::ofstream(path) << gltf.dump();
  };
  write(folder / "square.gltf");
  const Mesh mesh = apps::read_triangle_mesh((folder / "square.gltf").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  // 32768 / 65535 is a hair over a half.
  const double half = 1 - 32768.0 / 65535;
  EXPECT_EQ(points_and_uvs(mesh), (std::vector<std::array<double, 5>>{{0, 0, 0, 0, half},
                                                                      {0, 0, 0, 0, half},
                                                                      {0, 1, 0, 0, 0},
                                                                      {1, 0, 0, 1, half},
                                                                      {1, 1, 0, 1, 0},
                                                                      {1, 1, 0, 1, 0}}));
  // Bytes that do not decode are one bad-input line.
  b.model.buffers[0].data[0] ^= 0xff;
  write(folder / "broken.gltf");
  try {
    apps::read_gltf((folder / "broken.gltf").string(), false);
    ADD_FAILURE() << "read a corrupt compressed view";
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(std::string(e.what()), (folder / "broken.gltf").string() +
                                         ": bufferView 0: its compressed bytes do not decode");
  }
  fs::remove_all(folder);
}

// Files another tool wrote: tests/apps/gltfpack/grid.obj through gltfpack 0.20, quantized (u16
// positions under a scaling node, normalized u16 texture coordinates under a texture transform),
// also meshopt-compressed, and in floats. Each reads as the grid: 128 faces, every point within
// gltfpack's quantization step of (x, y, x y / 64), its texture coordinates of (x, y) / 8, v the
// OBJ's way up, and no seam but the border.
TEST(Gltf, GltfpackOutputsReadAsTheGrid) {
  const fs::path folder = fs::path(CGAL_POLICIES_SOURCE_DIR) / "tests" / "apps" / "gltfpack";
  for (const std::string name : {"grid_quantized.glb", "grid_meshopt.glb", "grid_float.glb"}) {
    SCOPED_TRACE(name);
    apps::Read_report report;
    const Mesh mesh = apps::read_triangle_mesh((folder / name).string(), &report,
                                               apps::Corner_attribute_reading::keep);
    EXPECT_TRUE(report.repairs.empty());
    EXPECT_EQ(mesh.number_of_faces(), 128u);
    EXPECT_EQ(mesh.number_of_vertices(), 81u);
    EXPECT_EQ(report.materials.names, std::vector<std::string>{"grid"});
    const Attributes a(mesh);
    ASSERT_TRUE(a.uvs.has_value());
    double point_error = 0, uv_error = 0;
    for (const auto h : mesh.halfedges()) {
      if (mesh.is_border(h)) continue;
      const apps::Point& p = mesh.point(mesh.target(h));
      const double x = std::round(p.x()), y = std::round(p.y());
      point_error = std::max(
          {point_error, std::abs(p.x() - x), std::abs(p.y() - y), std::abs(p.z() - x * y / 64)});
      uv_error =
          std::max({uv_error, std::abs((*a.uvs)[h][0] - x / 8), std::abs((*a.uvs)[h][1] - y / 8)});
    }
    EXPECT_LE(point_error, 8.0 / 16383);     // a step of u16 positions over the grid's side
    EXPECT_LE(uv_error, 16.003664 / 65535);  // a step of the transformed u16 coordinates
    EXPECT_EQ(seam_edge_count(mesh), 32u);   // the border's 32 edges
  }
}

// A file another tool wrote with KHR_draco_mesh_compression: tests/apps/draco/bob.glb (bob at
// 2,000 faces, written by simplify) through gltf-pipeline 4.3.1 -d, its positions quantized to 14
// bits and its texture coordinates to 12 (tests/apps/draco/README.md). Draco orders the vertices
// and triangles its own way; each decoded vertex matched to its nearest source vertex, the file
// reads as its source: the same faces, every point within half a quantization step of its source
// point, every corner's texture coordinates within half a step of its source corner's.
TEST(Gltf, DracoCompressedPrimitivesReadAsTheirSource) {
  const fs::path folder = fs::path(CGAL_POLICIES_SOURCE_DIR) / "tests" / "apps" / "draco";
  apps::Read_report source_report, draco_report;
  const Mesh source = apps::read_triangle_mesh((folder / "bob.glb").string(), &source_report,
                                               apps::Corner_attribute_reading::keep);
  const Mesh draco = apps::read_triangle_mesh((folder / "bob_draco.glb").string(), &draco_report,
                                              apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(draco_report.repairs.empty());
  EXPECT_EQ(source.number_of_faces(), 2000u);
  ASSERT_EQ(draco.number_of_faces(), source.number_of_faces());
  ASSERT_EQ(draco.number_of_vertices(), source.number_of_vertices());
  EXPECT_EQ(draco_report.materials.names, source_report.materials.names);
  const Attributes a(source), b(draco);
  ASSERT_TRUE(a.uvs && b.uvs && a.normals && b.normals);

  // Draco's step: the values' largest extent over 2^bits - 1; a value is rounded to the nearest
  // step, then stored as a float.
  const auto half_step = [](double lowest, double highest, int bits) {
    return (highest - lowest) / ((1 << bits) - 1) / 2 + 1e-6;
  };
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(source);
  const double position_tolerance = half_step(
      0, std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}), 14);
  double uv_lowest = 1e300, uv_highest = -1e300;
  for (const auto h : source.halfedges())
    if (!source.is_border(h))
      for (double c : (*a.uvs)[h])
        uv_lowest = std::min(uv_lowest, c), uv_highest = std::max(uv_highest, c);
  const double uv_tolerance = half_step(uv_lowest, uv_highest, 12);

  auto [match, point_error] = nearest_vertices(draco, source);
  std::set<Mesh::Vertex_index> matched;
  for (const auto& pair : match) matched.insert(pair.second);
  EXPECT_EQ(matched.size(), source.number_of_vertices());  // one decoded vertex each
  EXPECT_LE(point_error, position_tolerance);

  std::set<Mesh::Face_index> faces;
  double uv_error = 0;
  for (const auto h : draco.halfedges()) {
    if (draco.is_border(h)) continue;
    const auto g = source.halfedge(match[draco.source(h)], match[draco.target(h)]);
    ASSERT_TRUE(g != Mesh::null_halfedge() && !source.is_border(g));
    faces.insert(source.face(g));
    for (int k : {0, 1}) uv_error = std::max(uv_error, std::abs((*b.uvs)[h][k] - (*a.uvs)[g][k]));
  }
  EXPECT_EQ(faces.size(), source.number_of_faces());  // every source face, each once
  EXPECT_LE(uv_error, uv_tolerance);
}

// A node's world transform: a child turned a quarter about z and mirrored in x, under a parent
// moved up by 5. The mirror turns the winding, so the reader turns the triangle back to face its
// normal, which the transform leaves at +z.
TEST(Gltf, NodeTransformsPlaceTurnAndMirror) {
  const fs::path folder = scratch_folder("gltf_nodes");
  Gltf_builder b;
  const int position =
      b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  tinygltf::Primitive primitive = triangles(position, -1, -1, -1);
  primitive.attributes["NORMAL"] =
      b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, TINYGLTF_TYPE_VEC3);
  b.place({primitive}, {0, 0, 5});
  b.model.nodes[0].mesh = -1;
  b.model.nodes[0].children = {1};
  b.model.nodes.emplace_back();
  b.model.nodes[1].mesh = 0;
  b.model.nodes[1].rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  b.model.nodes[1].scale = {-1, 1, 1};
  b.write(folder / "turned.gltf");
  const Mesh mesh = apps::read_triangle_mesh((folder / "turned.gltf").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  ASSERT_EQ(mesh.number_of_faces(), 1u);
  // The quarter turn's sines and cosines are rounded: the points snapped to a 1e-12 grid.
  const auto snap = [](double x) { return std::round(x * 1e12) / 1e12; };
  std::vector<std::array<double, 3>> points;
  for (const auto v : mesh.vertices())
    points.push_back({snap(mesh.point(v).x()), snap(mesh.point(v).y()), snap(mesh.point(v).z())});
  std::sort(points.begin(), points.end());
  EXPECT_EQ(points, (std::vector<std::array<double, 3>>{{-1, 0, 5}, {0, -1, 5}, {0, 0, 5}}));
  const auto face_normal =
      CGAL::Polygon_mesh_processing::compute_face_normal(*mesh.faces().begin(), mesh);
  EXPECT_NEAR(face_normal.z(), 1, 1e-15);
  const Attributes a(mesh);
  ASSERT_TRUE(a.normals);
  for (const auto h : mesh.halfedges())
    if (!mesh.is_border(h)) {
      EXPECT_NEAR((*a.normals)[h].x(), 0, 1e-15);
      EXPECT_NEAR((*a.normals)[h].y(), 0, 1e-15);
      EXPECT_NEAR((*a.normals)[h].z(), 1, 1e-15);
    }
  fs::remove_all(folder);
}

// Three painted cubes of 192, 48 and 12 faces (painted_cube(4), (2), (1)), side by side along x,
// written as one chain by write_lod_chain_atomically read back as three levels, finest first, each
// with its faces and corners: through float as float32 (.glb), within a step as quantized (.gltf;
// each level's node moves its positions from its own box's corner, so the node standing in for
// another must keep its own transform). read_triangle_mesh, which does not follow MSFT_lod, reads
// the finest level alone.
TEST(Gltf, ALodChainReadsBackAsItsLevelsWithTheirCorners) {
  const fs::path folder = scratch_folder("gltf_lod_chain");
  const auto moved_along_x = [](Mesh mesh, double x) {
    for (const auto v : mesh.vertices())
      mesh.point(v) = mesh.point(v) + apps::Kernel::Vector_3(x, 0, 0);
    return mesh;
  };
  const std::vector<Mesh> cubes = {painted_cube(4), moved_along_x(painted_cube(2), 5),
                                   moved_along_x(painted_cube(1), 10)};
  const std::vector<std::size_t> faces = {192, 48, 12};
  const std::vector<apps::Lod_level> levels = {{&cubes[0], 0.5}, {&cubes[1], 0.2}, {&cubes[2], 0}};
  const apps::Material_references names{{}, {"even", "odd"}, nullptr, {}};
  // Every cube spans 4 on each axis: one step of the quantized positions.
  const double step = 4.0 / 65535;
  for (const auto& [name, encoding] :
       {std::make_pair("chain.glb", apps::Gltf_encoding::float32),
        std::make_pair("chain.gltf", apps::Gltf_encoding::quantized)}) {
    SCOPED_TRACE(name);
    const std::string out = (folder / name).string();
    apps::write_lod_chain_atomically(levels, out, names, encoding);
    apps::Read_report report;
    const std::vector<Mesh> read =
        apps::read_lod_chain(out, {apps::Corner_attribute_reading::keep, 1, {}}, &report);
    ASSERT_EQ(read.size(), 3u);
    EXPECT_TRUE(report.repairs.empty());
    EXPECT_EQ(report.materials.names, names.names);
    for (std::size_t k = 0; k < read.size(); ++k) {
      SCOPED_TRACE("level " + std::to_string(k));
      EXPECT_EQ(read[k].number_of_faces(), faces[k]);
      if (encoding == apps::Gltf_encoding::float32)
        EXPECT_EQ(sorted(face_corners(read[k])), sorted(through_float(face_corners(cubes[k]))));
      else  // texture coordinates past [-1, 1] stay float: u runs up to 6
        expect_within_steps(cubes[k], read[k], step, 6.0 / (1 << 24));
    }
    EXPECT_EQ(apps::read_triangle_mesh(out).number_of_faces(), faces[0]);
  }
  fs::remove_all(folder);
}

// A glTF file without MSFT_lod, and a file of any other format, is one level.
TEST(Gltf, AFileWithoutMsftLodIsOneLevel) {
  const fs::path folder = scratch_folder("gltf_one_level");
  const Mesh cube = painted_cube(2);
  for (const std::string name : {"cube.glb", "cube.obj"}) {
    SCOPED_TRACE(name);
    apps::write_mesh_atomically(cube, (folder / name).string());
    const std::vector<Mesh> read = apps::read_lod_chain((folder / name).string());
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(read[0].number_of_faces(), 48u);
  }
  fs::remove_all(folder);
}

// Each bad MSFT_lod of a three-level chain is one bad-input line naming the file and the cause;
// read_triangle_mesh, which does not follow the extension, still reads the finest level.
TEST(Gltf, BadMsftLodReferencesAreOneBadInputLine) {
  const fs::path folder = scratch_folder("gltf_bad_lod");
  const std::vector<Mesh> cubes = {painted_cube(4), painted_cube(2), painted_cube(1)};
  apps::write_lod_chain_atomically({{&cubes[0], 0.5}, {&cubes[1], 0.2}, {&cubes[2], 0}},
                                   (folder / "chain.gltf").string());
  const nlohmann::json chain = gltf_json(folder / "chain.gltf");
  ASSERT_EQ(chain["nodes"][0]["extensions"]["MSFT_lod"]["ids"], std::vector<int>({1, 2}));
  const std::string bad = (folder / "bad.gltf").string();
  struct Bad_lod {
    nlohmann::json lod;
    std::string cause;
  };
  for (const Bad_lod& c : {
           Bad_lod{{{"ids", {1, 7}}}, "node 0's MSFT_lod names node 7, which does not exist"},
           Bad_lod{{{"ids", {-1}}}, "node 0's MSFT_lod names node -1, which does not exist"},
           Bad_lod{{{"ids", {1.5}}}, "node 0's MSFT_lod names node 1.5, which does not exist"},
           Bad_lod{{{"ids", {1, 3}}}, "node 0's MSFT_lod names node 3, which has no mesh"},
           Bad_lod{{{"ids", {"1"}}},
                   "node 0's MSFT_lod names a node by something other than a number"},
           Bad_lod{{{"ids", 1}}, "node 0's MSFT_lod has no array of node indices (ids)"},
           Bad_lod{nlohmann::json::object(),
                   "node 0's MSFT_lod has no array of node indices (ids)"},
       }) {
    SCOPED_TRACE(c.cause);
    nlohmann::json edited = chain;
    edited["nodes"].push_back(nlohmann::json::object());  // node 3, without a mesh
    edited["nodes"][0]["extensions"]["MSFT_lod"] = c.lod;
    std::ofstream(bad) << edited.dump();
    try {
      apps::read_lod_chain(bad);
      ADD_FAILURE() << "read";
    } catch (const apps::Io_error& e) {
      EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
      EXPECT_EQ(std::string(e.what()), bad + ": " + c.cause);
    }
    EXPECT_EQ(apps::read_triangle_mesh(bad).number_of_faces(), 192u);
  }
  fs::remove_all(folder);
}

// ---------------------------------------------------------------------------------------------
// Skins: JOINTS_0 and WEIGHTS_0 as corner values, the skeleton passed through.

using gltf_fixtures::skinned_strip;

// The weight of `joint` in `skin`: 0 when it has none.
double weight_of(const Attributes::Skin_influences& skin, std::uint16_t joint) {
  double weight = 0;
  for (int i = 0; i < 4; ++i)
    if (skin.joints[i] == joint) weight += skin.weights[i];
  return weight;
}

// Whether every corner of `mesh` has the strip's influences at its point, within `tolerance`:
// joint 0 weighing 1 - x / 4, joint 1 x / 4, the heavier first.
void expect_strip_influences(const Mesh& mesh, double tolerance) {
  const Attributes a(mesh);
  ASSERT_TRUE(a.skins);
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    const Attributes::Skin_influences& skin = (*a.skins)[h];
    const double x = mesh.point(mesh.target(h)).x();
    EXPECT_NEAR(weight_of(skin, 0), 1 - x / 4, tolerance);
    EXPECT_NEAR(weight_of(skin, 1), x / 4, tolerance);
    EXPECT_GE(skin.weights[0], skin.weights[1]);
    EXPECT_EQ(skin.weights[2] + skin.weights[3], 0);
  }
}

// The skinned strip reads where its mesh is, untransformed (glTF ignores the skinned node's move
// by 100), each corner with its influences exactly. Written in every encoding, the file holds the
// skeleton: the joints by name with their transforms and hierarchy, the skin with its skeleton and
// inverse bind matrices, the mesh's node skinned at the scene's root without a transform (its
// positions stay float when quantized), JOINTS_0 u8 and WEIGHTS_0 float, or normalized u16 when
// quantized; read back, every influence within a step. A chain of levels of detail skins every
// level's node. OBJ and PLY hold no skin, which the writer says in one line.
TEST(Gltf, ASkinnedMeshKeepsItsInfluencesAndItsSkeleton) {
  const fs::path folder = scratch_folder("gltf_skin");
  const fs::path in = folder / "strip.gltf";
  skinned_strip().write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.left_out.empty());
  EXPECT_EQ(mesh.number_of_faces(), 8u);
  for (const auto v : mesh.vertices()) {
    EXPECT_GE(mesh.point(v).x(), 0);
    EXPECT_LE(mesh.point(v).x(), 4);
  }
  expect_strip_influences(mesh, 0);
  ASSERT_TRUE(report.materials.gltf);
  for (const auto& [encoding, weight_type, tolerance] :
       {std::make_tuple(apps::Gltf_encoding::float32, kFloat, 1e-7),
        std::make_tuple(apps::Gltf_encoding::quantized, kUnsignedShort, 1.0 / 65535),
        std::make_tuple(apps::Gltf_encoding::meshopt, kUnsignedShort, 1.0 / 65535)}) {
    SCOPED_TRACE(int(encoding));
    const fs::path out = folder / "out.gltf";
    EXPECT_TRUE(
        apps::write_mesh_atomically(mesh, out.string(), report.materials, encoding).empty());
    const nlohmann::json gltf = gltf_json(out);
    ASSERT_EQ(gltf["skins"].size(), 1u);
    const nlohmann::json& skin = gltf["skins"][0];
    ASSERT_EQ(skin["joints"].size(), 2u);
    const nlohmann::json& root = gltf["nodes"][skin["joints"][0].get<std::size_t>()];
    const nlohmann::json& tip = gltf["nodes"][skin["joints"][1].get<std::size_t>()];
    EXPECT_EQ(root["name"], "root");
    EXPECT_EQ(tip["name"], "tip");
    EXPECT_EQ(root["children"], nlohmann::json::array({skin["joints"][1]}));
    EXPECT_EQ(tip["translation"], nlohmann::json::array({4.0, 0.0, 0.0}));
    EXPECT_EQ(skin["skeleton"], skin["joints"][0]);
    EXPECT_EQ(gltf["scenes"][0]["nodes"], nlohmann::json::array({0, skin["joints"][0]}));
    const nlohmann::json& matrices =
        gltf["accessors"][skin["inverseBindMatrices"].get<std::size_t>()];
    EXPECT_EQ(matrices["type"], "MAT4");
    EXPECT_EQ(matrices["count"], 2);
    const nlohmann::json& node = gltf["nodes"][0];
    EXPECT_EQ(node["skin"], 0);
    EXPECT_FALSE(node.contains("translation") || node.contains("scale") || node.contains("matrix"));
    const nlohmann::json& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
    EXPECT_EQ(gltf["accessors"][attributes["POSITION"].get<std::size_t>()]["componentType"],
              kFloat);
    EXPECT_EQ(gltf["accessors"][attributes["JOINTS_0"].get<std::size_t>()]["componentType"],
              kUnsignedByte);
    const nlohmann::json& weights = gltf["accessors"][attributes["WEIGHTS_0"].get<std::size_t>()];
    EXPECT_EQ(weights["componentType"], weight_type);
    EXPECT_EQ(weights.value("normalized", false), weight_type != kFloat);
    apps::Read_report read_report;
    const Mesh read =
        apps::read_triangle_mesh(out.string(), &read_report, apps::Corner_attribute_reading::keep);
    EXPECT_TRUE(read_report.left_out.empty());
    EXPECT_EQ(read.number_of_faces(), 8u);
    expect_strip_influences(read, tolerance);
    // Two levels, each node skinned by the one skin, read back as two skinned levels.
    const fs::path chain = folder / "chain.glb";
    EXPECT_TRUE(apps::write_lod_chain_atomically({{&mesh, 0.5}, {&read, 0}}, chain.string(),
                                                 report.materials, encoding)
                    .empty());
    const nlohmann::json chain_json = gltf_json(chain);
    EXPECT_EQ(chain_json["nodes"][0]["skin"], 0);
    EXPECT_EQ(chain_json["nodes"][1]["skin"], 0);
    const std::vector<Mesh> levels =
        apps::read_lod_chain(chain.string(), {apps::Corner_attribute_reading::keep, 1, {}});
    ASSERT_EQ(levels.size(), 2u);
    for (const Mesh& level : levels) expect_strip_influences(level, tolerance + 1.0 / 65535);
  }
  for (const auto& [extension, format] :
       {std::make_pair(".obj", "OBJ"), std::make_pair(".ply", "PLY")}) {
    const fs::path out = folder / (std::string("strip") + extension);
    EXPECT_EQ(
        apps::write_mesh_atomically(mesh, out.string()),
        std::vector<std::string>{out.string() + ": the skin (glTF's JOINTS_0 and WEIGHTS_0); " +
                                 std::string(format) + " holds none, written without it"});
  }
  fs::remove_all(folder);
}

// The floats of accessor `index` of the looks a reader kept: each in a view of its own in buffer 0.
std::vector<float> kept_floats(const tinygltf::Model& looks, int index) {
  const tinygltf::Accessor& accessor = looks.accessors[std::size_t(index)];
  const tinygltf::BufferView& view = looks.bufferViews[std::size_t(accessor.bufferView)];
  std::vector<float> values(view.byteLength / sizeof(float));
  std::memcpy(values.data(), looks.buffers[0].data.data() + view.byteOffset, view.byteLength);
  return values;
}

tinygltf::AnimationSampler animation_sampler(int input, int output, const std::string& kind) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = kind;
  return sampler;
}

tinygltf::AnimationChannel animation_channel(int sampler, int node, const std::string& path) {
  tinygltf::AnimationChannel channel;
  channel.sampler = sampler;
  channel.target_node = node;
  channel.target_path = path;
  return channel;
}

// A skeleton's animations travel with it: each channel that moves one of its nodes, with its
// sampler's times (one copy for the samplers that share them, their bounds written, as glTF asks)
// and values, in every encoding, read back the same. A channel of another node, whose times do
// not increase, without a sampler, or whose values do not fit its path is left out, one line per
// animation, and the mesh is read; an animation left without a channel is not written. Morph
// targets, and the animations of a file whose meshes are not skinned, are left out with one line
// each.
TEST(Gltf, TheSkeletonsAnimationsTravelWithIt) {
  const fs::path folder = scratch_folder("gltf_animation");
  const fs::path in = folder / "strip.gltf";
  Gltf_builder b = skinned_strip();
  const std::vector<float> turn = {0, 0, 0, 1, 0, 0, 0.6f, 0.8f};
  const int times = b.accessor(std::vector<float>{0, 1}, kFloat, TINYGLTF_TYPE_SCALAR);
  const int turns = b.accessor(turn, kFloat, TINYGLTF_TYPE_VEC4);
  const int moves = b.accessor(std::vector<float>{0, 0, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  const int stuck = b.accessor(std::vector<float>{0, 0}, kFloat, TINYGLTF_TYPE_SCALAR);
  tinygltf::Animation bend;
  bend.name = "bend";
  bend.samplers = {animation_sampler(times, turns, "LINEAR"),
                   animation_sampler(times, moves, "STEP"),
                   animation_sampler(stuck, moves, "LINEAR")};
  // Kept: the tip's turn, the root's steps. Left out: a move of the mesh's node, times that do
  // not increase, a sampler that is not there, values of a move for a turn.
  bend.channels = {animation_channel(0, 2, "rotation"),    animation_channel(1, 0, "translation"),
                   animation_channel(2, 1, "translation"), animation_channel(1, 1, "translation"),
                   animation_channel(7, 2, "rotation"),    animation_channel(1, 2, "rotation")};
  tinygltf::Animation slide;
  slide.name = "slide";
  slide.samplers = {animation_sampler(times, moves, "LINEAR")};
  slide.channels = {animation_channel(0, 0, "translation")};
  b.model.animations = {bend, slide};
  b.write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  const std::string why =
      " channels left out (they move nodes other than the skeleton's, or morph target weights, or "
      "break glTF's rules)";
  EXPECT_EQ(report.left_out,
            (std::vector<std::string>{in.string() + ": animation 0 ('bend'): 4 of 6" + why,
                                      in.string() + ": animation 1 ('slide'): 1 of 1" + why}));
  for (const apps::Gltf_encoding encoding :
       {apps::Gltf_encoding::float32, apps::Gltf_encoding::quantized,
        apps::Gltf_encoding::meshopt}) {
    SCOPED_TRACE(int(encoding));
    const fs::path out = folder / "out.glb";
    EXPECT_TRUE(
        apps::write_mesh_atomically(mesh, out.string(), report.materials, encoding).empty());
    const nlohmann::json gltf = gltf_json(out);
    ASSERT_EQ(gltf["animations"].size(), 1u);
    const nlohmann::json& animation = gltf["animations"][0];
    EXPECT_EQ(animation["name"], "bend");
    ASSERT_EQ(animation["channels"].size(), 2u);
    ASSERT_EQ(animation["samplers"].size(), 2u);
    const auto node_name = [&](std::size_t channel) {
      return gltf["nodes"][animation["channels"][channel]["target"]["node"].get<std::size_t>()]
                 ["name"];
    };
    EXPECT_EQ(node_name(0), "tip");
    EXPECT_EQ(animation["channels"][0]["target"]["path"], "rotation");
    EXPECT_EQ(node_name(1), "root");
    EXPECT_EQ(animation["channels"][1]["target"]["path"], "translation");
    const nlohmann::json& turning = animation["samplers"][0];
    EXPECT_EQ(turning["interpolation"], "LINEAR");
    EXPECT_EQ(animation["samplers"][1]["interpolation"], "STEP");
    // Both samplers read the one copy of their times.
    EXPECT_EQ(animation["samplers"][1]["input"], turning["input"]);
    const nlohmann::json& input = gltf["accessors"][turning["input"].get<std::size_t>()];
    EXPECT_EQ(input["min"], nlohmann::json::array({0.0}));
    EXPECT_EQ(input["max"], nlohmann::json::array({1.0}));
    apps::Read_report read_report;
    apps::read_triangle_mesh(out.string(), &read_report, apps::Corner_attribute_reading::keep);
    EXPECT_TRUE(read_report.left_out.empty());
    ASSERT_TRUE(read_report.materials.gltf);
    const tinygltf::Model& looks = *read_report.materials.gltf;
    ASSERT_EQ(looks.animations.size(), 1u);
    ASSERT_EQ(looks.animations[0].samplers.size(), 2u);
    const tinygltf::AnimationSampler& kept = looks.animations[0].samplers[0];
    EXPECT_EQ(kept_floats(looks, kept.input), (std::vector<float>{0, 1}));
    EXPECT_EQ(kept_floats(looks, kept.output), turn);
    EXPECT_EQ(kept_floats(looks, looks.animations[0].samplers[1].output),
              (std::vector<float>{0, 0, 0, 0, 1, 0}));
  }
  Gltf_builder square = two_primitive_square();
  square.model.meshes[0].primitives[0].targets = {
      {{"POSITION", square.accessor(std::vector<float>(9, 0), kFloat, TINYGLTF_TYPE_VEC3)}}};
  square.model.animations = {slide};
  square.model.animations[0].samplers[0] = animation_sampler(
      square.accessor(std::vector<float>{0, 1}, kFloat, TINYGLTF_TYPE_SCALAR),
      square.accessor(std::vector<float>{0, 0, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3), "LINEAR");
  const fs::path morphed = folder / "square.gltf";
  square.write(morphed);
  apps::Read_report square_report;
  apps::read_triangle_mesh(morphed.string(), &square_report, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(
      square_report.left_out,
      (std::vector<std::string>{
          morphed.string() + ": mesh 0: its morph targets are left out; its base shape is read",
          morphed.string() + ": its 1 animation is left out: the meshes are written where "
                             "their nodes place them"}));
  fs::remove_all(folder);
}

// More than four influences (JOINTS_1 and WEIGHTS_1) are merged: each vertex keeps its four
// heaviest joints, ties to the lower joint, renormalised. Normalized u8 weights read as their
// values.
TEST(Gltf, MoreThanFourInfluencesKeepTheFourHeaviest) {
  const fs::path folder = scratch_folder("gltf_skin_eight");
  Gltf_builder b = skinned_strip();
  b.model.nodes.resize(7);
  b.model.nodes[1].children = {2, 3, 4, 5, 6};
  for (int n = 3; n < 7; ++n) b.model.nodes[std::size_t(n)].name = "joint " + std::to_string(n);
  b.model.skins[0].joints = {1, 2, 3, 4, 5, 6};
  b.model.skins[0].inverseBindMatrices = -1;
  tinygltf::Primitive& strip = b.model.meshes[0].primitives[0];
  std::vector<std::uint8_t> first_joints, second_joints, first_weights, second_weights;
  for (int v = 0; v < 10; ++v) {
    first_joints.insert(first_joints.end(), {0, 1, 2, 3});
    first_weights.insert(first_weights.end(), {102, 51, 52, 0});  // of 255 in all
    second_joints.insert(second_joints.end(), {5, 4, 0, 0});
    second_weights.insert(second_weights.end(), {25, 25, 0, 0});
  }
  const auto add = [&b, &strip](const char* name, const std::vector<std::uint8_t>& values,
                                bool normalized) {
    strip.attributes[name] = b.accessor(values, kUnsignedByte, TINYGLTF_TYPE_VEC4, normalized);
  };
  add("JOINTS_0", first_joints, false);
  add("WEIGHTS_0", first_weights, true);
  add("JOINTS_1", second_joints, false);
  add("WEIGHTS_1", second_weights, true);
  b.write(folder / "eight.gltf");
  const Mesh mesh = apps::read_triangle_mesh((folder / "eight.gltf").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  const Attributes a(mesh);
  ASSERT_TRUE(a.skins);
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    // Joints 4 and 5 tie at 25 / 255: 4 is kept, and the four weights' sum of 230 / 255 becomes 1.
    EXPECT_EQ((*a.skins)[h].joints, (std::array<std::uint16_t, 4>{0, 2, 1, 4}));
    const std::array<double, 4> expected = {102, 52, 51, 25};
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR((*a.skins)[h].weights[i], expected[i] / 230, 1e-15);
  }
  fs::remove_all(folder);
}

// The JSON of `mesh` written as glTF to `out`, which must bring no warning.
nlohmann::json written_gltf(const Mesh& mesh, const fs::path& out,
                            const apps::Material_references& materials) {
  EXPECT_TRUE(apps::write_mesh_atomically(mesh, out.string(), materials).empty());
  return gltf_json(out);
}

// The skinned strip and a second strip, 5 above it, of a mesh of its own, under a node moved by
// 200 (which glTF ignores), skinned by skin 1: joints `joints` with inverse bind matrices
// `matrices` (a copy of skin 0's when empty).
Gltf_builder strips_of_two_skins(const std::vector<int>& joints, std::vector<float> matrices) {
  Gltf_builder b = skinned_strip();
  std::vector<float> points;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 1; ++y) points.insert(points.end(), {float(x), float(y + 5), 0});
  tinygltf::Mesh upper = b.model.meshes[0];
  upper.primitives[0].attributes["POSITION"] = b.accessor(points, kFloat, TINYGLTF_TYPE_VEC3);
  b.model.meshes.push_back(upper);
  b.model.nodes.resize(6);
  b.model.nodes[3].name = "root 2";
  b.model.nodes[3].children = {4};
  b.model.nodes[4].name = "tip 2";
  b.model.nodes[4].translation = {4, 0, 0};
  b.model.nodes[5].mesh = 1;
  b.model.nodes[5].skin = 1;
  b.model.nodes[5].translation = {200, 0, 0};
  b.model.scenes[0].nodes = {0, 1, 3, 5};
  tinygltf::Skin second = b.model.skins[0];
  second.joints = joints;
  second.skeleton = joints[0];
  if (!matrices.empty())
    second.inverseBindMatrices = b.accessor(matrices, kFloat, TINYGLTF_TYPE_MAT4);
  b.model.skins.push_back(second);
  return b;
}

// Meshes skinned by several skins share one: the skins' joints in order, each joint once, the
// first skin's name, and a skeleton only when they share it. Two skeletons: the upper strip's
// influences name joints 2 and 3, written as one skin of four joints and four inverse bind
// matrices, read back the same. A joint that both skins bind alike (the tip) is one joint.
TEST(Gltf, MeshesOfSeveralSkinsShareOneMergedSkin) {
  const fs::path folder = scratch_folder("gltf_two_skins");
  const fs::path in = folder / "strips.gltf";
  strips_of_two_skins({3, 4}, {}).write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.left_out.empty());
  EXPECT_EQ(mesh.number_of_faces(), 16u);
  // Each strip's corners weigh its own skeleton's joints as the strip weighs joints 0 and 1.
  const auto expect_influences = [](const Mesh& m, double tolerance) {
    const Attributes a(m);
    ASSERT_TRUE(a.skins);
    for (const auto h : m.halfedges()) {
      if (m.is_border(h)) continue;
      const auto& p = m.point(m.target(h));
      const std::uint16_t root = p.y() > 2 ? 2 : 0;
      EXPECT_LE(p.x(), 4);  // untransformed
      EXPECT_NEAR(weight_of((*a.skins)[h], root), 1 - p.x() / 4, tolerance);
      EXPECT_NEAR(weight_of((*a.skins)[h], std::uint16_t(root + 1)), p.x() / 4, tolerance);
    }
  };
  expect_influences(mesh, 0);
  const fs::path out = folder / "out.gltf";
  const nlohmann::json gltf = written_gltf(mesh, out, report.materials);
  ASSERT_EQ(gltf["skins"].size(), 1u);
  const nlohmann::json& skin = gltf["skins"][0];
  ASSERT_EQ(skin["joints"].size(), 4u);
  std::vector<std::string> names;
  for (const auto& joint : skin["joints"])
    names.push_back(gltf["nodes"][joint.get<std::size_t>()]["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"root", "tip", "root 2", "tip 2"}));
  EXPECT_FALSE(skin.contains("skeleton"));
  EXPECT_EQ(gltf["accessors"][skin["inverseBindMatrices"].get<std::size_t>()]["count"], 4);
  apps::Read_report read_report;
  const Mesh read =
      apps::read_triangle_mesh(out.string(), &read_report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(read_report.left_out.empty());
  expect_influences(read, 1e-7);

  // Skin 1 binds the tip as skin 0 does, then the second root: three joints in all.
  strips_of_two_skins({2, 3}, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -4, 0, 0, 1,  // the tip's
                               1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1})
      .write(in);
  const Mesh shared =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  const Attributes a(shared);
  ASSERT_TRUE(a.skins);
  for (const auto h : shared.halfedges()) {
    if (shared.is_border(h) || shared.point(shared.target(h)).y() < 2) continue;
    const double x = shared.point(shared.target(h)).x();
    EXPECT_NEAR(weight_of((*a.skins)[h], 1), 1 - x / 4, 0);  // skin 1's joint 0: the tip
    EXPECT_NEAR(weight_of((*a.skins)[h], 2), x / 4, 0);      // its joint 1: the second root
  }
  EXPECT_EQ(written_gltf(shared, out, report.materials)["skins"][0]["joints"].size(), 3u);
  fs::remove_all(folder);
}

// A mesh without a skin beside a skinned one rides on its own node: the strip again under a node
// moved by 200 and turned a quarter about z, its points where the node puts them, each weighing 1
// on the node, a joint of the skin bound where the node is (its inverse transform).
TEST(Gltf, AnUnskinnedMeshBesideASkinnedOneRidesOnItsNode) {
  const fs::path folder = scratch_folder("gltf_rigid");
  const fs::path in = folder / "strips.gltf";
  Gltf_builder b = skinned_strip();
  b.model.nodes.emplace_back();
  b.model.nodes.back().name = "prop";
  b.model.nodes.back().mesh = 0;
  b.model.nodes.back().translation = {200, 0, 0};
  b.model.nodes.back().rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  b.model.scenes[0].nodes.push_back(3);
  b.write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.left_out.empty());
  EXPECT_EQ(mesh.number_of_faces(), 16u);
  const Attributes a(mesh);
  ASSERT_TRUE(a.skins);
  for (const auto h : mesh.halfedges()) {
    if (mesh.is_border(h)) continue;
    const auto& p = mesh.point(mesh.target(h));
    if (p.x() < 100) continue;  // the skinned strip
    // The quarter turn takes (x, y) to (-y, x).
    EXPECT_GE(p.x(), 199 - 1e-12);
    EXPECT_LE(p.x(), 200 + 1e-12);
    EXPECT_GE(p.y(), -1e-12);
    EXPECT_LE(p.y(), 4 + 1e-12);
    EXPECT_EQ(weight_of((*a.skins)[h], 2), 1);
  }
  const nlohmann::json gltf = written_gltf(mesh, folder / "out.gltf", report.materials);
  ASSERT_EQ(gltf["skins"].size(), 1u);
  const nlohmann::json& skin = gltf["skins"][0];
  ASSERT_EQ(skin["joints"].size(), 3u);
  EXPECT_EQ(gltf["nodes"][skin["joints"][2].get<std::size_t>()]["name"], "prop");
  EXPECT_EQ(gltf["nodes"][skin["joints"][2].get<std::size_t>()]["translation"],
            nlohmann::json::array({200.0, 0.0, 0.0}));
  ASSERT_TRUE(report.materials.gltf);
  const tinygltf::Model& looks = *report.materials.gltf;
  const std::vector<float> matrices = kept_floats(looks, looks.skins[0].inverseBindMatrices);
  ASSERT_EQ(matrices.size(), 48u);
  // The inverse of the turn then the move: (x, y) to (y, 200 - x), as columns.
  const std::vector<float> prop(matrices.begin() + 32, matrices.end());
  const std::vector<float> expected = {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 200, 0, 1};
  for (std::size_t i = 0; i < 16; ++i) EXPECT_NEAR(prop[i], expected[i], 1e-5) << i;
  fs::remove_all(folder);
}

// A skin the reader cannot carry as one set of influences is left out, in one line, and every mesh
// is placed by its node's transform, the skinned one's too, as before: two skins that bind a joint
// differently, an unskinned mesh whose node's transform cannot be undone, a skinned primitive
// without weights. A joint outside its skin's range is bad input, one line.
TEST(Gltf, SkinsThatCannotBeCarriedAreLeftOutInOneLine) {
  const fs::path folder = scratch_folder("gltf_skin_left_out");
  const fs::path in = folder / "strips.gltf";
  const auto read = [&in](const Gltf_builder& b, apps::Read_report& report) {
    b.write(in);
    return apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  };
  // A second node of the strip, without a skin, flattened.
  Gltf_builder flattened = skinned_strip();
  flattened.model.nodes.emplace_back();
  flattened.model.nodes.back().mesh = 0;
  flattened.model.nodes.back().translation = {200, 0, 0};
  flattened.model.nodes.back().scale = {1, 1, 0};
  flattened.model.scenes[0].nodes.push_back(3);
  Gltf_builder no_weights = skinned_strip();
  no_weights.model.meshes[0].primitives[0].attributes.erase("WEIGHTS_0");
  // Skin 1 binds the tip at the root's place.
  const Gltf_builder conflicting = strips_of_two_skins(
      {2, 3}, std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  for (const auto& [b, cause, faces] :
       {std::make_tuple(conflicting, std::string("skin 0 and skin 1 bind node 2 differently"), 16u),
        std::make_tuple(flattened, std::string("node 3's transform flattens its mesh"), 16u),
        std::make_tuple(no_weights, std::string("mesh 0 primitive 0 has no JOINTS_0 and WEIGHTS_0"),
                        8u)}) {
    SCOPED_TRACE(cause);
    apps::Read_report report;
    const Mesh mesh = read(b, report);
    EXPECT_EQ(report.left_out,
              std::vector<std::string>{in.string() + ": the skin is left out (" + cause +
                                       "); every mesh is placed by its node's transform"});
    EXPECT_FALSE(Attributes(mesh).skins);
    EXPECT_EQ(mesh.number_of_faces(), faces);
    for (const auto v : mesh.vertices()) EXPECT_GE(mesh.point(v).x(), 100);
  }
  Gltf_builder far_joint = skinned_strip();
  far_joint.model.meshes[0].primitives[0].attributes["JOINTS_0"] =
      far_joint.accessor(std::vector<std::uint8_t>(40, 2), kUnsignedByte, TINYGLTF_TYPE_VEC4);
  try {
    apps::Read_report report;
    read(far_joint, report);
    ADD_FAILURE() << "read";
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(std::string(e.what()),
              in.string() +
                  ": mesh 0 primitive 0: joint 2 of vertex 0 is out of range (skin 0 "
                  "has 2 joints)");
  }
  fs::remove_all(folder);
}

}  // namespace corner_attributes

// ---- What an asset can make the readers read, and what a written file names ----------------
// (Asset_folder.h, docs/reliability.md.) The files are made by hand: a glTF file's buffers and
// images, an OBJ file's material libraries and their textures, named inside and outside its folder.

namespace asset_folder {

using apps::Mesh;
using corner_attributes::file_names;
using corner_attributes::gltf_json;
using gltf_fixtures::Gltf_builder;

// A fresh folder holding `asset/`, where each test puts the file it reads, and beside it (outside
// the asset's folder) `secret.bin`: the unit triangle's nine floats, a buffer that would read well.
fs::path scratch(const std::string& name) {
  const fs::path folder =
      fs::path(testing::TempDir()) / ("assets_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder / "asset" / "data");
  const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (const fs::path& file : {folder / "secret.bin", folder / "asset" / "data" / "tri.bin"})
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(triangle), sizeof triangle);
  return folder;
}

// folder/asset/leak.gltf: one triangle whose three points are read from the buffer `uri` names,
// `byte_length` bytes long (the triangle's 36 when it is right).
fs::path gltf_naming(const fs::path& folder, const std::string& uri, std::size_t byte_length = 36) {
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}},
                         {"buffers", {{{"uri", uri}, {"byteLength", byte_length}}}},
                         {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                         {"accessors",
                          {{{"bufferView", 0},
                            {"componentType", 5126},
                            {"count", 3},
                            {"type", "VEC3"},
                            {"min", {0, 0, 0}},
                            {"max", {1, 1, 0}}}}},
                         {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                         {"nodes", {{{"mesh", 0}}}},
                         {"scenes", {{{"nodes", {0}}}}},
                         {"scene", 0}};
  const fs::path path = folder / "asset" / "leak.gltf";
  std::ofstream(path) << gltf.dump();
  return path;
}

// The message of the Io_error (unreadable input) reading `path` gives; "" when it reads.
std::string read_failure(const fs::path& path, const apps::Read_options& options = {}) {
  try {
    apps::read_triangle_mesh(path.string(), options);
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(e.kind(), apps::Io_error::Kind::unreadable_input);
    return e.what();
  }
  return "";
}

std::string refused_buffer(const fs::path& gltf, const std::string& reference,
                           const std::string& cause) {
  return gltf.string() + ": a buffer's uri '" + reference + "' " + cause + " (" +
         fs::canonical(gltf.parent_path()).string() + "); an asset root above it widens that";
}

TEST(AssetFolder, ABufferOutsideTheAssetsFolderIsRefusedWithoutBeingOpened) {
  const fs::path folder = scratch("buffer_out");
  const std::string outside = "leads outside the asset's folder";
  // The reference as the file writes it, and as the message gives it (URI escapes decoded).
  for (const auto& [uri, reference] : std::vector<std::pair<std::string, std::string>>{
           {"../secret.bin", "../secret.bin"},
           {"%2e%2e/secret.bin", "../secret.bin"},
           {"..%2Fsecret.bin", "../secret.bin"},
           {"..\\secret.bin", "..\\secret.bin"},
           {"data/../../secret.bin", "data/../../secret.bin"},
           {"../../../../../../../../../../etc/passwd",
            "../../../../../../../../../../etc/passwd"}}) {
    SCOPED_TRACE(uri);
    const fs::path gltf = gltf_naming(folder, uri);
    EXPECT_EQ(read_failure(gltf), refused_buffer(gltf, reference, outside));
    // Its size wrong, the same message: nothing about the file it names, not even its size.
    EXPECT_EQ(read_failure(gltf_naming(folder, uri, 12)), refused_buffer(gltf, reference, outside));
  }
  const fs::path gltf = gltf_naming(folder, (folder / "secret.bin").string());
  EXPECT_EQ(read_failure(gltf),
            refused_buffer(gltf, (folder / "secret.bin").string(),
                           "is an absolute path; only paths relative to the asset are read"));
  const std::string file_uri = "file://" + (folder / "secret.bin").string();
  EXPECT_EQ(read_failure(gltf_naming(folder, file_uri)),
            refused_buffer(gltf, file_uri,
                           "is a URI with a scheme; only paths relative to the asset are read"));
  // A reference too long for any file system is one line, cut short.
  const std::string long_uri(5000, 'a');
  EXPECT_EQ(read_failure(gltf_naming(folder, long_uri)),
            refused_buffer(gltf, long_uri.substr(0, 200), "is too long"));
  fs::remove_all(folder);
}

TEST(AssetFolder, ABufferInsideTheAssetsFolderIsRead) {
  const fs::path folder = scratch("buffer_in");
  for (const std::string uri : {"data/tri.bin", "data/../data/tri.bin", "./data//tri.bin"}) {
    SCOPED_TRACE(uri);
    EXPECT_EQ(apps::read_triangle_mesh(gltf_naming(folder, uri).string()).number_of_faces(), 1u);
  }
  // A symbolic link that stays inside is followed.
  fs::create_directory_symlink(folder / "asset" / "data", folder / "asset" / "inner");
  EXPECT_EQ(
      apps::read_triangle_mesh(gltf_naming(folder, "inner/tri.bin").string()).number_of_faces(),
      1u);
  fs::remove_all(folder);
}

// Behind a folder that does not exist or a file, too ("missing/../link": the part of a path that
// does not exist is not looked at by the resolution of links, so ".." must go first).
TEST(AssetFolder, ASymbolicLinkOutOfTheAssetsFolderIsRefused) {
  const fs::path folder = scratch("link_out");
  fs::create_directory_symlink(folder, folder / "asset" / "up");
  fs::create_symlink(folder / "secret.bin", folder / "asset" / "data" / "innocent.bin");
  fs::create_symlink(folder / "secret.bin", folder / "asset" / "evil.bin");
  for (const std::string uri :
       {"up/secret.bin", "data/innocent.bin", "missing/../evil.bin", "data/tri.bin/../innocent.bin",
        "missing/../data/innocent.bin", "data/missing/../../evil.bin"}) {
    SCOPED_TRACE(uri);
    const fs::path gltf = gltf_naming(folder, uri);
    EXPECT_EQ(read_failure(gltf),
              refused_buffer(gltf, uri,
                             "leads outside the asset's folder through a symbolic link, or "
                             "cannot be resolved"));
  }
  // A control character (a decoded %00 among them) is refused before any look at the disk.
  const fs::path gltf = gltf_naming(folder, "data/tri.bin%00.png");
  EXPECT_EQ(read_failure(gltf),
            refused_buffer(gltf, "data/tri.bin\\x00.png", "holds a control character"));
  fs::remove_all(folder);
}

TEST(AssetFolder, AnAssetRootWidensTheFolderAndNoMore) {
  const fs::path folder = scratch("root");
  const fs::path gltf = gltf_naming(folder, "../secret.bin");
  const apps::Read_options widened{apps::Corner_attribute_reading::drop, 1, folder.string()};
  EXPECT_EQ(apps::read_triangle_mesh(gltf.string(), widened).number_of_faces(), 1u);
  // The root must hold the asset.
  const apps::Read_options below{apps::Corner_attribute_reading::drop, 1,
                                 (folder / "asset" / "data").string()};
  EXPECT_EQ(read_failure(gltf, below),
            gltf.string() + ": not inside the asset root " + (folder / "asset" / "data").string());
  // Nothing above the root.
  const fs::path deeper = folder / "asset" / "deeper";
  fs::create_directories(deeper);
  const fs::path moved = deeper / "leak.gltf";
  fs::rename(gltf_naming(folder, "../../../secret.bin"), moved);
  const apps::Read_options asset{apps::Corner_attribute_reading::drop, 1,
                                 (folder / "asset").string()};
  EXPECT_EQ(read_failure(moved, asset),
            moved.string() +
                ": a buffer's uri '../../../secret.bin' leads outside the asset's "
                "folder (" +
                fs::canonical(folder / "asset").string() + "); an asset root above it widens that");
  fs::remove_all(folder);
}

// textured_square() as folder/asset/square.glb, its second image the file `uri` names.
Mesh square_naming(const fs::path& folder, const std::string& uri, apps::Read_report& report) {
  Gltf_builder square = gltf_fixtures::textured_square(0, 2);
  square.model.images[1].uri = uri;
  square.write(folder / "asset" / "square.glb");
  return apps::read_triangle_mesh((folder / "asset" / "square.glb").string(), &report,
                                  apps::Corner_attribute_reading::keep);
}

TEST(AssetFolder, AnImageOutsideTheAssetsFolderIsLeftOutAndNamedNowhere) {
  const fs::path folder = scratch("image_out");
  std::ofstream(folder / "hostname.png", std::ios::binary) << gltf_fixtures::kImageBytes;
  apps::Read_report report;
  const Mesh mesh = square_naming(folder, "..%2Fhostname.png", report);
  const std::string in = (folder / "asset" / "square.glb").string();
  EXPECT_EQ(report.left_out,
            std::vector<std::string>{in + ": image 1's uri '..%2Fhostname.png' leads outside the "
                                          "asset's folder; written without it"});
  // The images held in the file stay; the texture that showed the file shows nothing, and its
  // material refers to no texture.
  const tinygltf::Model& looks = *report.materials.gltf;
  ASSERT_EQ(looks.images.size(), 2u);
  EXPECT_TRUE(looks.images[0].uri.empty() && looks.images[1].uri.empty());
  ASSERT_EQ(looks.textures.size(), 3u);
  EXPECT_EQ(looks.textures[0].source, 0);
  EXPECT_EQ(looks.textures[1].source, -1);
  EXPECT_EQ(looks.textures[2].source, 1);
  EXPECT_EQ(looks.materials[1].pbrMetallicRoughness.baseColorTexture.index, -1);
  for (const std::string name : {"out.gltf", "out.glb"}) {
    const fs::path out = folder / "asset" / name;
    EXPECT_EQ(apps::write_mesh_atomically(mesh, out.string(), report.materials),
              std::vector<std::string>{});
    const nlohmann::json written = gltf_json(out);
    EXPECT_EQ(written["images"].size(), 2u);
    EXPECT_EQ(written.dump().find("hostname"), std::string::npos);
  }
  fs::remove_all(folder);
}

TEST(AssetFolder, ObjLibrariesAndTexturesOutsideTheAssetsFolderAreLeftOut) {
  const fs::path folder = scratch("obj_out");
  const fs::path asset = folder / "asset";
  std::ofstream(folder / "outside.mtl") << "newmtl wood\nKd 1 0 0\n";
  std::ofstream(folder / "other.png", std::ios::binary) << gltf_fixtures::kImageBytes;
  std::ofstream(asset / "looks.mtl") << "newmtl wood\nmap_Kd ../../../../../../../../etc/passwd\n"
                                        "newmtl stone\nmap_Kd -s 1 1 1 ../other.png\n";
  std::ofstream(asset / "in.obj")
      << "mtllib ../outside.mtl looks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\n"
         "vt 0 1\nvt 1 1\nusemtl wood\nf 1/1 2/2 3/3\nusemtl stone\nf 2/2 4/4 3/3\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((asset / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  EXPECT_EQ(report.left_out,
            std::vector<std::string>{(asset / "in.obj").string() +
                                     ": material library '../outside.mtl' leads "
                                     "outside the asset's folder; read without it"});
  EXPECT_EQ(report.materials.libraries,
            std::vector<std::string>{fs::canonical(asset / "looks.mtl").string()});
  const std::string library = report.materials.libraries.front();
  EXPECT_EQ(apps::write_mesh_atomically(mesh, (asset / "out.glb").string(), report.materials),
            (std::vector<std::string>{
                library + ": texture '../../../../../../../../etc/passwd' leads outside the "
                          "asset's folder; written without it",
                library + ": texture '../other.png' leads outside the asset's folder; written "
                          "without it"}));
  EXPECT_FALSE(gltf_json(asset / "out.glb").contains("images"));
  // The picture's texture: the first map, refused by the same rule.
  try {
    apps::diffuse_texture_file(report.materials);
    ADD_FAILURE() << "a texture outside the folder was drawn";
  } catch (const apps::Io_error& e) {
    EXPECT_EQ(std::string(e.what()), library +
                                         ": texture '../../../../../../../../etc/passwd' leads "
                                         "outside the asset's folder");
  }
  fs::remove_all(folder);
}

// A written file names files inside its own folder only: an OBJ input's library and textures
// elsewhere are copied beside it, an image file elsewhere is embedded in a glTF file.
TEST(AssetFolder, WrittenFilesNameNothingOutsideTheirFolder) {
  const fs::path folder = scratch("written");
  const fs::path asset = folder / "asset";
  fs::create_directories(asset / "tex");
  std::ofstream(asset / "tex" / "a.png", std::ios::binary) << gltf_fixtures::kImageBytes;
  std::ofstream(asset / "tex" / "b.jpg", std::ios::binary) << gltf_fixtures::kJpegBytes;
  std::ofstream(asset / "looks.mtl")
      << "newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd tex/a.png\nmap_Bump -bm 0.3 tex/b.jpg\n"
         "newmtl stone\nmap_Kd tex/missing.png\nmap_Ks tex/a.png\n";
  std::ofstream(asset / "in.obj")
      << "mtllib looks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
         "vt 1 1\nusemtl wood\nf 1/1 2/2 3/3\nusemtl stone\nf 2/2 4/4 3/3\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((asset / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  const fs::path out = folder / "out";
  fs::create_directories(out);
  const std::string library = report.materials.libraries.front();
  EXPECT_EQ(
      apps::write_mesh_atomically(mesh, (out / "x.obj").string(), report.materials),
      std::vector<std::string>{library + ": texture 'tex/missing.png' does not exist or cannot be "
                                         "read; written without it"});
  EXPECT_EQ(file_names(out), (std::set<std::string>{"x.obj", "x.mtl", "x_a.png", "x_b.jpg"}));
  EXPECT_EQ(read_text(out / "x.mtl"),
            "newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd x_a.png\nmap_Bump -bm 0.3 x_b.jpg\n"
            "newmtl stone\nmap_Ks x_a.png\n");
  EXPECT_EQ(read_text(out / "x_a.png"), gltf_fixtures::kImageBytes);
  EXPECT_EQ(read_text(out / "x.obj").rfind("# written by cgal_policies\nmtllib x.mtl\n", 0), 0u);
  // Beside the input, the library is named as it is.
  EXPECT_EQ(apps::write_mesh_atomically(mesh, (asset / "y.obj").string(), report.materials),
            std::vector<std::string>{});
  EXPECT_EQ(read_text(asset / "y.obj").rfind("# written by cgal_policies\nmtllib looks.mtl\n", 0),
            0u);
  EXPECT_FALSE(fs::exists(asset / "y.mtl"));
  // A glTF input's image file: named beside the input, embedded elsewhere.
  apps::Read_report gltf_report;
  const Mesh square = square_naming(folder, "tex/a.png", gltf_report);
  apps::write_mesh_atomically(square, (asset / "z.gltf").string(), gltf_report.materials);
  EXPECT_EQ(gltf_json(asset / "z.gltf")["images"][1]["uri"], "tex/a.png");
  apps::write_mesh_atomically(square, (out / "z.gltf").string(), gltf_report.materials);
  const nlohmann::json embedded = gltf_json(out / "z.gltf");
  EXPECT_FALSE(embedded["images"][1].contains("uri"));
  EXPECT_EQ(embedded["images"][1]["mimeType"], "image/png");
  for (const fs::path& written : {out / "x.obj", out / "x.mtl", out / "z.gltf"})
    EXPECT_EQ(read_text(written).find(".."), std::string::npos) << written;
  fs::remove_all(folder);
}

}  // namespace asset_folder
