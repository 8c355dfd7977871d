// bake_vertex_colors IN OUT: a mesh coloured per vertex from its texture, to test and measure
// colour carrying on real data (docs/attributes.md). Each vertex takes the mean of its texture's
// colour at its corners' coordinates, so the colours have no seams even where the texture does.
#include "app_types.h"
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/app_main.h"
#include "cli/output_path.h"
#include "cli/tuned_allocator.h"
#include "io/material_texture.h"
#include "io/mesh_io.h"
#include "viewer/Texture_image.h"

#include <cgal_policies/Corner_attributes.h>

#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <iostream>
#include <optional>

namespace apps {
namespace {

using Attributes = cgal_policies::Corner_attributes<Point>;

constexpr const char* kUsage = "usage: bake_vertex_colors IN OUT [--texture IMAGE] [--force]";

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    std::cout << kUsage
              << "\nColours each vertex of IN, a mesh with texture coordinates, with the mean of\n"
                 "its texture's colour at its corners, and writes OUT (PLY: per-vertex red green\n"
                 "blue alpha; OBJ: v x y z r g b) with the colours alone.\n"
                 "  --texture IMAGE  the texture (default: the diffuse map, map_Kd, of IN's\n"
                 "                   material)\n"
                 "  --force          overwrite OUT if it exists\n"
              << kAssetRootHelp;
    return exit_success;
  }
  const bool force = cli.take_flag("force");
  const std::optional<std::string> texture_option = cli.take_value("texture");
  const std::string asset_root = take_asset_root(cli);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 2) throw App_error(exit_usage, kUsage);
  const std::string &input = args[0], &output = args[1];
  check_output_path(input, output, force);

  Read_report report;
  Mesh mesh = read_triangle_mesh(input, {Corner_attribute_reading::keep, 1, asset_root}, &report);
  const Attributes textured(mesh);
  if (!textured.uvs)
    throw Io_error(Io_error::Kind::unreadable_input, input + ": no texture coordinates");
  const std::optional<std::string> texture_file =
      texture_option ? texture_option : diffuse_texture_file(report.materials);
  if (!texture_file)
    throw Io_error(Io_error::Kind::unreadable_input,
                   input + ": no material with a diffuse map (give --texture)");
  const Texture_image texture = Texture_image::load(*texture_file);

  std::vector<Attributes::Color> colors(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) {
    std::array<double, 3> sum{0, 0, 0};
    int corners = 0;
    for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
      if (mesh.is_border(h)) continue;
      const auto rgb = texture.color_at((*textured.uvs)[h][0], (*textured.uvs)[h][1]);
      for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += rgb[std::size_t(c)];
      ++corners;
    }
    colors[std::size_t(v)] = {sum[0] / corners, sum[1] / corners, sum[2] / corners, 1};
  }
  Attributes::remove(mesh);
  const Attributes colored = Attributes::add(mesh, {false, false, true, false, false, false});
  for (const auto h : mesh.halfedges())
    if (!mesh.is_border(h)) (*colored.colors)[h] = colors[std::size_t(mesh.target(h))];
  write_mesh_atomically(mesh, output);
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("bake_vertex_colors", [&] { return apps::run(argc, argv); });
}
