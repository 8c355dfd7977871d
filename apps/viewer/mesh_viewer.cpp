// mesh_viewer MESH: the original and the simplified mesh side by side, re-simplified in real time
// as a slider moves (README.md, "Anyone looks"; the 2014 report's preview). With --snapshot, the
// same picture is rendered without a window and written as a PNG.
#include "Viewer_window.h"
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/Snapshot_renderer.h"
#include "cli/app_main.h"
#include "cli/pass_options.h"
#include "cli/policy_command_line.h"
#include "cli/tuned_allocator.h"
#include "io/mesh_io.h"
#include "pipeline/Pipeline.h"
#include "snapshot.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

namespace apps {
namespace {

void print_help() {
  std::cout
      << "usage: mesh_viewer MESH [options]\n"
         "Shows MESH (.off .obj .ply .stl .gltf .glb) and its simplification side by side: drag\n"
         "to orbit, right-drag or shift-drag to pan, wheel to zoom; the panel picks the policy, "
         "its\n"
         "options and the target face count. A mesh with texture coordinates and a texture (an\n"
         "OBJ's map_Kd, a glTF material's base colour texture in PNG or JPEG), or with colours,\n"
         "is drawn with them, and so is each simplification that carries them. A glTF file\n"
         "with levels of detail (MSFT_lod, as simplify --lod writes it) shows one level at a\n"
         "time, the panel simplifying that level: PageUp/PageDown or [ ] step to the finer or\n"
         "coarser level.\n\n"
         "  --policy NAME         "
      << policy_names() << " (default: the default pipeline, "
      << pipeline_name(cgal_policies::Simplification_options())
      << ")\n"
         "  --fit                 fit the result to MESH (the default pipeline does)\n"
         "  --ratio R             keep this fraction of the faces, 0 < R <= 1 (default 0.1)\n"
         "  --max-normal-angle A  as for simplify (default 90)\n"
         "  --flat                flat shading instead of smooth\n"
         "  --wireframe           draw the edges\n"
         "  --heat-map            colour the simplified mesh by its distance to MESH\n"
         "  --lod-level K         show MESH's level of detail K, 0 the finest (default 0)\n"
         "  --snapshot OUT.png    render the view without a window, write it and exit\n"
         "  --size WxH            the snapshot's size in pixels (default 1600x800)\n"
      << kAssetRootHelp
      << "  --help                this text\n\n"
         "Policy options are those of simplify (see simplify --help).\n"
         "Exit codes: 0 done, 1 not done, 2 bad usage, 3 bad input, 4 output not written.\n";
}

// Level `level` of `levels` beside its simplification; the summary line names the level when the
// file has more than one.
int write_snapshot_of(const std::vector<Mesh>& levels, std::size_t level,
                      cgal_policies::Simplification_options options, double ratio,
                      Snapshot_settings snapshot, const std::string& png) {
  const Mesh& mesh = levels[level];
  options.target = cgal_policies::Face_target::ratio(ratio);
  Mesh simplified = mesh;
  const cgal_policies::Simplification_report report = Pipeline(options).run(simplified);
  const std::string name = pipeline_name(options), title = level_title(level, levels.size());
  caption_snapshot(mesh, simplified, name, snapshot, title);
  write_snapshot(mesh, simplified, snapshot, png);
  if (levels.size() > 1) std::printf("%s, ", title.c_str());
  std::printf("%s: %zu -> %zu faces in %.3f s (%s); wrote %s (%dx%d)\n", name.c_str(),
              report.input_faces, report.output_faces, report.total_seconds(),
              to_string(report.stop_reason), png.c_str(), snapshot.width, snapshot.height);
  return exit_success;
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  Policy_choice choice = take_policy_options(cli);
  take_fit_options(cli, choice.named, choice.options);
  const double ratio = cli.take_number("ratio").value_or(0.1);
  if (!(ratio > 0 && ratio <= 1)) throw App_error(exit_usage, "the ratio must be in (0, 1]");
  const std::optional<std::string> png = cli.take_value("snapshot");
  const std::optional<std::string> size = cli.take_value("size");
  Snapshot_settings snapshot;
  snapshot.view.flat_shading = cli.take_flag("flat");
  snapshot.view.wireframe = cli.take_flag("wireframe");
  snapshot.heat_map = cli.take_flag("heat-map");
  const auto level = std::size_t(cli.take_whole_number("lod-level", 0, kMaxCount).value_or(0));
  const std::string asset_root = take_asset_root(cli);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 1)
    throw App_error(exit_usage, "usage: mesh_viewer MESH [options] (see --help)");
  if (size && !png) throw App_error(exit_usage, "--size goes with --snapshot");
  if (size) std::tie(snapshot.width, snapshot.height) = parse_picture_size(*size);
  if (png && std::filesystem::path(*png).extension() != ".png")
    throw App_error(exit_usage, *png + ": the snapshot must be a .png file");

  Read_report report;
  std::vector<Mesh> levels =
      read_lod_chain(args[0], {Corner_attribute_reading::keep, 1, asset_root}, &report);
  // Its range is known once MESH is read.
  if (level >= levels.size())
    throw App_error(exit_usage, "--lod-level must be a whole number in [0, " +
                                    std::to_string(levels.size() - 1) + "]: " + args[0] + " has " +
                                    std::to_string(levels.size()) +
                                    (levels.size() == 1 ? " level" : " levels") + " of detail");
  for (Mesh& mesh : levels) mesh.collect_garbage();
  // The levels share their materials, and simplify --lod gives each the finest one's kinds of
  // corner values: the finest says whether a texture is drawn.
  std::vector<std::string> left_out;
  snapshot.texture = texture_to_draw(levels.front(), report.materials, left_out);
  // What the picture will not show: what the reader left out (a morph target, an animation),
  // each line naming MESH already, then a texture it cannot draw.
  for (const std::string& loss : report.left_out)
    std::cerr << "mesh_viewer: warning: " << loss << '\n';
  for (const std::string& loss : left_out)
    std::cerr << "mesh_viewer: warning: " << args[0] << ": " << loss << '\n';
  if (png) return write_snapshot_of(levels, level, choice.options, ratio, snapshot, *png);

  Viewer_start start;
  start.title = std::filesystem::path(args[0]).filename().string();
  start.policy = choice.policy;
  start.options = choice.options;
  start.ratio = ratio;
  start.view = snapshot.view;
  start.heat_map = snapshot.heat_map;
  start.texture = snapshot.texture ? &*snapshot.texture : nullptr;
  start.level = level;
  run_viewer_window(levels, start);
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("mesh_viewer", [&] { return apps::run(argc, argv); });
}
