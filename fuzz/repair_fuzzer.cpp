// Fuzzes the reader's repair pipeline (apps::triangle_mesh_from_soup) on polygon soups built from
// the bytes (fuzz_soup.h): a valid triangle mesh, or Io_error (unreadable input) with one line.
// Checks too that the reader's fast path (clean_triangle_soup.h) takes exactly the soups that CGAL
// calls triangle meshes, and builds them as CGAL does.
#include "fuzz_checks.h"
#include "fuzz_soup.h"

#include "io/Io_error.h"
#include "io/clean_triangle_soup.h"
#include "io/mesh_io.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

void require_fast_path_agrees_with_cgal(const fuzz::Soup& soup) {
  // The reader refuses these before either path sees them.
  if (soup.polygons.empty()) return;
  for (const auto& polygon : soup.polygons)
    for (std::size_t index : polygon)
      if (index >= soup.points.size()) return;

  const bool triangles = std::all_of(soup.polygons.begin(), soup.polygons.end(),
                                     [](const auto& polygon) { return polygon.size() == 3; });
  const bool cgal_takes = triangles && PMP::is_polygon_soup_a_polygon_mesh(soup.polygons);
  apps::Mesh fast;
  std::size_t unused = 0;
  fuzz::require(
      apps::build_mesh_from_clean_triangles(soup.points, soup.polygons, fast, unused) == cgal_takes,
      "the fast path takes exactly the triangle soups CGAL calls polygon meshes");
  if (!cgal_takes) return;
  apps::Mesh cgal;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, cgal);
  fuzz::require(PMP::remove_isolated_vertices(cgal) == unused,
                "the fast path counts unused points");
  cgal.collect_garbage();
  fuzz::require(fast.number_of_vertices() == cgal.number_of_vertices() &&
                    fast.number_of_halfedges() == cgal.number_of_halfedges() &&
                    fast.number_of_faces() == cgal.number_of_faces(),
                "the fast path builds as many elements as CGAL");
  for (const auto h : fast.halfedges())
    fuzz::require(fast.point(fast.target(h)) == cgal.point(cgal.target(h)) &&
                      fast.face(h) == cgal.face(h) && fast.next(h) == cgal.next(h),
                  "the fast path builds CGAL's halfedges");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Byte_reader bytes(data, size);
  fuzz::Soup soup = fuzz::read_soup(bytes);
  require_fast_path_agrees_with_cgal(soup);
  try {
    const apps::Mesh mesh = apps::triangle_mesh_from_soup("soup", soup.points, soup.polygons);
    fuzz::require_finite_triangle_mesh(mesh, "a repaired soup");
  } catch (const cgal_policies::io::Io_error& error) {
    fuzz::require(error.kind() == cgal_policies::io::Io_error::Kind::unreadable_input,
                  std::string("an unreadable input: ") + error.what());
    fuzz::require_one_line(error.what());
  }
  return 0;
}
