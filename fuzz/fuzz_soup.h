// The polygon soup the repair and policy fuzzers build from their bytes (the layout is in
// fuzz/README.md, and fuzz/make_seeds.py writes it from the shipped meshes): points on a 1/256
// grid, so that mutations make coincident, collinear and coplanar points often, and polygons whose
// indices may be out of range.
#ifndef CGAL_POLICIES_FUZZ_FUZZ_SOUP_H
#define CGAL_POLICIES_FUZZ_FUZZ_SOUP_H

#include "Byte_reader.h"

#include "app_types.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fuzz {

// Under the "small input" of 10k faces, and small enough for a sanitized Debug build.
constexpr std::size_t kMaxSoupPoints = 1024, kMaxSoupPolygons = 2048;

struct Soup {
  std::vector<apps::Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

inline Soup read_soup(Byte_reader& bytes) {
  Soup soup;
  const std::size_t points = std::min<std::size_t>(bytes.u16(), kMaxSoupPoints);
  for (std::size_t i = 0; i < points && !bytes.empty(); ++i) {
    const double x = bytes.i16() / 256.0, y = bytes.i16() / 256.0, z = bytes.i16() / 256.0;
    soup.points.emplace_back(x, y, z);
  }
  const std::size_t polygons = std::min<std::size_t>(bytes.u16(), kMaxSoupPolygons);
  for (std::size_t f = 0; f < polygons && !bytes.empty(); ++f) {
    // Mostly triangles; 0 to 7 corners in all, so that the reader's checks see every case.
    const std::uint8_t head = bytes.u8();
    const std::size_t corners = head < 192 ? 3 : head % 8;
    std::vector<std::size_t> polygon;
    for (std::size_t c = 0; c < corners; ++c) polygon.push_back(bytes.u16());
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

}  // namespace fuzz

#endif  // CGAL_POLICIES_FUZZ_FUZZ_SOUP_H
