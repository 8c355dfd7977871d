// Fuzzes the reader's repair pipeline (apps::triangle_mesh_from_soup) on polygon soups built from
// the bytes (fuzz_soup.h): a valid triangle mesh, or App_error(exit_bad_input) with one line.
#include "fuzz_checks.h"
#include "fuzz_soup.h"

#include "common/App_error.h"
#include "common/mesh_io.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Byte_reader bytes(data, size);
  fuzz::Soup soup = fuzz::read_soup(bytes);
  try {
    const apps::Mesh mesh = apps::triangle_mesh_from_soup("soup", soup.points, soup.polygons);
    fuzz::require_finite_triangle_mesh(mesh, "a repaired soup");
  } catch (const apps::App_error& error) {
    fuzz::require_one_line_error(error, apps::exit_bad_input);
  }
  return 0;
}
