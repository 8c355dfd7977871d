// simplify IN OUT [RATIO]: simplifies a mesh with any policy of the suite (see README.md).
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/Json_object.h"
#include "common/Progress_bar.h"
#include "common/Removed_on_interrupt.h"
#include "common/Stopwatch.h"
#include "common/app_main.h"
#include "common/atomic_write.h"
#include "common/fitting.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/peak_memory.h"
#include "common/policy_registry.h"
#include "common/simplify_request.h"
#include "common/small_components.h"
#include "common/smoothing.h"

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Corner_attributes.h>

#ifdef CGAL_POLICIES_WITH_VIEWER
#include "snapshot.h"
#endif

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace apps {
namespace {

void print_help() {
  std::cout
      << "usage: simplify IN OUT [RATIO] [options]\n"
         "Simplifies the triangle mesh IN (.off .obj .ply .stl .gltf .glb) and writes OUT.\n"
         "An OBJ, PLY or glTF (.gltf .glb) OUT keeps IN's texture coordinates, normals and\n"
         "colours, seams included, and an OBJ or glTF OUT its materials (fast keeps the\n"
         "materials alone); a glTF OUT of a glTF IN keeps their textures and images too.\n\n"
         "  RATIO, --ratio R      keep this fraction of the faces, 0 < R <= 1\n"
         "  --faces N             keep N faces instead\n"
         "  --policy NAME         "
      << policy_names()
      << " (default classic)\n"
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
         "                        (map_Kd; exit 3 when that file is missing)"
#ifndef CGAL_POLICIES_WITH_VIEWER
         "\n                        (not in this build: mesh_viewer's packages were missing)"
#endif
         "\n"
         "  --size WxH            the snapshot's size in pixels (default 1600x800)\n"
         "  --force               allow OUT to be the same file as IN\n"
         "  --quiet               no progress bar, no summary\n"
         "  --help                this text\n\n"
         "Policy options (all lengths are fractions of IN's bounding-box diagonal):\n";
  for (const Policy_entry& p : policy_registry())
    std::cout << "  " << p.name << ": " << p.summary << '\n' << policy_options_help(p);
  std::cout << "\nExit codes: 0 done, 1 not done, 2 bad usage, 3 bad input, 4 output not written,\n"
               "130 or 143 interrupted by SIGINT or SIGTERM (OUT is then never half-written).\n";
}

// --snapshot OUT.png [--size WxH], checked before anything is read or written. The picture is
// rendered before OUT is written and removed again if OUT cannot be written: a failed run leaves
// neither new file, and an OUT that existed before is only replaced once the picture exists.
struct Snapshot_request {
  std::string png;
#ifdef CGAL_POLICIES_WITH_VIEWER
  Snapshot_settings settings;
#endif
};

std::optional<Snapshot_request> take_snapshot_options(Command_line& cli) {
  const std::optional<std::string> png = cli.take_value("snapshot");
  const std::optional<std::string> size = cli.take_value("size");
  if (size && !png) throw App_error(exit_usage, "--size goes with --snapshot");
  if (!png) return std::nullopt;
#ifdef CGAL_POLICIES_WITH_VIEWER
  // A .png is never a mesh, so never IN or OUT.
  if (std::filesystem::path(*png).extension() != ".png")
    throw App_error(exit_usage, *png + ": the snapshot must be a .png file");
  check_output_folder(*png);
  Snapshot_request request{*png, {}};
  if (size) parse_snapshot_size(*size, request.settings);
  return request;
#else
  throw App_error(exit_usage, *png +
                                  ": --snapshot is not in this build (mesh_viewer's packages "
                                  "were missing when it was configured)");
#endif
}

// Without the viewer, take_snapshot_options refuses every picture: only the mesh is written.
void write_mesh_and_snapshot([[maybe_unused]] const Mesh& original, const Mesh& simplified,
                             [[maybe_unused]] const std::string& policy_name,
                             [[maybe_unused]] const std::optional<Snapshot_request>& snapshot,
                             const std::string& output, const Material_references& materials) {
#ifdef CGAL_POLICIES_WITH_VIEWER
  // An interrupt before OUT is in place removes the new picture too.
  std::optional<Removed_on_interrupt> picture_without_mesh;
  if (snapshot) {
    Snapshot_settings settings = snapshot->settings;
    caption_snapshot(original, simplified, policy_name, settings);
    write_snapshot(original, simplified, settings, snapshot->png);
    picture_without_mesh.emplace(snapshot->png);
  }
  try {
    write_mesh_atomically(simplified, output, materials);
  } catch (...) {
    std::error_code ignored;
    if (snapshot) std::filesystem::remove(snapshot->png, ignored);
    throw;
  }
#else
  write_mesh_atomically(simplified, output, materials);
#endif
}

using Attributes = cgal_policies::Corner_attributes<Point>;

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  std::optional<Snapshot_request> snapshot = take_snapshot_options(cli);
  Simplify_request request = take_simplify_request(cli);
  const Policy_entry* policy = request.choice.policy;
  Simplify_settings& settings = request.choice.settings;
  const std::string& input = request.input;
  const std::string& output = request.output;
  const Smoothing_request& smoothing = request.smoothing;
  const Fit_request& fit = request.fit;
  const bool quiet = request.quiet, measure = request.measure;

  Read_report read_report;
  const Stopwatch reading;
  // Only an OBJ, PLY or glTF output can hold texture coordinates, normals and colours.
  Mesh mesh = read_triangle_mesh(input, &read_report,
                                 writes_corner_attributes(output) ? Corner_attribute_reading::keep
                                                                  : Corner_attribute_reading::drop);
  const double read_seconds = reading.seconds();
  if (!quiet)
    for (const std::string& repair : read_report.repairs)
      std::cerr << "simplify: " << input << ": " << repair << '\n';
#ifdef CGAL_POLICIES_WITH_VIEWER
  // Before any work: a texture the picture needs and cannot read is bad input.
  if (snapshot) snapshot->settings.texture = texture_to_draw(mesh, read_report.materials);
#endif
  const std::size_t input_faces = mesh.number_of_faces();
  const std::size_t input_vertices = mesh.number_of_vertices();
  settings.target_faces = request.target.of(input_faces);
  const Mesh original = measure || smoothing.bounded || snapshot || fit.enabled ? mesh : Mesh();
  // The pre-pass (docs/quadric_core.md, pair contraction) is not part of the simplification's time.
  const cgal_policies::Border_pair_contraction_report merge_report =
      cgal_policies::Border_pair_contraction(request.merge_distance)(mesh);
  if (merge_report.stitched_edges > 0) mesh.collect_garbage();
  const Dropped_components specks = drop_components_smaller_than(mesh, request.min_component);

  const bool input_had_corner_values = Attributes(mesh).any_corner_values();
  Simplify_outcome outcome;
  {
    Progress_bar bar(input_faces, settings.target_faces, !quiet);
    settings.on_progress = [&bar](std::size_t now) { bar.update(now); };
    outcome = policy->run(mesh, settings);
  }
  mesh.collect_garbage();
  const char* attributes = corner_attributes_word(input_had_corner_values, outcome);
  const Dropped_components vanished =
      request.drop_small_pieces && outcome.stop_reason == Stop_reason::no_collapse_left
          ? drop_smallest_components_until(mesh, settings.target_faces)
          : Dropped_components();
  const std::size_t refused_smoothing_moves = smooth_mesh(mesh, original, smoothing, request.bound);
  // After smoothing, so that the output the user gets is the fitted one.
  const Fit_outcome fitted =
      fit.enabled
          ? fit_to_input(mesh, original, fit.rounds, settings.max_normal_angle_deg, request.bound)
          : Fit_outcome();
  const Stopwatch writing;
  write_mesh_and_snapshot(original, mesh, policy->name, snapshot, output, read_report.materials);
  const double write_seconds = writing.seconds();

  const std::size_t removed = input_faces - mesh.number_of_faces();
  Json_object report;
  report.add("policy", policy->name);
  report.add("input", input);
  report.add("output", output);
  report.add("input_faces", input_faces);
  report.add("input_vertices", input_vertices);
  report.add("target_faces", settings.target_faces);
  report.add("output_faces", mesh.number_of_faces());
  report.add("output_vertices", mesh.number_of_vertices());
  report.add("seconds", outcome.seconds);
  report.add("read_seconds", read_seconds);    // reading and repairing IN
  report.add("write_seconds", write_seconds);  // writing OUT (and the snapshot, when asked)
  report.add("faces_removed_per_second", outcome.seconds > 0 ? removed / outcome.seconds : 0.0);
  report.add("peak_memory_mib", peak_rss_mib());
  report.add("stop_reason", to_string(outcome.stop_reason));
  // Signed: dropping a last piece may overshoot the target.
  report.add("target_gap_faces", static_cast<long long>(mesh.number_of_faces()) -
                                     static_cast<long long>(settings.target_faces));
  report.add("time_limit_seconds", settings.time_limit_seconds);
  report.add("min_component", request.min_component);
  report.add("dropped_components", specks.components);
  report.add("dropped_component_faces", specks.faces);
  report.add("drop_small_pieces", request.drop_small_pieces);
  report.add("vanished_components", vanished.components);
  report.add("vanished_faces", vanished.faces);
  report.add("max_error", settings.max_error);
  if (snapshot) report.add("snapshot", snapshot->png);
  report.add("smooth_iterations", smoothing.iterations);
  report.add("smooth_refused_moves", refused_smoothing_moves);
  if (fit.enabled) {
    report.add("fit_seconds", fitted.seconds);
    report.add("fit_rounds", fitted.report.rounds);
    report.add("fit_moves", fitted.report.moves);
    report.add("fit_refused_moves", fitted.report.refused_moves);
    report.add("fit_flips", fitted.report.flips);
    report.add("fit_refused_flips", fitted.report.refused_flips);
  }
  report.add("repairs", read_report.repairs);
  report.add("attributes", attributes);
  report.add("merge_distance", request.merge_distance);
  report.add("merged_pairs", merge_report.merged_pairs);
  report.add("stitched_edges", merge_report.stitched_edges);
  report.add("refused_pairs", merge_report.refused_pairs);
  for (const auto& [reason, count] : merge_report.refused_by_reason)
    report.add("refused_pairs_" + reason, count);
  for (const auto& [name, value] : settings.options) report.add("option_" + name, value);
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
    std::printf("%s: %zu -> %zu faces in %.3f s (%s)\n", policy->name.c_str(), input_faces,
                std::size_t(mesh.number_of_faces()), outcome.seconds,
                to_string(outcome.stop_reason));
    if (specks.components + vanished.components > 0)
      std::printf("dropped %zu small components (%zu faces) before, %zu (%zu faces) after\n",
                  specks.components, specks.faces, vanished.components, vanished.faces);
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
  return apps::guarded_main("simplify", [&] { return apps::run(argc, argv); });
}
