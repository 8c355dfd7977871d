// simplify IN OUT [RATIO]: simplifies a mesh with the suite's pipeline (README.md, docs/cli.md).
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/Json_object.h"
#include "cli/Progress_bar.h"
#include "cli/Snapshot_renderer.h"
#include "cli/Stopwatch.h"
#include "cli/app_main.h"
#include "cli/lod_chain.h"
#include "cli/out_of_core_run.h"
#include "cli/pass_options.h"
#include "cli/peak_memory.h"
#include "cli/report_fields.h"
#include "cli/simplify_request.h"
#include "cli/tuned_allocator.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/Removed_on_interrupt.h"
#include "io/Streamed_mesh_file.h"
#include "io/atomic_write.h"
#include "io/mesh_io.h"
#include "pipeline/Pipeline.h"

#include <cgal_policies/Corner_attributes.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace apps {
namespace {

void print_help() {
  std::cout
      << "usage: simplify IN OUT [RATIO] [options]\n"
         "Simplifies the triangle mesh IN (.off .obj .ply .stl .gltf .glb) and writes OUT.\n"
         "An OBJ, PLY or glTF (.gltf .glb) OUT keeps IN's texture coordinates, normals and\n"
         "colours, seams included, and an OBJ or glTF OUT its materials (fast keeps the\n"
         "materials alone); a glTF OUT of a glTF IN keeps their textures and images too,\n"
         "an OBJ OUT their base colours and images (OUT.mtl, the images IN holds beside).\n\n"
         "  RATIO, --ratio R      keep this fraction of the faces, 0 < R <= 1\n"
         "  --faces N             keep N faces instead\n"
         "  --lod R0,R1,...       a chain of levels of detail instead, finest first: level k\n"
         "                        keeps Rk of IN's faces, made from level k - 1 by the same\n"
         "                        pipeline; a glTF OUT holds every level (MSFT_lod), any\n"
         "                        other OUT becomes OUT_lod0, OUT_lod1, ... (all or none);\n"
         "                        each level is measured against IN; at most "
      << kMaxLodLevels
      << " levels\n"
         "  --gltf-encoding E     how a glTF OUT stores its vertices: float (default),\n"
         "                        quantized (KHR_mesh_quantization: 16-bit positions, 8-bit\n"
         "                        normals and colours, 16-bit texture coordinates when all\n"
         "                        lie in [-1, 1], float otherwise) or meshopt (quantized,\n"
         "                        then compressed: EXT_meshopt_compression); a viewer must\n"
         "                        support the extensions, which the file requires; a glTF\n"
         "                        OUT only\n"
         "  --policy NAME         "
      << policy_names()
      << " (default: the default pipeline,\n"
         "                        "
      << pipeline_name(cgal_policies::Simplification_options())
      << "; naming a policy runs it alone)\n"
         "  --max-normal-angle A  our policies refuse collapses that turn a face normal by\n"
         "                        more than A degrees (default 90)\n"
         "  --max-error X         also stop before the output's two-sided Hausdorff distance\n"
         "                        to IN would exceed X (a fraction of IN's diagonal); every\n"
         "                        edge-collapse policy, not fast\n"
         "  --time-limit S        stop where the run is after S seconds (default 0, none);\n"
         "                        every edge-collapse policy, not fast\n"
         "  --merge-distance T    first stitch border vertices of different border loops\n"
         "                        closer than T (a fraction of IN's diagonal; default 0, off)\n"
         "  --min-component N     first drop every connected component of fewer than N faces\n"
         "                        but the largest (a whole number; default 0, off)\n"
         "  --prepass K           fast first takes IN (each cell) down to K times the\n"
         "                        target, then the policy goes on from there: K >= 1\n"
         "                        (default 0, off; docs/pipeline.md). Not with fast,\n"
         "                        --max-error, hausdorff or --time-limit\n"
         "  --parts N             cut IN into N cells (a power of two) simplified at once and\n"
         "                        stitched (docs/scale.md); 0: one per 500,000 faces (default),\n"
         "                        1: none. A bound (--max-error, hausdorff) holds across them\n"
         "  --threads N           cores for the cells, the fit's matching and checking IN as it\n"
         "                        is read, 0: all (default); the output is the same for every N\n"
         "  --out-of-core         never hold IN whole (binary PLY or OBJ): read it in passes,\n"
         "                        spill each cell's triangles to a temporary file, and\n"
         "                        simplify cell by cell (docs/scale.md); IN's equal points are\n"
         "                        joined, its corner attributes carried. Not with --max-error,\n"
         "                        hausdorff, --merge-distance, --min-component, --measure or\n"
         "                        --snapshot\n"
         "  --drop-small-pieces   when no collapse is left short of the target, drop the\n"
         "                        smallest connected components whole, smallest first, until\n"
         "                        it is met; never the largest\n"
      << smoothing_help() << fit_help()
      << "  --json                print one JSON object on stdout\n"
         "  --measure             also measure the two-sided error against IN, and the\n"
         "                        error of the carried texture coordinates, normals and\n"
         "                        colours\n"
         "  --samples N           face samples per direction for --measure (default "
      << kDefaultErrorSamples
      << ")\n"
         "  --snapshot OUT.png    also render IN and OUT side by side, as mesh_viewer does,\n"
         "                        without a window; all or nothing: when the picture fails,\n"
         "                        OUT is not written (exit 4, or 1 without OpenGL); when\n"
         "                        OUT is an OBJ, a textured IN is drawn with its texture\n"
         "                        (map_Kd; exit 3 when that file is missing); needs a build\n"
         "                        with mesh_viewer's packages"
      << (snapshots_in_this_build() ? "" : " (not in this build)")
      << "\n"
         "  --size WxH            the snapshot's size in pixels (default 1600x800)\n"
      << kAssetRootHelp
      << "  --force               allow OUT to be the same file as IN\n"
         "  --quiet               no progress bar, no summary\n"
         "  --help                this text\n\n"
         "Policy options (all lengths are fractions of IN's bounding-box diagonal):\n";
  for (const Policy_entry& p : policy_registry())
    std::cout << "  " << p.name << ": " << p.summary << '\n' << options_help(p.options);
  std::cout << "\nExit codes: 0 done, 1 not done, 2 bad usage, 3 bad input, 4 output not written,\n"
               "130 or 143 interrupted by SIGINT or SIGTERM (OUT is then never half-written).\n";
}

// --snapshot OUT.png [--size WxH], checked before anything is read or written. The picture is
// rendered before OUT is written and removed again if OUT cannot be written: a failed run leaves
// neither new file, and an OUT that existed before is only replaced once the picture exists.
struct Snapshot_request {
  std::string png;
  std::unique_ptr<Snapshot_renderer> renderer;
};

std::optional<Snapshot_request> take_snapshot_options(Command_line& cli) {
  const std::optional<std::string> png = cli.take_value("snapshot");
  const std::optional<std::string> size = cli.take_value("size");
  if (size && !png) throw App_error(exit_usage, "--size goes with --snapshot");
  if (!png) return std::nullopt;
  const auto [width, height] = size ? parse_picture_size(*size) : std::pair<int, int>(1600, 800);
  Snapshot_request request{*png, make_snapshot_renderer(width, height)};
  if (!request.renderer)
    throw App_error(exit_usage, *png +
                                    ": --snapshot is not in this build (mesh_viewer's packages "
                                    "were missing when it was configured)");
  // A .png is never a mesh, so never IN or OUT.
  if (std::filesystem::path(*png).extension() != ".png")
    throw App_error(exit_usage, *png + ": the snapshot must be a .png file");
  check_output_folder(*png);
  return request;
}

// Returns what OUT was written without (write_mesh_atomically).
std::vector<std::string> write_mesh_and_snapshot(const Mesh& original, const Mesh& simplified,
                                                 const std::string& name,
                                                 const std::optional<Snapshot_request>& snapshot,
                                                 const std::string& output,
                                                 const Material_references& materials,
                                                 Gltf_encoding encoding) {
  // An interrupt before OUT is in place removes the new picture too.
  std::optional<Removed_on_interrupt> picture_without_mesh;
  if (snapshot) {
    snapshot->renderer->write(original, simplified, name, snapshot->png);
    picture_without_mesh.emplace(snapshot->png);
  }
  try {
    return write_mesh_atomically(simplified, output, materials, encoding);
  } catch (...) {
    std::error_code ignored;
    if (snapshot) std::filesystem::remove(snapshot->png, ignored);
    throw;
  }
}

// The pipeline of `options` with a progress bar from `start` faces.
template <class Run_pipeline>
cgal_policies::Simplification_report run_with_bar(cgal_policies::Simplification_options options,
                                                  std::size_t start, bool quiet,
                                                  const Run_pipeline& run_pipeline) {
  Progress_bar bar(start, options.target.of(start), !quiet && start > 0);
  options.progress = [&bar](cgal_policies::Simplification_pass pass, double, std::size_t faces) {
    if (pass == cgal_policies::Simplification_pass::simplification) bar.update(faces);
  };
  return run_pipeline(Pipeline(options));
}

// IN as simplify read it.
struct Read_input {
  const Mesh& mesh;
  const Read_report& report;
  double seconds;
  bool had_corner_values;
};

// --lod: each level made from the one before (the fit and bounded smoothing measuring against
// IN), every level written at once, all or none, then each measured against IN.
int run_lod_chain(const Simplify_request& request, const Read_input& input) {
  const std::vector<double>& ratios = request.lod_ratios;
  std::vector<cgal_policies::Simplification_options> options;
  std::vector<cgal_policies::Simplification_report> runs;
  std::vector<Mesh> levels;
  for (std::size_t k = 0; k < ratios.size(); ++k) {
    options.push_back(lod_level_options(request.options, ratios, k, input.mesh.number_of_faces()));
    Mesh level = k == 0 ? input.mesh : levels.back();
    runs.push_back(
        run_with_bar(options.back(), level.number_of_faces(), request.quiet,
                     [&](const Pipeline& pipeline) { return pipeline.run(level, input.mesh); }));
    levels.push_back(std::move(level));
  }
  const std::vector<double> coverage = lod_screen_coverage(ratios);
  std::vector<Lod_level> chain;
  for (std::size_t k = 0; k < levels.size(); ++k) chain.push_back({&levels[k], coverage[k]});
  const Stopwatch writing;
  // Even with --quiet: OUT lacks something IN had.
  for (const std::string& loss : write_lod_chain_atomically(
           chain, request.output, input.report.materials, request.gltf_encoding))
    std::cerr << "simplify: warning: " << loss << '\n';
  const double write_seconds = writing.seconds();
  if (request.quiet && !request.json) return exit_success;

  const bool one_file = holds_lod_chain(request.output);
  const std::vector<std::string> files = lod_level_paths(request.output, levels.size());
  const std::size_t samples = request.samples.value_or(kDefaultErrorSamples);
  std::vector<Json_object> level_reports;
  bool carried = true;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const cgal_policies::Simplification_report& run = runs[k];
    const Mesh_error error = measure_mesh_error(input.mesh, levels[k], samples);
    Json_object level;
    level.add("level", k);
    level.add("ratio", ratios[k]);
    level.add("output", one_file ? request.output : files[k]);
    if (one_file) {
      level.add("node", k);
      level.add("screen_coverage", coverage[k]);
    }
    add_fields(level, run, options[k], *request.policy);
    add_fields(level, error);
    add_fields(level, check_mesh_validity(levels[k]));
    if (input.had_corner_values)
      add_fields(level, measure_attribute_error(input.mesh, levels[k], samples));
    level_reports.push_back(level);
    carried = carried && run.attributes_carried;
    if (!request.json)
      std::printf(
          "level %zu (%g): %zu -> %zu faces in %.3f s (%s), two-sided Hausdorff %.4f%%, "
          "mean %.4f%% / %.4f%% of the diagonal\n",
          k, ratios[k], run.input_faces, run.output_faces, run.total_seconds(),
          to_string(run.stop_reason), 100 * error.hausdorff / error.bbox_diagonal,
          100 * error.mean_a_to_b / error.bbox_diagonal,
          100 * error.mean_b_to_a / error.bbox_diagonal);
  }
  if (!request.json) {
    for (const std::string& file : files) std::printf("wrote %s\n", file.c_str());
    return exit_success;
  }
  Json_object report;
  report.add("policy", request.policy->name);
  report.add("input", request.input);
  report.add("output", request.output);
  report.add("outputs", files);
  report.add("input_faces", input.mesh.number_of_faces());
  report.add("input_vertices", input.mesh.number_of_vertices());
  report.add("read_seconds", input.seconds);
  report.add("write_seconds", write_seconds);
  report.add("peak_memory_mib", peak_rss_mib());
  report.add("repairs", input.report.repairs);
  report.add("attributes", corner_attributes_word(input.had_corner_values, carried));
  report.add("levels", level_reports);
  std::cout << report.str() << '\n';
  return exit_success;
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  const std::optional<Snapshot_request> snapshot = take_snapshot_options(cli);
  Simplify_request request = take_simplify_request(cli);
  const std::string& input = request.input;
  const std::string& output = request.output;
  const bool quiet = request.quiet, measure = request.measure;

  const cgal_policies::Simplification_options& options = request.options;
  if (snapshot && !request.lod_ratios.empty())
    throw App_error(exit_usage, "--snapshot draws one output, and --lod writes several");
  Read_report read_report;
  Mesh mesh, original;
  bool input_had_corner_values = false;
  double read_seconds = 0;  // out of core, the reading is the simplification pass's
  cgal_policies::Simplification_report run;
  if (request.out_of_core) {
    if (snapshot)
      throw App_error(exit_usage, "--snapshot draws IN whole, which --out-of-core never holds");
    // Only an OBJ, PLY or glTF output can hold texture coordinates, normals and colours.
    const Streamed_mesh_file source(input, writes_corner_attributes(output)
                                               ? Corner_attribute_reading::keep
                                               : Corner_attribute_reading::drop);
    run = run_with_bar(options, source.declared_faces(), quiet, [&](const Pipeline& pipeline) {
      return run_out_of_core(pipeline, source, input, mesh);
    });
    input_had_corner_values = source.has_corner_values();
    read_report.materials = source.materials(request.asset_root, read_report.left_out);
    for (const std::string& loss : read_report.left_out)
      std::cerr << "simplify: warning: " << loss << '\n';
  } else {
    const Stopwatch reading;
    // Only an OBJ, PLY or glTF output can hold texture coordinates, normals and colours.
    const Corner_attribute_reading reading_attributes = writes_corner_attributes(output)
                                                            ? Corner_attribute_reading::keep
                                                            : Corner_attribute_reading::drop;
    mesh = read_triangle_mesh(input, {reading_attributes, options.threads, request.asset_root},
                              &read_report);
    read_seconds = reading.seconds();
    if (!quiet)
      for (const std::string& repair : read_report.repairs)
        std::cerr << "simplify: " << input << ": " << repair << '\n';
    // Even with --quiet: the output will lack something IN had.
    for (const std::string& loss : read_report.left_out)
      std::cerr << "simplify: warning: " << loss << '\n';
    // Before any work: a texture file the picture needs and cannot read is bad input; a glTF
    // image it cannot decode is a warning (texture_to_draw).
    if (snapshot)
      for (const std::string& loss : snapshot->renderer->prepare(mesh, read_report.materials))
        std::cerr << "simplify: warning: " << input << ": " << loss << '\n';
    input_had_corner_values = cgal_policies::Corner_attributes<Point>(mesh).any_corner_values();
    if (!request.lod_ratios.empty())
      return run_lod_chain(request, {mesh, read_report, read_seconds, input_had_corner_values});
    if (measure || snapshot || options.fit || options.smoothing.bounded) original = mesh;
    run = run_with_bar(options, mesh.number_of_faces(), quiet,
                       [&](const Pipeline& pipeline) { return pipeline.run(mesh, original); });
  }
  const std::string name = pipeline_name(options);
  const Stopwatch writing;
  // Even with --quiet: OUT lacks something IN had.
  for (const std::string& loss : write_mesh_and_snapshot(
           original, mesh, name, snapshot, output, read_report.materials, request.gltf_encoding))
    std::cerr << "simplify: warning: " << loss << '\n';
  const double write_seconds = writing.seconds();

  Json_object report;
  report.add("policy", request.policy->name);
  report.add("input", input);
  report.add("output", output);
  add_fields(report, run, request.options, *request.policy);
  report.add("read_seconds", read_seconds);    // reading and repairing IN
  report.add("write_seconds", write_seconds);  // writing OUT (and the snapshot, when asked)
  report.add("peak_memory_mib", peak_rss_mib());
  if (snapshot) report.add("snapshot", snapshot->png);
  report.add("repairs", read_report.repairs);
  report.add("attributes", corner_attributes_word(input_had_corner_values, run.attributes_carried));
  Mesh_error error;
  if (measure) {
    const std::size_t samples = request.samples.value_or(kDefaultErrorSamples);
    error = measure_mesh_error(original, mesh, samples);
    add_fields(report, error);
    add_fields(report, check_mesh_validity(mesh));
    // IN keeps its corner attributes only for an OBJ, PLY or glTF OUT; a dropping run leaves none
    // to compare.
    if (input_had_corner_values)
      add_fields(report, measure_attribute_error(original, mesh, samples));
  }

  if (request.json) {
    std::cout << report.str() << '\n';
  } else if (!quiet) {
    std::printf("%s: %zu -> %zu faces in %.3f s (%s)\n", name.c_str(), run.input_faces,
                run.output_faces, run.total_seconds(), to_string(run.stop_reason));
    const std::size_t dropped = run.dropped_before.components + run.dropped_after.components;
    if (dropped > 0)
      std::printf("dropped %zu small components (%zu faces) before, %zu (%zu faces) after\n",
                  run.dropped_before.components, run.dropped_before.faces,
                  run.dropped_after.components, run.dropped_after.faces);
    if (snapshot) std::printf("wrote %s\n", snapshot->png.c_str());
    if (measure)
      std::printf("two-sided Hausdorff %.4f%%, mean %.4f%% / %.4f%% of the diagonal\n",
                  100 * error.hausdorff / error.bbox_diagonal,
                  100 * error.mean_a_to_b / error.bbox_diagonal,
                  100 * error.mean_b_to_a / error.bbox_diagonal);
  }
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("simplify", [&] { return apps::run(argc, argv); });
}
