#include "output_path.h"

#include "App_error.h"
#include "io/atomic_write.h"
#include "io/mesh_io.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace apps {

void check_output_path(const std::string& input, const std::string& output, bool force) {
  using namespace cgal_policies::io;
  if (!has_supported_mesh_extension(output))
    throw App_error(exit_usage, output + ": unsupported output format '" + lower_extension(output) +
                                    "' (use .off, .obj, .ply, .stl, .gltf or .glb)");
  std::error_code ec;
  if (!force && fs::exists(output, ec) && fs::equivalent(input, output, ec))
    throw App_error(exit_usage, output + ": refusing to overwrite the input (use --force)");
  check_output_folder(output);
}

}  // namespace apps
