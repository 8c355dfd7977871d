// simplify_bench: every policy of the registry and its peers on a matrix of meshes and targets, in
// one process, with the evaluator of mesh_error (issue 7, docs/evaluation.md). Prints the Markdown
// report; --out DIR also writes runs.csv, runs.json, report.md and the plots.
#include "bench_peers.h"
#include "bench_plots.h"
#include "bench_presets.h"
#include "bench_report.h"
#include "bench_runner.h"
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/Json_object.h"
#include "cli/app_main.h"
#include "cli/pass_options.h"
#include "cli/policy_command_line.h"
#include "cli/tuned_allocator.h"
#include "io/atomic_write.h"
#include "pipeline/policy_registry.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace apps {
namespace {

// Where the meshes of a preset that makes them (Bench_preset::made_by) are, unless --data says.
constexpr const char* kMadeMeshesVariable = "CGAL_POLICIES_SCALE_INPUTS";
constexpr const char* kMadeMeshesDefault = "/tmp/cgal_policies_scale";

// This suite's pipelines, one row per policy, then the peers.
std::vector<Bench_row> all_rows() {
  std::vector<Bench_row> all;
  for (const Policy_entry& p : policy_registry()) all.push_back(pipeline_row(p, false));
  const std::vector<Bench_row> peers = bench_peers();
  all.insert(all.end(), peers.begin(), peers.end());
  return all;
}

std::string names(const std::vector<Bench_row>& rows) {
  std::string text;
  for (const Bench_row& r : rows) text += (text.empty() ? "" : ",") + r.name;
  return text;
}

void print_help() {
  std::cout << "usage: simplify_bench (--preset NAME | --mesh FILE...) [options]\n"
               "Runs every policy (and the peers built in) on meshes and targets, times the\n"
               "simplification alone, measures each result with the two-sided error of\n"
               "mesh_error, and prints a Markdown report.\n\n"
               "  --preset NAME        ";
  for (const Bench_preset& p : bench_presets())
    std::cout << (&p == &bench_presets().front() ? "" : "                       ") << p.name << ": "
              << p.description << " (" << p.repetitions
              << (p.repetitions == 1 ? " repetition" : " repetitions") << ", "
              << (p.time_limit_seconds > 0
                      ? "time limit " + Json_object::format_number(p.time_limit_seconds) + " s"
                      : std::string("no time limit"))
              << ")\n";
  std::cout
      << "  --data DIR           where the presets' meshes are (default: the project's data/,\n"
         "                       " CGAL_POLICIES_DATA_DIR
         ";\n"
         "                       for a preset of made meshes, $"
      << kMadeMeshesVariable << " or " << kMadeMeshesDefault
      << ")\n"
         "  --only FILE,...      run only these of the preset's meshes (file names)\n"
         "  --mesh FILE          a mesh of your own; repeat for several\n"
         "  --ratios A,B         targets as fractions of the faces kept (default 0.1)\n"
         "  --faces N,M          targets as face counts\n"
         "  --policies P,Q       which policies (default all; gh is always run, as the\n"
         "                       reference of the time ratios): "
      << names(all_rows())
      << "\n"
         "  --fit                add a P+fit row beside each policy P of this suite: P, then\n"
         "                       the fitting pass (docs/fitting.md); the standard preset has\n"
         "                       lt+fit, gh+fit and hausdorff+fit without it; --policies\n"
         "                       takes P+fit\n"
         "  --threads A,B        run each policy of this suite on each of these thread\n"
         "                       counts, 0: every core (default: the preset's, else 0); the\n"
         "                       peers run once; a Threads table gives the scaling from 1\n"
         "  --out-of-core        read each --mesh (binary PLY) in passes, never whole, as\n"
         "                       simplify --out-of-core does; this suite's policies only\n"
         "                       (not hausdorff), and the error is not measured\n"
         "  --prepass K          fast first takes the mesh down to K times the target in\n"
         "                       every row of this suite without a bound (not fast,\n"
         "                       hausdorff), then the row's policy (simplify --prepass);\n"
         "                       not with a time limit\n"
         "  --repetitions N      runs per case; the fastest counts (default: the preset's, "
         "else 3)\n"
         "  --samples N          face samples per direction of the error measure\n"
         "  --attributes         read the texture coordinates and normals of OBJ meshes, carry\n"
         "                       them, and measure them (a Corner attributes table)\n"
         "  --time-limit S       stop an edge-collapse run after S seconds where it is,\n"
         "                       and do not repeat it; 0: none (default: the preset's,\n"
         "                       else none)\n"
         "  --out DIR            also write runs.csv, runs.json, report.md and PNG plots\n"
         "  --OPTION X           a policy option, for every policy that has it (simplify "
         "--help)\n"
         "  --help               this text\n";
  for (const Bench_row& p : bench_peers())
    std::cout << "  peer " << p.name << ": " << p.summary << '\n';
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::string item;
  for (char c : text + ",") {
    if (c != ',') {
      item += c;
    } else if (!item.empty()) {
      items.push_back(item);
      item.clear();
    }
  }
  return items;
}

std::size_t positive_count(const std::optional<double>& value, const std::string& option) {
  return value ? std::size_t(check_whole_number(*value, 1, kMaxCount, option)) : 0;
}

std::vector<std::size_t> parse_thread_counts(const std::string& list) {
  std::vector<std::size_t> counts;
  for (const std::string& n : split_list(list))
    counts.push_back(
        std::size_t(check_whole_number(parse_number(n, "--threads"), 0, 4096, "--threads")));
  if (counts.empty()) throw App_error(exit_usage, "--threads: give at least one count");
  return counts;
}

// The folder of a preset's meshes: --data, else data/ or, for made meshes, the folder the
// environment names or the default one.
std::string data_folder(const std::optional<std::string>& data, const Bench_preset* preset) {
  if (data) return *data;
  if (!preset || preset->made_by.empty()) return CGAL_POLICIES_DATA_DIR;
  const char* made = std::getenv(kMadeMeshesVariable);
  return made && *made ? made : kMadeMeshesDefault;
}

// The preset's meshes in `data`, only those named by --only when given.
std::vector<Bench_mesh> preset_meshes(const Bench_preset& preset, const std::string& data,
                                      const std::optional<std::string>& only) {
  const std::vector<std::string> names = split_list(only.value_or(""));
  for (const std::string& name : names)
    if (std::none_of(preset.meshes.begin(), preset.meshes.end(),
                     [&](const Bench_mesh& m) { return m.path == name; }))
      throw App_error(exit_usage,
                      "--only: the preset " + preset.name + " has no mesh '" + name + "'");
  std::vector<Bench_mesh> meshes;
  for (Bench_mesh m : preset.meshes) {
    if (!names.empty() && std::find(names.begin(), names.end(), m.path) == names.end()) continue;
    m.path = (fs::path(data) / m.path).string();
    meshes.push_back(std::move(m));
  }
  return meshes;
}

// Fail before hours of work, not after: a missing mesh, in one line that says how to make the
// made ones.
void check_meshes_exist(const std::vector<Bench_mesh>& meshes, const Bench_preset* preset,
                        const std::string& data) {
  std::string missing;
  for (const Bench_mesh& m : meshes)
    if (!fs::is_regular_file(m.path)) missing += " " + fs::path(m.path).filename().string();
  if (missing.empty()) return;
  if (preset && !preset->made_by.empty())
    throw App_error(exit_bad_input, data + ": missing" + missing + ": make them with " +
                                        preset->made_by + " '" + data + "'" + missing);
  for (const Bench_mesh& m : meshes)
    if (!fs::is_regular_file(m.path))
      throw App_error(exit_bad_input, m.path + ": cannot open: no such file");
}

std::vector<Bench_target> ad_hoc_targets(const std::optional<std::string>& ratios,
                                         const std::optional<std::string>& faces) {
  std::vector<Bench_target> targets;
  for (const std::string& r : split_list(ratios.value_or(faces ? "" : "0.1"))) {
    const double ratio = parse_number(r, "--ratios");
    if (!(ratio > 0 && ratio <= 1)) throw App_error(exit_usage, "--ratios: each must be in (0, 1]");
    targets.push_back({ratio, 0, ""});
  }
  for (const std::string& f : split_list(faces.value_or("")))
    targets.push_back({0, positive_count(parse_number(f, "--faces"), "--faces"), ""});
  return targets;
}

bool has_row(const std::vector<Bench_row>& rows, const std::string& name) {
  return std::any_of(rows.begin(), rows.end(), [&](const Bench_row& r) { return r.name == name; });
}

// The rows named, in that order, with gh added first when missing.
std::vector<Bench_row> select_rows(const std::optional<std::string>& list) {
  const std::vector<Bench_row> all = all_rows();
  if (!list) return all;
  std::vector<Bench_row> chosen;
  for (const std::string& name : split_list(*list)) {
    if (has_row(chosen, name)) continue;
    // "P+fit": this suite's pipeline with P, then the fitting pass.
    const std::optional<std::string> fitted = fitted_base(name);
    const Policy_entry* fitted_policy = fitted ? find_policy(*fitted) : nullptr;
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const Bench_row& r) { return r.name == name; });
    if (fitted_policy)
      chosen.push_back(pipeline_row(*fitted_policy, true));
    else if (it != all.end())
      chosen.push_back(*it);
    else
      throw App_error(exit_usage, "unknown policy '" + name + "' (" + names(all) +
                                      ", each of this suite's also as P" + kFitSuffix + ")");
  }
  if (!has_row(chosen, "gh"))
    chosen.insert(chosen.begin(), pipeline_row(*find_policy("gh"), false));
  return chosen;
}

std::string command_text(int argc, char** argv) {
  std::string text = fs::path(argv[0]).filename().string();
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    text += " " + (arg.find(' ') == std::string::npos ? arg : "'" + arg + "'");
  }
  return text;
}

// A report interrupted while written keeps its previous version.
void write_file(const fs::path& path, const std::string& text) {
  write_atomically(path.string(), [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << text;
    return bool(out.flush());
  });
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  const std::optional<std::string> preset_name = cli.take_value("preset");
  const std::optional<std::string> data_option = cli.take_value("data");
  const std::optional<std::string> only = cli.take_value("only");
  const std::optional<std::string> threads = cli.take_value("threads");
  const bool out_of_core = cli.take_flag("out-of-core");
  std::vector<std::string> mesh_files;
  while (const auto mesh = cli.take_value("mesh")) mesh_files.push_back(*mesh);
  const std::optional<std::string> ratios = cli.take_value("ratios"),
                                   faces = cli.take_value("faces");
  const std::optional<std::string> policy_list = cli.take_value("policies");
  const std::size_t repetitions = positive_count(cli.take_number("repetitions"), "--repetitions");
  const std::size_t samples = positive_count(cli.take_number("samples"), "--samples");
  const std::optional<double> time_limit = cli.take_number("time-limit");
  if (time_limit && !(*time_limit >= 0 && *time_limit <= kMaxTimeLimitSeconds))
    throw App_error(exit_usage, "--time-limit must be a number of seconds in [0, 1e9]");
  const double prepass_factor = take_prepass_factor(cli);
  const std::optional<std::string> out = cli.take_value("out");
  const bool fit_all = cli.take_flag("fit");
  const bool attributes = cli.take_flag("attributes");

  Bench_plan plan;
  plan.attributes = attributes;
  plan.rows = select_rows(policy_list);
  for (const Bench_row& r : plan.rows) {
    const Option_values given = take_option_values(cli, r.options);
    plan.options.insert(given.begin(), given.end());
  }
  for (const Bench_row& r : plan.rows) check_option_values(r.name, r.options, plan.options);
  if (!cli.positionals().empty())
    throw App_error(exit_usage, "unexpected argument '" + cli.positionals().front() + "'");

  const Bench_preset* preset = preset_name ? find_bench_preset(*preset_name) : nullptr;
  const std::string data = data_folder(data_option, preset);
  if (preset_name) {
    if (!preset) throw App_error(exit_usage, "unknown preset '" + *preset_name + "'");
    if (!mesh_files.empty() || ratios || faces || out_of_core)
      throw App_error(exit_usage,
                      "--preset takes its own meshes and targets: no --mesh, --ratios, "
                      "--faces or --out-of-core with it");
    plan.meshes = preset_meshes(*preset, data, only);
    plan.repetitions = repetitions ? repetitions : preset->repetitions;
    plan.samples = samples ? samples : preset->samples;
    plan.time_limit_seconds = time_limit.value_or(preset->time_limit_seconds);
    plan.threads = threads ? parse_thread_counts(*threads) : preset->threads;
  } else {
    if (mesh_files.empty()) throw App_error(exit_usage, "give --preset or --mesh (see --help)");
    if (only) throw App_error(exit_usage, "--only picks among a preset's meshes: give --preset");
    if (out_of_core && attributes)
      throw App_error(exit_usage,
                      "the bench's out-of-core rows read no corner attributes: no --attributes");
    const std::vector<Bench_target> targets = ad_hoc_targets(ratios, faces);
    for (const std::string& file : mesh_files)
      plan.meshes.push_back({file, targets, {}, out_of_core});
    plan.repetitions = repetitions ? repetitions : 3;
    plan.samples = samples ? samples : kDefaultErrorSamples;
    plan.time_limit_seconds = time_limit.value_or(0.0);
    if (threads) plan.threads = parse_thread_counts(*threads);
  }
  plan.prepass_factor = prepass_factor;
  if (plan.prepass_factor > 0 && plan.time_limit_seconds > 0)
    throw App_error(exit_usage,
                    "--prepass runs fast, which keeps no time limit: not with one (a preset's "
                    "too: give --time-limit 0)");
  // The "P+fit" rows: beside every policy of this suite with --fit, beside the preset's choice
  // without.
  std::vector<std::string> fitted;
  if (fit_all)
    for (const Bench_row& r : plan.rows) fitted.push_back(r.name);
  else if (preset && !policy_list)
    fitted = preset->fitted;
  for (const std::string& name : fitted) {
    const Policy_entry* policy = find_policy(name);
    const auto at = std::find_if(plan.rows.begin(), plan.rows.end(),
                                 [&](const Bench_row& r) { return r.name == name; });
    if (policy && at != plan.rows.end() && !has_row(plan.rows, name + kFitSuffix))
      plan.rows.insert(at + 1, pipeline_row(*policy, true));
  }
  for (const Bench_mesh& m : plan.meshes)
    for (const Bench_row& r : plan.rows)
      if (m.out_of_core && !r.run_out_of_core && mesh_runs_row(m, r.name))
        throw App_error(exit_usage, r.name +
                                        " needs the input whole: out of core, name this "
                                        "suite's policies with --policies (not hausdorff)");
  check_meshes_exist(plan.meshes, preset, data);
  if (out) {
    std::error_code ec;
    fs::create_directories(*out, ec);
    if (!fs::is_directory(*out))
      throw App_error(exit_bad_output, *out + ": cannot create the folder");
  }

  const std::string command = command_text(argc, argv);
  // The files are rewritten after each mesh, so that a long run interrupted keeps its results.
  const auto write_reports = [&](const std::vector<Run_record>& records) {
    const fs::path folder(*out);
    write_file(folder / "runs.csv", runs_csv(records));
    write_file(folder / "runs.json", runs_json(records, command));
    write_file(folder / "report.md", markdown_report(records, command, plan));
  };
  if (out) plan.on_mesh_done = write_reports;
  const std::vector<Run_record> records = run_bench(plan);
  std::cout << markdown_report(records, command, plan) << std::flush;
  if (out) draw_plots(records, *out);
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("simplify_bench", [&] { return apps::run(argc, argv); });
}
