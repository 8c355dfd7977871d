#include "soup_repair.h"

#include "polygon_triangulation.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>

namespace cgal_policies {
namespace io {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Polygon = std::vector<std::size_t>;
using Triangle = std::array<std::size_t, 3>;

// A triangle of a rebuilt soup: three corners (positions) of a polygon of the soup before.
struct Triangle_source {
  std::size_t polygon;
  Triangle corners;
};

// The lists of a rebuilt soup, from those of the soup before: each triangle's three entries.
std::vector<Polygon> rebuilt(const std::vector<Triangle_source>& sources,
                             const std::vector<Polygon>& lists) {
  std::vector<Polygon> result;
  result.reserve(sources.size());
  for (const Triangle_source& s : sources) {
    const Polygon& list = lists[s.polygon];
    result.push_back({list[s.corners[0]], list[s.corners[1]], list[s.corners[2]]});
  }
  return result;
}

// The corner tables' per-polygon lists that are not empty follow the triangles of `sources`.
void rebuild_corner_lists(const std::vector<Triangle_source>& sources, Corner_tables* corners) {
  if (!corners) return;
  for (std::vector<Polygon>* lists :
       {&corners->polygon_uvs, &corners->polygon_normals, &corners->polygon_colors,
        &corners->polygon_second_uvs, &corners->polygon_skins})
    if (!lists->empty()) *lists = rebuilt(sources, *lists);
  if (corners->polygon_materials.empty()) return;
  std::vector<std::uint32_t> materials;
  materials.reserve(sources.size());
  for (const Triangle_source& s : sources)
    materials.push_back(corners->polygon_materials[s.polygon]);
  corners->polygon_materials = std::move(materials);
}

void rebuild(const std::vector<Triangle_source>& sources, std::vector<Polygon>& polygons,
             Corner_tables* corners) {
  polygons = rebuilt(sources, polygons);
  rebuild_corner_lists(sources, corners);
}

std::string count_of(std::size_t count, const std::string& things) {
  return std::to_string(count) + " " + things;
}

// Drops the triangles that name a point twice, and every triangle of the same three points as one
// before it; returns how many.
std::size_t drop_degenerate_and_duplicate_triangles(std::vector<Polygon>& polygons,
                                                    Corner_tables* corners) {
  std::vector<Triangle_source> kept;
  kept.reserve(polygons.size());
  std::set<Triangle> seen;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    Triangle points{polygons[f][0], polygons[f][1], polygons[f][2]};
    std::sort(points.begin(), points.end());
    if (points[0] == points[1] || points[1] == points[2] || !seen.insert(points).second) continue;
    kept.push_back({f, {0, 1, 2}});
  }
  const std::size_t dropped = polygons.size() - kept.size();
  if (dropped > 0) rebuild(kept, polygons, corners);
  return dropped;
}

// Orients the triangles; a triangle that orient_polygon_soup turned over, or whose points it
// split, finds each corner's entries at the corner of the same point before (a split point is a
// copy of it; the three points of a triangle differ after the merge).
void orient_keeping_corners(std::vector<Point>& points, std::vector<Polygon>& polygons,
                            Corner_tables* corners, std::vector<std::string>& repairs) {
  const std::vector<Polygon> before = corners ? polygons : std::vector<Polygon>();
  const std::size_t points_before = points.size();
  if (!PMP::orient_polygon_soup(points, polygons) || points.size() > points_before)
    repairs.push_back("oriented the faces and split " +
                      count_of(points.size() - points_before, "non-manifold vertices"));
  else
    repairs.push_back("oriented the faces consistently");
  if (!corners) return;
  std::vector<Triangle_source> turned;
  turned.reserve(polygons.size());
  bool any_turned = false;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    Triangle_source source{f, {}};
    for (std::size_t k = 0; k < 3; ++k) {
      std::size_t j = 0;
      while (j < 2 && points[before[f][j]] != points[polygons[f][k]]) ++j;
      source.corners[k] = j;
    }
    any_turned = any_turned || source.corners != Triangle{0, 1, 2};
    turned.push_back(source);
  }
  if (any_turned) rebuild_corner_lists(turned, corners);
}

}  // namespace

void triangulate_polygons(const std::vector<Point>& points, std::vector<Polygon>& polygons,
                          Corner_tables* corners, std::vector<std::string>& repairs) {
  if (std::all_of(polygons.begin(), polygons.end(),
                  [](const Polygon& polygon) { return polygon.size() == 3; }))
    return;
  std::vector<Triangle_source> triangles;
  triangles.reserve(polygons.size());
  std::size_t split = 0, too_small = 0;
  std::vector<Point> polygon_points;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& polygon = polygons[f];
    if (polygon.size() < 3) {
      ++too_small;
      continue;
    }
    if (polygon.size() == 3) {
      triangles.push_back({f, {0, 1, 2}});
      continue;
    }
    ++split;
    polygon_points.clear();
    for (std::size_t p : polygon) polygon_points.push_back(points[p]);
    for (const Triangle& t : polygon_triangles(polygon_points)) triangles.push_back({f, t});
  }
  rebuild(triangles, polygons, corners);
  if (too_small > 0)
    repairs.push_back("dropped " + count_of(too_small, "faces of fewer than 3 corners"));
  if (split > 0) repairs.push_back("triangulated " + count_of(split, "polygons"));
}

void repair_triangle_soup(std::vector<Point>& points, std::vector<Polygon>& polygons,
                          Corner_tables* corners, std::vector<std::string>& repairs) {
  const std::size_t points_before = points.size();
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  const std::size_t dropped = drop_degenerate_and_duplicate_triangles(polygons, corners);
  PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  if (points.size() < points_before)
    repairs.push_back("merged or dropped " +
                      count_of(points_before - points.size(), "duplicate or unused points"));
  if (dropped > 0)
    repairs.push_back("dropped " + count_of(dropped, "degenerate or duplicate faces"));
  if (!polygons.empty()) orient_keeping_corners(points, polygons, corners, repairs);
}

}  // namespace io
}  // namespace cgal_policies
