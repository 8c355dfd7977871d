// simplify IN OUT [RATIO]: simplifies a mesh with any policy of the suite (see README.md).
#include "common/App_error.h"
#include "common/Command_line.h"
#include "common/Json_object.h"
#include "common/Progress_bar.h"
#include "common/Removed_on_interrupt.h"
#include "common/app_main.h"
#include "common/atomic_write.h"
#include "common/fitting.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/peak_memory.h"
#include "common/policy_command_line.h"
#include "common/policy_registry.h"
#include "common/small_components.h"
#include "common/smoothing.h"

#include <cgal_policies/Border_pair_contraction.h>

#ifdef CGAL_POLICIES_WITH_VIEWER
#include "snapshot.h"
#endif

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace apps {
namespace {

void print_help() {
  std::cout
      << "usage: simplify IN OUT [RATIO] [options]\n"
         "Simplifies the triangle mesh IN (.off .obj .ply .stl) and writes OUT.\n\n"
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
         "  --measure             also measure the two-sided error against IN\n"
         "  --samples N           face samples per direction for --measure (default "
      << kDefaultErrorSamples
      << ")\n"
         "  --snapshot OUT.png    also render IN and OUT side by side, as mesh_viewer does,\n"
         "                        without a window; all or nothing: when the picture fails,\n"
         "                        OUT is not written (exit 4, or 1 without OpenGL)"
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

// RATIO, --ratio or --faces, checked before the input is read.
class Face_target {
 public:
  Face_target(std::optional<double> ratio, std::optional<double> faces) : m_ratio(ratio) {
    if (ratio && faces) throw App_error(exit_usage, "give a ratio or --faces, not both");
    if (faces) {
      if (*faces < 1 || *faces != std::floor(*faces))
        throw App_error(exit_usage, "--faces must be a whole number of at least 1");
      m_faces = std::size_t(*faces);
      return;
    }
    if (!ratio) throw App_error(exit_usage, "give RATIO, --ratio or --faces (see --help)");
    if (!(*ratio > 0 && *ratio <= 1))
      throw App_error(exit_usage, "RATIO or --ratio must be a number in (0, 1]");
  }
  std::size_t of(std::size_t input_faces) const {
    return m_ratio ? std::size_t(std::llround(*m_ratio * double(input_faces))) : m_faces;
  }

 private:
  std::optional<double> m_ratio;
  std::size_t m_faces = 0;
};

// A whole number of at least 0 for `option`, 0 when not given.
std::size_t take_count(Command_line& cli, const std::string& option) {
  const double value = cli.take_number(option).value_or(0);
  if (!(value >= 0 && value == std::floor(value)))
    throw App_error(exit_usage, "--" + option + " must be a whole number of at least 0");
  return std::size_t(value);
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
                             const std::string& output) {
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
    write_mesh_atomically(simplified, output);
  } catch (...) {
    std::error_code ignored;
    if (snapshot) std::filesystem::remove(snapshot->png, ignored);
    throw;
  }
#else
  write_mesh_atomically(simplified, output);
#endif
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  Policy_choice choice = take_policy_options(cli, "classic");
  const Policy_entry* policy = choice.policy;
  Simplify_settings& settings = choice.settings;
  std::optional<double> ratio = cli.take_number("ratio");
  const std::optional<double> faces = cli.take_number("faces");
  const std::optional<double> samples = cli.take_number("samples");
  const std::optional<double> max_error = cli.take_number("max-error");
  const double merge_distance = cli.take_number("merge-distance").value_or(0.0);
  if (!(merge_distance >= 0)) throw App_error(exit_usage, "--merge-distance must be at least 0");
  settings.time_limit_seconds = cli.take_number("time-limit").value_or(0.0);
  if (!(settings.time_limit_seconds >= 0))
    throw App_error(exit_usage, "--time-limit must be a number of seconds of at least 0");
  if (settings.time_limit_seconds > 0 && !policy->takes_time_limit)
    throw App_error(exit_usage, "--time-limit needs an edge-collapse policy; " + policy->name +
                                    " runs its own engine (try classic)");
  const std::size_t min_component = take_count(cli, "min-component");
  const bool drop_small_pieces = cli.take_flag("drop-small-pieces");
  const Smoothing_request smoothing = take_smoothing_options(cli);
  const Fit_request fit = take_fit_options(cli);
  const std::optional<Snapshot_request> snapshot = take_snapshot_options(cli);
  const bool json = cli.take_flag("json"), measure = cli.take_flag("measure"),
             force = cli.take_flag("force"), quiet = cli.take_flag("quiet");
  if (max_error && !(*max_error > 0)) throw App_error(exit_usage, "--max-error must be positive");
  if (max_error && !policy->takes_error_bound)
    throw App_error(exit_usage, "--max-error needs an edge-collapse policy; " + policy->name +
                                    " runs its own engine (try classic)");
  settings.max_error = max_error.value_or(0.0);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() < 2 || args.size() > 3)
    throw App_error(exit_usage, "usage: simplify IN OUT [RATIO] [options] (see --help)");
  if (args.size() == 3) {
    if (ratio) throw App_error(exit_usage, "give RATIO or --ratio, not both");
    ratio = parse_number(args[2], "RATIO");
  }
  const Face_target target(ratio, faces);
  if (samples && !(*samples >= 1 && *samples == std::floor(*samples)))
    throw App_error(exit_usage, "--samples must be a whole number of at least 1");
  // The run's two-sided bound, which smoothing (when asked) and fitting keep.
  const double bound = two_sided_bound(*policy, settings);
  if (smoothing.bounded && !(bound > 0))
    throw App_error(exit_usage, "--smooth-bounded needs --max-error (or a policy's --tolerance)");
  const std::string& input = args[0];
  const std::string& output = args[1];
  check_output_path(input, output, force);

  Read_report read_report;
  Mesh mesh = read_triangle_mesh(input, &read_report);
  if (!quiet)
    for (const std::string& repair : read_report.repairs)
      std::cerr << "simplify: " << input << ": " << repair << '\n';
  const std::size_t input_faces = mesh.number_of_faces();
  const std::size_t input_vertices = mesh.number_of_vertices();
  settings.target_faces = target.of(input_faces);
  const Mesh original = measure || smoothing.bounded || snapshot || fit.enabled ? mesh : Mesh();
  // The pre-pass (docs/quadric_core.md, pair contraction) is not part of the simplification's time.
  const cgal_policies::Border_pair_contraction_report merge_report =
      cgal_policies::Border_pair_contraction(merge_distance)(mesh);
  if (merge_report.stitched_edges > 0) mesh.collect_garbage();
  const Dropped_components specks = drop_components_smaller_than(mesh, min_component);

  Simplify_outcome outcome;
  {
    Progress_bar bar(input_faces, settings.target_faces, !quiet);
    settings.on_progress = [&bar](std::size_t now) { bar.update(now); };
    outcome = policy->run(mesh, settings);
  }
  mesh.collect_garbage();
  const Dropped_components vanished =
      drop_small_pieces && outcome.stop_reason == Stop_reason::no_collapse_left
          ? drop_smallest_components_until(mesh, settings.target_faces)
          : Dropped_components();
  const std::size_t refused_smoothing_moves = smooth_mesh(mesh, original, smoothing, bound);
  // After smoothing, so that the output the user gets is the fitted one.
  const Fit_outcome fitted =
      fit.enabled ? fit_to_input(mesh, original, fit.rounds, settings.max_normal_angle_deg, bound)
                  : Fit_outcome();
  write_mesh_and_snapshot(original, mesh, policy->name, snapshot, output);

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
  report.add("faces_removed_per_second", outcome.seconds > 0 ? removed / outcome.seconds : 0.0);
  report.add("peak_memory_mib", peak_rss_mib());
  report.add("stop_reason", to_string(outcome.stop_reason));
  // Signed: dropping a last piece may overshoot the target.
  report.add("target_gap_faces", static_cast<long long>(mesh.number_of_faces()) -
                                     static_cast<long long>(settings.target_faces));
  report.add("time_limit_seconds", settings.time_limit_seconds);
  report.add("min_component", min_component);
  report.add("dropped_components", specks.components);
  report.add("dropped_component_faces", specks.faces);
  report.add("drop_small_pieces", drop_small_pieces);
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
  report.add("merge_distance", merge_distance);
  report.add("merged_pairs", merge_report.merged_pairs);
  report.add("stitched_edges", merge_report.stitched_edges);
  report.add("refused_pairs", merge_report.refused_pairs);
  for (const auto& [reason, count] : merge_report.refused_by_reason)
    report.add("refused_pairs_" + reason, count);
  for (const auto& [name, value] : settings.options) report.add("option_" + name, value);
  Mesh_error error;
  if (measure) {
    error =
        measure_mesh_error(original, mesh, samples ? std::size_t(*samples) : kDefaultErrorSamples);
    add_fields(report, error);
    add_fields(report, check_mesh_validity(mesh));
  }

  if (json) {
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
