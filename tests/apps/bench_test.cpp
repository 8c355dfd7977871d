// simplify_bench end to end: the quick preset writes its report files with one row per run and
// finite numbers, and its gh rows are exactly what simplify --policy gh --measure prints; the scale
// preset's plan, on small stand-ins for its made meshes, and its scaling figure.
#include "app_types.h"
#include "bench_presets.h"
#include "bench_runner.h"
#include "io/mesh_io.h"
#include "pipeline/policy_registry.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Row = std::map<std::string, std::string>;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// One CSV line, with "quoted, cells" and doubled quotes inside them.
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

std::vector<Row> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_csv_line(line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    EXPECT_EQ(cells.size(), header.size()) << line;
    Row row;
    for (std::size_t i = 0; i < std::min(cells.size(), header.size()); ++i)
      row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

bool parses_as_finite(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0' && std::isfinite(v);
}

// A number field of a flat JSON object as printed by simplify --json.
double json_number(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\": ";
  const std::size_t at = json.find(pattern);
  EXPECT_NE(at, std::string::npos) << key;
  return at == std::string::npos ? NAN : std::strtod(json.c_str() + at + pattern.size(), nullptr);
}

std::size_t count_occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

int run_command(const std::string& command) { return std::system(command.c_str()); }

// An output folder of this process for the test `name`, gone if an earlier run left it.
fs::path fresh_out(const std::string& name) {
  const fs::path out =
      fs::temp_directory_path() / ("cgal_policies_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(out);
  return out;
}

class BenchQuickPreset : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (test_meshes::real_meshes_skipped()) return;
    s_out = fresh_out("bench_test");
    s_exit =
        run_command(std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --preset quick --data '" +
                    CGAL_POLICIES_DATA_DIR + "' --out '" + s_out.string() + "' > '" +
                    (s_out.string() + ".stdout") + "' 2> '" + (s_out.string() + ".stderr") + "'");
    s_rows = read_csv(s_out / "runs.csv");
  }
  static void TearDownTestSuite() {
    if (s_out.empty()) return;
    fs::remove_all(s_out);
    fs::remove(s_out.string() + ".stdout");
    fs::remove(s_out.string() + ".stderr");
  }
  void SetUp() override {
    SKIP_IF_REAL_MESHES_ARE_OFF();
    ASSERT_EQ(s_exit, 0) << read_text(s_out.string() + ".stderr");
    ASSERT_FALSE(s_rows.empty());
  }

  static fs::path s_out;
  static int s_exit;
  static std::vector<Row> s_rows;
};

fs::path BenchQuickPreset::s_out;
int BenchQuickPreset::s_exit = -1;
std::vector<Row> BenchQuickPreset::s_rows;

TEST_F(BenchQuickPreset, CsvHasOneRowPerCaseAndPolicyWithFiniteNumbers) {
  const std::set<std::string> text_columns = {
      "mesh", "target", "label", "policy", "input_read", "stop_reason", "valid", "closed", "cgal"};
  // Without --attributes, the corner-attribute columns stay empty (BenchAttributes fills them).
  const std::set<std::string> attribute_columns = {
      "attributes",           "uv_mean_rel",  "uv_max_rel",   "normal_angle_mean_deg",
      "normal_angle_max_deg", "color_mean",   "color_max",    "seam_edges_a",
      "seam_edges_b",         "seam_loops_a", "seam_loops_b", "flipped_uv_faces"};
  std::set<std::pair<std::string, std::string>> cases;
  std::set<std::string> policies;
  std::set<std::vector<std::string>> runs;
  for (const Row& row : s_rows) {
    // One thread count, every core: no scaling.
    EXPECT_EQ(row.at("threads"), "0");
    EXPECT_EQ(row.at("scaling"), "");
    EXPECT_EQ(row.at("input_read"), "whole");
    EXPECT_EQ(row.at("cgal"), CGAL_VERSION_STR);
    for (const auto& [column, cell] : row) {
      if (attribute_columns.count(column) || column == "scaling") {
        EXPECT_EQ(cell, "") << column;
      } else if (!text_columns.count(column)) {
        EXPECT_TRUE(parses_as_finite(cell)) << column << " = " << cell;
      }
    }
    EXPECT_TRUE(row.at("valid") == "true" || row.at("valid") == "false");
    cases.insert({row.at("mesh"), row.at("target_faces")});
    policies.insert(row.at("policy"));
    EXPECT_TRUE(runs.insert({row.at("mesh"), row.at("target_faces"), row.at("policy")}).second)
        << "two rows for one run: " << row.at("mesh") << " " << row.at("policy");
  }
  EXPECT_EQ(s_rows.size(), cases.size() * policies.size());
  for (const apps::Policy_entry& p : apps::policy_registry())
    EXPECT_TRUE(policies.count(p.name)) << "policy " << p.name << " did not run";
}

TEST_F(BenchQuickPreset, JsonMarkdownAndPlotsCoverEveryRun) {
  const std::string json = read_text(s_out / "runs.json");
  EXPECT_EQ(count_occurrences(json, "\"policy\": "), s_rows.size());
  EXPECT_EQ(json.find("null"), std::string::npos);

  const std::string markdown = read_text(s_out / "report.md");
  EXPECT_EQ(read_text(s_out.string() + ".stdout"), markdown);
  std::set<std::string> meshes;
  for (const Row& row : s_rows) meshes.insert(row.at("mesh"));
  EXPECT_EQ(count_occurrences(markdown, "\n| target → faces |"), meshes.size());
  std::size_t table_rows = 0;
  for (const Row& row : s_rows)
    table_rows +=
        count_occurrences(markdown, " → " + row.at("target_faces") + " | " + row.at("policy") +
                                        " | " + row.at("output_faces"));
  EXPECT_EQ(table_rows, s_rows.size());
  for (const std::string& mesh : meshes)
    EXPECT_NE(markdown.find("- " + mesh + ": "), std::string::npos) << "no summary for " << mesh;

  if (run_command("command -v gnuplot > /dev/null 2>&1") != 0) return;  // plots are optional
  for (std::string stem : meshes) {
    std::replace(stem.begin(), stem.end(), '.', '_');
    for (const char* plot : {"_error.png", "_time.png"}) {
      const fs::path png = s_out / (stem + plot);
      EXPECT_TRUE(fs::exists(png) && fs::file_size(png) > 0) << png;
    }
  }
}

TEST_F(BenchQuickPreset, GhRowsMatchSimplify) {
  std::size_t checked = 0;
  for (const Row& row : s_rows) {
    if (row.at("policy") != "gh") continue;
    const fs::path output = s_out / ("gh_" + std::to_string(checked++) + ".off");
    const std::string json_path = output.string() + ".json";
    const double ratio = std::stod(row.at("target_ratio"));
    const std::string target =
        ratio > 0 ? row.at("target_ratio") : "--faces " + row.at("target_faces");
    ASSERT_EQ(run_command(std::string(CGAL_POLICIES_BIN_DIR) + "/simplify '" +
                          test_meshes::data_file(row.at("mesh")) + "' '" + output.string() + "' " +
                          target + " --policy gh --measure --json --quiet --samples " +
                          row.at("samples") + " > '" + json_path + "'"),
              0);
    const std::string json = read_text(json_path);
    EXPECT_EQ(json_number(json, "target_faces"), std::stod(row.at("target_faces")));
    EXPECT_EQ(json_number(json, "output_faces"), std::stod(row.at("output_faces")));
    EXPECT_EQ(json_number(json, "output_vertices"), std::stod(row.at("output_vertices")));
    for (const char* field : {"hausdorff", "mean_a_to_b", "mean_b_to_a", "rms", "min_angle_deg"})
      EXPECT_EQ(json_number(json, field), std::stod(row.at(field))) << field;
  }
  EXPECT_GT(checked, 0u);
}

// A limit that has passed before the first collapse: every edge-collapse run stops at once, is
// marked in the report and is not repeated.
TEST(BenchTimeLimit, StopsARunWhereItIsAndDoesNotRepeatIt) {
  const fs::path out = fresh_out("bench_limit");
  const std::string bench = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --mesh '" +
                            CGAL_POLICIES_SOURCE_DIR + "/data/cow.obj' --ratios 0.5 ";
  ASSERT_EQ(
      run_command(bench + "--policies gh,classic --repetitions 3 --samples 1000 --time-limit " +
                  "1e-9 --out '" + out.string() + "' > /dev/null 2>&1"),
      0);
  const std::vector<Row> rows = read_csv(out / "runs.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const Row& row : rows) {
    EXPECT_EQ(row.at("stop_reason"), "time_limit") << row.at("policy");
    EXPECT_EQ(row.at("repetitions"), "1") << row.at("policy");
    EXPECT_EQ(row.at("output_faces"), row.at("input_faces")) << row.at("policy");
  }
  EXPECT_EQ(count_occurrences(read_text(out / "report.md"), "†"), 3u);  // two rows, one note
  fs::remove_all(out);
  const int status = run_command(bench + "--time-limit -1 > /dev/null 2>&1");
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
}

// --prepass K: every row reaches its target, the report says the rows ran fast first, and a time
// limit is refused (fast has none).
TEST(BenchPrepass, RunsTheRowsAfterFastAndSaysSo) {
  const fs::path out = fresh_out("bench_prepass");
  const std::string bench = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --mesh '" +
                            CGAL_POLICIES_SOURCE_DIR + "/data/cow.obj' --ratios 0.1 ";
  ASSERT_EQ(run_command(bench + "--policies flat-lt,fast --prepass 4 --repetitions 1 --samples " +
                        "1000 --out '" + out.string() + "' > /dev/null 2>&1"),
            0);
  const std::vector<Row> rows = read_csv(out / "runs.csv");
  ASSERT_EQ(rows.size(), 3u);  // gh, flat-lt, fast
  for (const Row& row : rows) {
    EXPECT_EQ(row.at("output_faces"), "580") << row.at("policy");
    EXPECT_EQ(row.at("valid"), "true") << row.at("policy");
  }
  EXPECT_NE(read_text(out / "report.md").find("ran fast first, down to 4 times its target"),
            std::string::npos);
  fs::remove_all(out);
  const int status = run_command(bench + "--prepass 4 --time-limit 5 > /dev/null 2>&1");
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
}

// --fit adds a P+fit row beside each policy, with the pass's time and a "Fitting pass" table that
// compares it with P and with lt.
TEST(BenchFit, AddsAFittedRowBesideEachPolicy) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path out = fresh_out("bench_fit");
  ASSERT_EQ(run_command(std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --mesh '" +
                        CGAL_POLICIES_SOURCE_DIR + "/data/cow.obj' --ratios 0.1 --policies lt " +
                        "--fit --repetitions 1 --samples 20000 --out '" + out.string() +
                        "' > /dev/null 2>&1"),
            0);
  const std::vector<Row> rows = read_csv(out / "runs.csv");
  std::vector<std::string> policies;
  for (const Row& row : rows) {
    policies.push_back(row.at("policy"));
    const bool fitted = row.at("policy").find("+fit") != std::string::npos;
    EXPECT_EQ(std::stod(row.at("fit_seconds")) > 0, fitted) << row.at("policy");
    EXPECT_EQ(row.at("output_faces"), rows.front().at("output_faces")) << row.at("policy");
    EXPECT_EQ(row.at("valid"), "true") << row.at("policy");
  }
  EXPECT_EQ(policies, (std::vector<std::string>{"gh", "gh+fit", "lt", "lt+fit"}));
  const std::string report = read_text(out / "report.md");
  EXPECT_NE(report.find("## Fitting pass"), std::string::npos);
  EXPECT_EQ(count_occurrences(report, "| cow.obj | 10% → 580 | "), 2u) << report;
  fs::remove_all(out);
}

// --attributes reads, carries and measures the corner attributes: on a flat grid with a linear
// texture field every run (fast too) reproduces the field exactly and keeps its one seam (the
// border).
TEST(BenchAttributes, CarriesAndMeasuresTheCornerAttributes) {
  const fs::path out = fresh_out("bench_attributes");
  fs::create_directories(out);
  test_meshes::Mesh grid = test_meshes::flat_grid(6);
  test_meshes::paint_corners(
      grid,
      [](test_meshes::Mesh::Face_index, const test_meshes::Point& p) {
        return std::array<double, 2>{p.x() / 6, p.y() / 6};
      },
      false);
  const fs::path input = out / "grid.obj";
  apps::write_mesh_atomically(grid, input.string());
  const std::string bench = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --mesh '" +
                            input.string() + "' --faces 8 --policies attributes,fast " +
                            "--repetitions 1 --samples 2000 --out '" + out.string() + "'";
  ASSERT_EQ(run_command(bench + " --attributes > /dev/null 2>&1"), 0);
  const std::vector<Row> rows = read_csv(out / "runs.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (const Row& row : rows) {
    const std::string& policy = row.at("policy");
    EXPECT_EQ(row.at("attributes"), "carried") << policy;
    EXPECT_LE(std::stod(row.at("uv_max_rel")), 1e-12) << policy;
    EXPECT_EQ(row.at("flipped_uv_faces"), "0") << policy;
    EXPECT_EQ(row.at("seam_loops_a"), "1") << policy;
    EXPECT_EQ(row.at("seam_loops_b"), "1") << policy;
    EXPECT_EQ(row.at("seam_edges_a"), "24") << policy;
  }
  const std::string json = read_text(out / "runs.json");
  EXPECT_EQ(count_occurrences(json, "\"uv_mean_rel\": "), 3u) << json;
  EXPECT_NE(read_text(out / "report.md").find("## Corner attributes"), std::string::npos);

  ASSERT_EQ(run_command(bench + " > /dev/null 2>&1"), 0);
  for (const Row& row : read_csv(out / "runs.csv")) {
    EXPECT_EQ(row.at("attributes"), "") << row.at("policy");
    EXPECT_EQ(row.at("uv_mean_rel"), "") << row.at("policy");
  }
  EXPECT_EQ(read_text(out / "report.md").find("## Corner attributes"), std::string::npos);
  fs::remove_all(out);
}

// The scale preset: per made mesh, the rows of the issue, each of this suite's on 1 and 2
// threads, the largest out of core.
TEST(BenchScalePreset, ListsItsMeshesAndRows) {
  const apps::Bench_preset* scale = apps::find_bench_preset("scale");
  ASSERT_NE(scale, nullptr);
  EXPECT_EQ(scale->made_by, "scripts/make_scale_inputs.sh");
  EXPECT_EQ(scale->threads, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(scale->fitted, (std::vector<std::string>{"flat-lt"}));
  EXPECT_EQ(scale->repetitions, 1u);
  ASSERT_EQ(scale->meshes.size(), 3u);
  const std::vector<std::string> in_memory = {"fast", "flat-lt+fit", "meshopt"};
  const std::vector<std::string> paths = {"dragon4.ply", "dragon16.ply", "dragon128.ply"};
  for (std::size_t i = 0; i < 3; ++i) {
    const apps::Bench_mesh& mesh = scale->meshes[i];
    EXPECT_EQ(mesh.path, paths[i]);
    ASSERT_EQ(mesh.targets.size(), 1u);
    EXPECT_EQ(mesh.targets[0].ratio, 0.01);
    const bool largest = i == 2;
    EXPECT_EQ(mesh.out_of_core, largest) << mesh.path;
    EXPECT_EQ(mesh.rows, largest ? std::vector<std::string>{"fast"} : in_memory) << mesh.path;
    EXPECT_EQ(mesh.left_out.empty(), !largest) << mesh.path;
    EXPECT_FALSE(apps::mesh_runs_row(mesh, "gh")) << mesh.path;
  }
}

// The preset's inputs missing: one line that says how to make them, exit 3, before any work.
TEST(BenchScalePreset, MissingInputsSayHowToMakeThem) {
  const fs::path missing =
      fs::temp_directory_path() / ("cgal_policies_no_scale_" + std::to_string(::getpid()));
  const fs::path err = missing.string() + ".stderr";
  const std::string bench = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --preset scale ";
  const auto exit_code = [](int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; };
  EXPECT_EQ(exit_code(run_command(bench + "--data '" + missing.string() + "' > /dev/null 2> '" +
                                  err.string() + "'")),
            3);
  EXPECT_EQ(read_text(err), "simplify_bench: " + missing.string() +
                                ": missing dragon4.ply dragon16.ply dragon128.ply: make them with "
                                "scripts/make_scale_inputs.sh '" +
                                missing.string() + "' dragon4.ply dragon16.ply dragon128.ply\n");
  // Without --data: the folder of the environment; --only: those meshes alone.
  EXPECT_EQ(exit_code(run_command("CGAL_POLICIES_SCALE_INPUTS='" + missing.string() + "' " + bench +
                                  "--only dragon16.ply > /dev/null 2> '" + err.string() + "'")),
            3);
  EXPECT_EQ(read_text(err), "simplify_bench: " + missing.string() +
                                ": missing dragon16.ply: make them with "
                                "scripts/make_scale_inputs.sh '" +
                                missing.string() + "' dragon16.ply\n");
  EXPECT_EQ(exit_code(run_command(bench + "--only dragon8.ply > /dev/null 2>&1")), 2);
  fs::remove(err);
}

// The whole preset on small stand-ins (a sphere of 5,120 faces under the made meshes' names): the
// rows it lists, in order, the scaling of every 2-thread run, and the out-of-core rows as
// simplify --out-of-core makes them, their error not measured.
TEST(BenchScalePreset, RunsItsRowsOnStandIns) {
  SKIP_IF_TOO_SLOW_WHEN_SANITIZED();
  const fs::path out = fresh_out("bench_scale");
  const fs::path inputs = out / "inputs";
  fs::create_directories(inputs);
  const test_meshes::Mesh sphere = test_meshes::loop_sphere(4);
  ASSERT_EQ(sphere.number_of_faces(), 5120u);
  for (const char* name : {"dragon4.ply", "dragon16.ply", "dragon128.ply"})
    apps::write_mesh_atomically(sphere, (inputs / name).string());
  ASSERT_EQ(run_command(std::string(CGAL_POLICIES_BIN_DIR) + "/simplify_bench --preset scale " +
                        "--data '" + inputs.string() + "' --samples 1000 --out '" + out.string() +
                        "' > /dev/null 2>&1"),
            0);
  const std::vector<Row> rows = read_csv(out / "runs.csv");
  std::vector<std::string> runs;
  for (const Row& row : rows)
    runs.push_back(row.at("mesh") + " " + row.at("policy") + " " + row.at("threads") + " " +
                   row.at("input_read"));
  EXPECT_EQ(runs, (std::vector<std::string>{
                      "dragon4.ply fast 1 whole", "dragon4.ply fast 2 whole",
                      "dragon4.ply flat-lt+fit 1 whole", "dragon4.ply flat-lt+fit 2 whole",
                      "dragon4.ply meshopt 0 whole", "dragon16.ply fast 1 whole",
                      "dragon16.ply fast 2 whole", "dragon16.ply flat-lt+fit 1 whole",
                      "dragon16.ply flat-lt+fit 2 whole", "dragon16.ply meshopt 0 whole",
                      "dragon128.ply fast 1 out of core", "dragon128.ply fast 2 out of core"}));
  ASSERT_EQ(rows.size(), 12u);
  for (const Row& row : rows) {
    const std::string run = row.at("mesh") + " " + row.at("policy") + " " + row.at("threads");
    EXPECT_EQ(row.at("target_faces"), "51") << run;
    EXPECT_LE(std::stoul(row.at("output_faces")), 51u) << run;
    EXPECT_EQ(row.at("valid"), "true") << run;
    EXPECT_EQ(row.at("scaling").empty(), row.at("threads") != "2") << run;
    const bool measured = row.at("input_read") == "whole";
    for (const char* field : {"mean_a_to_b", "mean_b_to_a", "hausdorff", "samples"})
      EXPECT_EQ(row.at(field).empty(), !measured) << run << " " << field;
  }
  // The output of an out-of-core row is simplify --out-of-core's.
  const fs::path simplified = out / "fast.ply";
  const std::string json_path = simplified.string() + ".json";
  ASSERT_EQ(run_command(std::string(CGAL_POLICIES_BIN_DIR) + "/simplify '" +
                        (inputs / "dragon128.ply").string() + "' '" + simplified.string() +
                        "' --faces 51 --policy fast --out-of-core --threads 1 --json --quiet > '" +
                        json_path + "'"),
            0);
  const std::string json = read_text(json_path);
  for (const char* field : {"input_faces", "input_vertices", "output_faces", "output_vertices"})
    EXPECT_EQ(json_number(json, field), std::stod(rows[10].at(field))) << field;

  const std::string report = read_text(out / "report.md");
  EXPECT_NE(report.find("## Threads"), std::string::npos);
  EXPECT_EQ(
      count_occurrences(report, "| dragon128.ply | 1% → 51 | fast, 2 threads, out of core | "), 1u)
      << report;
  EXPECT_EQ(count_occurrences(report, "\nLeft out: flat-lt+fit"), 1u) << report;
  EXPECT_EQ(count_occurrences(report, "| not measured |"), 2u) << report;
  fs::remove_all(out);
}

// The scaling of a run on 2 threads: the same row's time on 1 thread over its own, the policy's
// pass and the fit together; only beside a 1-thread run of the same row, mesh and target.
TEST(BenchScaling, IsTheOneThreadTimeOverTheRunsTime) {
  const auto record = [](std::string mesh, std::string policy, std::size_t threads, double seconds,
                         double fit_seconds) {
    apps::Run_record r;
    r.mesh = std::move(mesh);
    r.target = "1%";
    r.policy = std::move(policy);
    r.threads = threads;
    r.input_read = "whole";
    r.seconds = seconds;
    r.fit_seconds = fit_seconds;
    return r;
  };
  std::vector<apps::Run_record> records = {
      record("a.ply", "fast", 1, 10, 0),         record("a.ply", "fast", 2, 4, 0),
      record("a.ply", "flat-lt+fit", 1, 30, 10), record("a.ply", "flat-lt+fit", 2, 16, 4),
      record("a.ply", "meshopt", 0, 3, 0),       record("b.ply", "fast", 2, 5, 0)};
  apps::add_scaling(records);
  EXPECT_FALSE(records[0].scaling);
  ASSERT_TRUE(records[1].scaling);
  EXPECT_EQ(*records[1].scaling, 2.5);
  EXPECT_FALSE(records[2].scaling);
  ASSERT_TRUE(records[3].scaling);
  EXPECT_EQ(*records[3].scaling, 2.0);  // (30 + 10) / (16 + 4)
  EXPECT_FALSE(records[4].scaling);
  EXPECT_FALSE(records[5].scaling);  // no run of b.ply on one thread
}

}  // namespace
