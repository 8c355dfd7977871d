// Fuzzes one reader (the extension is FUZZ_EXTENSION, one target per format): the bytes become a
// file that apps::read_triangle_mesh reads as simplify would when it keeps corner attributes
// (texture coordinates, normals, colours and materials of OBJ, PLY and glTF). It
// must give a valid triangle mesh or Io_error (unreadable input) with one line; anything else (a
// crash, another exception, a sanitizer report, an allocation beyond libFuzzer's limit, a hang) is
// a finding.
#include "fuzz_checks.h"

#include "io/Io_error.h"
#include "io/mesh_io.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

// One file per process, in memory when the machine has /dev/shm.
const std::string& input_path() {
  static const std::string path = [] {
    const std::filesystem::path folder =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp";
    return (folder / ("cgal_policies_fuzz_" + std::to_string(getpid()) + FUZZ_EXTENSION)).string();
  }();
  return path;
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
    fuzz::require(error.kind() == cgal_policies::io::Io_error::Kind::unreadable_input,
                  std::string("an unreadable input: ") + error.what());
    fuzz::require_one_line(error.what());
    fuzz::require(std::string(error.what()).rfind(path + ": ", 0) == 0,
                  "the error names the file: '" + std::string(error.what()) + "'");
  }
  std::remove(path.c_str());
  return 0;
}
