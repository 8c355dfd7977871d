// Fuzzes one reader (the extension is kFuzzExtension, one target per format): the bytes become a
// file that apps::read_triangle_mesh reads as simplify would when it keeps corner attributes
// (texture coordinates, normals, colours and materials of OBJ, PLY and glTF). It
// must give a valid triangle mesh or Io_error (unreadable input) with one line; anything else (a
// crash, another exception, a sanitizer report, an allocation beyond libFuzzer's limit, a hang) is
// a finding. A PLY or an OBJ is read again by the reader of --out-of-core, which must give finite
// points and triangles that name them, or Io_error so.
#include "fuzz_checks.h"

#include "io/Io_error.h"
#include "io/Streamed_mesh_file.h"
#include "io/mesh_io.h"

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

// The reader's extension (".obj", ...), defined by each target's own one-line file
// (fuzz/CMakeLists.txt), so that this file compiles once for every reader.
extern const char* const kFuzzExtension;

namespace {

// One file per process, in memory when the machine has /dev/shm.
const std::string& input_path() {
  static const std::string path = [] {
    const std::filesystem::path folder =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
    return (folder / ("cgal_policies_fuzz_" + std::to_string(getpid()) + kFuzzExtension)).string();
  }();
  return path;
}

void require_unreadable_input(const cgal_policies::io::Io_error& error, const std::string& path) {
  fuzz::require(error.kind() == cgal_policies::io::Io_error::Kind::unreadable_input,
                std::string("an unreadable input: ") + error.what());
  fuzz::require_one_line(error.what());
  fuzz::require(std::string(error.what()).rfind(path + ": ", 0) == 0,
                "the error names the file: '" + std::string(error.what()) + "'");
}

void read_in_passes(const std::string& path) {
  try {
    using File = cgal_policies::io::Streamed_mesh_file;
    const File file(path, apps::Corner_attribute_reading::keep);
    std::size_t points = 0;
    file.for_each_point([&](double x, double y, double z) {
      fuzz::require(std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
                    "a streamed point is finite");
      ++points;
    });
    std::vector<std::string> left_out;
    const std::size_t materials = file.materials({}, left_out).names.size();
    file.for_each_triangle(
        [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, const File::Corners& corners) {
          fuzz::require(a < points && b < points && c < points, "a streamed triangle names points");
          fuzz::require(
              corners.material < materials ||
                  corners.material == cgal_policies::Corner_attributes<apps::Point>::kNoMaterial,
              "a streamed triangle's material is one of the file's");
          for (const auto& v : corners.values)
            fuzz::require(!std::isinf(v.uv[0]) && !std::isinf(v.uv[1]) &&
                              !std::isinf(v.normal.x()) && !std::isinf(v.color[0]),
                          "a streamed corner's values are finite or none");
        });
  } catch (const cgal_policies::io::Io_error& error) {
    require_unreadable_input(error, path);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = input_path();
  {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    fuzz::require(file != nullptr, "the input file can be written");
    fuzz::require(std::fwrite(data, 1, size, file) == size, "the input file is written whole");
    std::fclose(file);
  }
  try {
    const apps::Mesh mesh =
        apps::read_triangle_mesh(path, nullptr, apps::Corner_attribute_reading::keep);
    fuzz::require_finite_triangle_mesh(mesh, "a mesh read from " + path);
  } catch (const cgal_policies::io::Io_error& error) {
    require_unreadable_input(error, path);
  }
  if (std::string(kFuzzExtension) == ".ply" || std::string(kFuzzExtension) == ".obj")
    read_in_passes(path);
  std::remove(path.c_str());
  return 0;
}
