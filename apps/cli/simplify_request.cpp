#include "simplify_request.h"

#include "App_error.h"
#include "io/mesh_io.h"
#include "lod_chain.h"
#include "out_of_core_run.h"
#include "output_path.h"
#include "pass_options.h"
#include "policy_command_line.h"
#include "target_option.h"

#include <vector>

namespace apps {
namespace {

// --gltf-encoding float|quantized|meshopt, checked against OUT once it is known.
std::optional<Gltf_encoding> take_gltf_encoding(Command_line& cli) {
  const std::optional<std::string> name = cli.take_value("gltf-encoding");
  if (!name) return std::nullopt;
  if (const std::optional<Gltf_encoding> encoding = gltf_encoding_named(*name)) return encoding;
  throw App_error(exit_usage, "--gltf-encoding must be float, quantized or meshopt");
}

}  // namespace

Pipeline_request take_pipeline_request(Command_line& cli) {
  Pipeline_request request;
  Policy_choice choice = take_policy_options(cli);
  request.policy = choice.policy;
  cgal_policies::Simplification_options& options = request.options;
  options = choice.options;
  request.ratio = cli.take_number("ratio");
  request.faces = cli.take_whole_number("faces", 1, kMaxCount);
  const std::optional<double> max_error = cli.take_number("max-error");
  options.prepass_factor = take_prepass_factor(cli);
  options.merge_distance = cli.take_number("merge-distance").value_or(0.0);
  if (!(options.merge_distance >= 0))
    throw App_error(exit_usage, "--merge-distance must be at least 0");
  options.time_limit_seconds = cli.take_number("time-limit").value_or(0.0);
  if (!(options.time_limit_seconds >= 0 && options.time_limit_seconds <= kMaxTimeLimitSeconds))
    throw App_error(exit_usage, "--time-limit must be a number of seconds in [0, 1e9]");
  if (options.time_limit_seconds > 0 && !cgal_policies::runs_edge_collapse(options.policy))
    throw App_error(exit_usage, "--time-limit needs an edge-collapse policy; " +
                                    request.policy->name + " runs its own engine (try classic)");
  options.min_component =
      std::size_t(cli.take_whole_number("min-component", 0, kMaxCount).value_or(0));
  options.drop_small_pieces = cli.take_flag("drop-small-pieces");
  options.threads = std::size_t(cli.take_whole_number("threads", 0, 4096).value_or(0));
  options.parts = std::size_t(cli.take_whole_number("parts", 0, 1 << 20).value_or(0));
  options.smoothing = take_smoothing_options(cli);
  take_fit_options(cli, choice.named, options);
  if (max_error && !(*max_error > 0)) throw App_error(exit_usage, "--max-error must be positive");
  if (max_error && !cgal_policies::runs_edge_collapse(options.policy))
    throw App_error(exit_usage, "--max-error needs an edge-collapse policy; " +
                                    request.policy->name + " runs its own engine (try classic)");
  options.max_error = max_error.value_or(0.0);
  if (options.smoothing.bounded && !(options.two_sided_bound() > 0))
    throw App_error(exit_usage, "--smooth-bounded needs --max-error (or a policy's --tolerance)");
  if (options.prepass_factor > 0 && options.policy == cgal_policies::Simplification_policy::fast)
    throw App_error(exit_usage, "--prepass runs fast before another policy, not before fast");
  if (options.prepass_factor > 0 &&
      (options.two_sided_bound() > 0 || options.time_limit_seconds > 0))
    throw App_error(exit_usage,
                    "--prepass runs fast, which keeps no bound and no time limit: not with "
                    "--max-error, the hausdorff policy or --time-limit");
  return request;
}

Simplify_request take_simplify_request(Command_line& cli) {
  Simplify_request request;
  Pipeline_request pipeline = take_pipeline_request(cli);
  request.policy = pipeline.policy;
  request.options = pipeline.options;
  const std::optional<double> samples = cli.take_whole_number("samples", 1, kMaxCount);
  request.json = cli.take_flag("json");
  request.measure = cli.take_flag("measure");
  request.force = cli.take_flag("force");
  request.quiet = cli.take_flag("quiet");
  request.out_of_core = cli.take_flag("out-of-core");
  const std::optional<std::string> lod = cli.take_value("lod");
  if (lod) request.lod_ratios = parse_lod_ratios(*lod);
  const std::optional<Gltf_encoding> gltf_encoding = take_gltf_encoding(cli);
  request.asset_root = take_asset_root(cli);
  const cgal_policies::Simplification_options& options = request.options;
  if (request.out_of_core && (!runs_out_of_core(options) || request.measure))
    throw App_error(exit_usage,
                    "--out-of-core never holds IN whole, which --max-error, the hausdorff "
                    "policy, --merge-distance, --min-component, --smooth-bounded and --measure "
                    "need");
  const std::vector<std::string> args = cli.positionals();
  if (args.size() < 2 || args.size() > 3)
    throw App_error(exit_usage, "usage: simplify IN OUT [RATIO] [options] (see --help)");
  std::optional<double> ratio = pipeline.ratio;
  if (args.size() == 3) {
    if (ratio) throw App_error(exit_usage, "give RATIO or --ratio, not both");
    ratio = parse_number(args[2], "RATIO");
  }
  if (lod) {
    if (ratio || pipeline.faces)
      throw App_error(exit_usage, "--lod gives every level's ratio: no RATIO, --ratio or --faces");
    if (request.out_of_core)
      throw App_error(exit_usage,
                      "--lod measures every level against IN, which --out-of-core "
                      "never holds whole");
    request.options.target = cgal_policies::Face_target::ratio(request.lod_ratios.front());
  } else {
    request.options.target = face_target(ratio, pipeline.faces);
  }
  if (samples) request.samples = std::size_t(*samples);
  request.input = args[0];
  request.output = args[1];
  if (gltf_encoding && !is_gltf_file(request.output))
    throw App_error(exit_usage, "--gltf-encoding needs a glTF OUT (.gltf or .glb)");
  request.gltf_encoding = gltf_encoding.value_or(Gltf_encoding::float32);
  for (const std::string& output :
       lod ? cgal_policies::io::lod_level_paths(request.output, request.lod_ratios.size())
           : std::vector<std::string>{request.output})
    check_output_path(request.input, output, request.force);
  return request;
}

}  // namespace apps
