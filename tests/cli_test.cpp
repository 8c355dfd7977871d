// The apps from the outside: exit codes, one error line naming the file, no partial output even
// when interrupted, the input never overwritten (README.md "Interfaces that others rely on"); and
// the removal of small components that simplify runs on dirty scans; the OFF and PLY readers.
#include "test_meshes.h"

#include "common/App_error.h"
#include "common/clean_triangle_soup.h"
#include "common/gltf_io.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/obj_writer.h"
#include "common/polygon_crossing.h"
#include "common/small_components.h"
#include "common/soup_readers.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>

#include <cgal_policies/Corner_attributes.h>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <thread>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Command_result {
  int exit_code;
  std::string out, err;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class Cli : public testing::Test {
 protected:
  void SetUp() override {
    // The process id too, as viewer_test and bench_test do: two builds' suites may run at once.
    m_dir = fs::path(testing::TempDir()) /
            ("cli_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) +
             "_" + std::to_string(::getpid()));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }

  fs::path file(const std::string& name) const { return m_dir / name; }

  fs::path write(const std::string& name, const std::string& contents) const {
    std::ofstream(file(name), std::ios::binary) << contents;
    return file(name);
  }

  Command_result run(const std::string& app, const std::string& args) const {
    const std::string command = std::string(CGAL_POLICIES_BIN_DIR) + "/" + app + " " + args + " >" +
                                file("stdout").string() + " 2>" + file("stderr").string();
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(file("stdout")),
            read_text(file("stderr"))};
  }

  // A failure: the expected code, exactly one line on stderr naming `path`, and no output file.
  void expect_failure(const std::string& args, int code, const fs::path& named,
                      const fs::path& output) const {
    const Command_result r = run("simplify", args);
    EXPECT_EQ(r.exit_code, code) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(named.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(output));
    for (const auto& entry : fs::directory_iterator(m_dir))
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
          << "temporary file left behind: " << entry.path();
  }

  fs::path m_dir;
};

const char* const kTetrahedronOff =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

TEST_F(Cli, SimplifiesATinyMeshAndReportsJson) {
  const fs::path in = write("tet.off", kTetrahedronOff), out = file("out.obj");
  const Command_result r = run("simplify", in.string() + " " + out.string() + " 1 --json --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
  for (const char* field : {"\"policy\": \"classic\"", "\"input_faces\": 4", "\"output_faces\": 4",
                            "\"output_vertices\": 4", "\"seconds\": ", "\"stop_reason\": "})
    EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing in " << r.out;
}

TEST_F(Cli, AnEmptyFileIsBadInput) {
  const fs::path in = write("empty.off", ""), out = file("out.off");
  expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
}

TEST_F(Cli, RandomBytesAreBadInput) {
  std::string noise;
  unsigned state = 12345;
  for (int i = 0; i < 4096; ++i) noise += char((state = state * 1103515245u + 12345u) >> 16);
  for (const char* name : {"noise.ply", "noise.off", "noise.obj", "noise.stl"}) {
    const fs::path in = write(name, noise), out = file("out.off");
    expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
  }
}

TEST_F(Cli, ATruncatedBinaryPlyIsBadInput) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float "
      "y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const float points[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  ply.append(reinterpret_cast<const char*>(points), sizeof points);
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    ply += char(3);
    ply.append(reinterpret_cast<const char*>(f), sizeof f);
  }
  const fs::path whole = write("whole.ply", ply), out = file("out.off");
  ASSERT_EQ(run("simplify", whole.string() + " " + out.string() + " 1 --quiet").exit_code, 0);
  fs::remove(out);
  const fs::path in = write("truncated.ply", ply.substr(0, ply.size() - 20));
  expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
}

TEST_F(Cli, NonFiniteCoordinatesAreBadInput) {
  const fs::path in = write("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n");
  const fs::path out = file("out.off");
  expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
  const fs::path inf = write("inf.obj", "v 0 0 0\nv 1 0 0\nv inf 1 0\nf 1 2 3\n");
  expect_failure(inf.string() + " " + out.string() + " 0.5", 3, inf, out);
}

TEST_F(Cli, AnOutOfRangeFaceIndexIsBadInput) {
  const fs::path in = write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  const fs::path out = file("out.off");
  expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
}

TEST_F(Cli, AMissingFileIsBadInput) {
  const fs::path in = file("missing.obj"), out = file("out.off");
  expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
}

TEST_F(Cli, AnUnwritableOutputFolderFailsWithCodeFourAndNoFile) {
  const fs::path in = write("tet.off", kTetrahedronOff);
  const fs::path out = file("no_such_folder") / "out.off";
  expect_failure(in.string() + " " + out.string() + " 1", 4, out, out);
}

TEST_F(Cli, TheInputIsNeverOverwrittenWithoutForce) {
  const fs::path in = write("tet.off", kTetrahedronOff);
  const Command_result r = run("simplify", in.string() + " " + in.string() + " 1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_text(in), kTetrahedronOff);
  EXPECT_EQ(run("simplify", in.string() + " " + in.string() + " 1 --force --quiet").exit_code, 0);
}

TEST_F(Cli, BadUsageGivesCodeTwo) {
  const fs::path in = write("tet.off", kTetrahedronOff), out = file("out.off");
  for (const std::string& args :
       {in.string() + " " + out.string() + " 1.5", in.string() + " " + out.string(),
        in.string() + " " + out.string() + " 0.5 --policy nonsense",
        in.string() + " " + out.string() + " 0.5 --no-such-option",
        in.string() + " " + file("out.xyz").string() + " 0.5"}) {
    const Command_result r = run("simplify", args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Cli, OptionsOutOfRangeAreRefusedBeforeTheInputIsRead) {
  // The input does not exist: a check made after reading would give code 3, not 2.
  const fs::path in = file("missing.off"), out = file("out.off");
  const std::string io = in.string() + " " + out.string() + " 0.5 ";
  // The policy, the option the error line must name, its value.
  const std::vector<std::array<std::string, 3>> cases = {{"hausdorff", "--tolerance", "-1"},
                                                         {"hausdorff", "--tolerance", "0"},
                                                         {"hausdorff", "--steps", "0"},
                                                         {"hausdorff", "--steps", "2.5"},
                                                         {"fast", "--aggressiveness", "0"},
                                                         {"classic", "--border-weight", "-1"},
                                                         {"curvature", "--eps", "-0.1"},
                                                         {"fusion", "--mu", "-2"},
                                                         {"classic", "--max-normal-angle", "200"},
                                                         {"fast", "--max-error", "0.01"}};
  for (const auto& [policy, option, value] : cases) {
    const Command_result r =
        run("simplify", io + "--policy " + policy + " " + option + " " + value);
    EXPECT_EQ(r.exit_code, 2) << policy << " " << option << " " << value << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos)
        << "the line names " << option << ": " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// Counts beyond what a size_t or an int holds, and time limits beyond what the clock holds, are
// refused, not converted (that conversion is undefined behaviour, which UBSan reports in the
// sanitized build).
TEST_F(Cli, CountsTooLargeForTheirTypeAreRefused) {
  const fs::path in = file("missing.off"), out = file("out.off");
  const std::string io = in.string() + " " + out.string() + " ";
  for (const auto& [option, arguments] : std::vector<std::pair<std::string, std::string>>{
           {"--faces", "--faces 1e30"},
           {"--samples", "0.5 --samples 1e30"},
           {"--min-component", "0.5 --min-component 1e30"},
           {"--smooth", "0.5 --smooth 1e30"},
           {"--time-limit", "0.5 --time-limit 1e300"},
           {"--fit-rounds", "0.5 --fit --fit-rounds 1e30"}}) {
    const Command_result r = run("simplify", io + arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << ": " << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Cli, MeshErrorBetweenAFileAndItselfIsZero) {
  const fs::path in = write("tet.off", kTetrahedronOff);
  const Command_result r =
      run("mesh_error", in.string() + " " + in.string() + " --json --samples 1000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch hausdorff;  // zero up to the round-off of points built on the faces
  ASSERT_TRUE(std::regex_search(r.out, hausdorff, std::regex("\"hausdorff\": ([-+.e0-9]+),")));
  EXPECT_LE(std::stod(hausdorff[1]), 1e-12);
  EXPECT_NE(r.out.find("\"valid\": true"), std::string::npos) << r.out;
  EXPECT_EQ(run("mesh_error", in.string() + " " + file("missing.off").string()).exit_code, 3);
}

// A number field of an app's JSON object; NaN when missing.
double json_number(const std::string& json, const std::string& field) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + field + "\": ([-+.e0-9]+)")))
    return std::nan("");
  return std::stod(match[1]);
}

TEST_F(Cli, MeshErrorComparesCornerAttributesWhenAsked) {
  const std::string spot = test_meshes::data_file("spot.obj");
  const Command_result same =
      run("mesh_error", spot + " " + spot + " --attributes --json --samples 20000");
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_LE(json_number(same.out, "uv_mean_rel"), 1e-12) << same.out;
  EXPECT_LE(json_number(same.out, "uv_max_rel"), 1e-12) << same.out;
  EXPECT_EQ(json_number(same.out, "flipped_uv_faces"), 0) << same.out;
  EXPECT_EQ(json_number(same.out, "seam_edges_a"), 288) << same.out;
  EXPECT_EQ(json_number(same.out, "seam_edges_b"), 288) << same.out;
  EXPECT_EQ(json_number(same.out, "seam_loops_a"), 1) << same.out;
  EXPECT_EQ(json_number(same.out, "seam_loops_b"), 1) << same.out;
  EXPECT_EQ(same.out.find("normal_angle"), std::string::npos) << same.out;  // spot has no normals
  // Not asked, or nothing to compare: no attribute field.
  const Command_result plain = run("mesh_error", spot + " " + spot + " --json --samples 1000");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const fs::path tet = write("tet.off", kTetrahedronOff);
  const Command_result bare =
      run("mesh_error", tet.string() + " " + tet.string() + " --attributes --json --samples 1000");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  for (const Command_result* r : {&plain, &bare})
    for (const char* field : {"\"uv_", "\"normal_angle", "\"seam_", "\"flipped_uv_faces\""})
      EXPECT_EQ(r->out.find(field), std::string::npos) << field << " in " << r->out;
  EXPECT_NE(bare.out.find("\"valid\": true"), std::string::npos) << bare.out;
}

TEST_F(Cli, ASnapshotThatCannotBeWrittenLeavesNoMeshEither) {
  // Builds without the viewer refuse --snapshot as bad usage, before reading anything.
  const bool with_viewer =
      run("simplify", "--help").out.find("not in this build") == std::string::npos;
  const fs::path in = write("tet.off", kTetrahedronOff), out = file("out.off");
  const fs::path png = file("no_such_folder") / "picture.png";
  expect_failure(in.string() + " " + out.string() + " 1 --snapshot " + png.string(),
                 with_viewer ? 4 : 2, png, out);
  EXPECT_FALSE(fs::exists(file("no_such_folder")));
  if (!with_viewer) return;
  // The picture comes first: an OUT that existed is not replaced when it fails.
  const fs::path kept = write("kept.off", "an older output");
  EXPECT_EQ(run("simplify", in.string() + " " + kept.string() + " 1 --snapshot " + png.string())
                .exit_code,
            4);
  std::ifstream older(kept);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(older), {}), "an older output");
}

TEST_F(Cli, MaxErrorBoundsEveryEdgeCollapsePolicy) {
  // A sphere of 1,280 faces: curved everywhere, so the bound must stop every policy early, and
  // small enough for the sanitized build.
  const fs::path sphere = file("sphere.off");
  test_meshes::Mesh input = test_meshes::loop_sphere(3);
  ASSERT_TRUE(
      CGAL::IO::write_polygon_mesh(sphere.string(), input, CGAL::parameters::stream_precision(17)));
  const fs::path out = file("sphere_out.off");
  for (const char* policy : {"gh", "classic", "curvature"}) {
    const std::string args = sphere.string() + " " + out.string() + " --ratio 0.01 --policy " +
                             policy + " --json --quiet --measure --samples 20000";
    const Command_result bounded = run("simplify", args + " --max-error 0.002");
    ASSERT_EQ(bounded.exit_code, 0) << policy << ": " << bounded.err;
    EXPECT_NE(bounded.out.find("\"stop_reason\": \"error_bound_reached\""), std::string::npos)
        << policy << ": " << bounded.out;
    EXPECT_NE(bounded.out.find("\"valid\": true"), std::string::npos) << policy;
    EXPECT_LE(json_number(bounded.out, "hausdorff"),
              0.002 * json_number(bounded.out, "bbox_diagonal"))
        << policy;
    const Command_result free = run("simplify", args);
    ASSERT_EQ(free.exit_code, 0) << policy << ": " << free.err;
    EXPECT_LT(json_number(free.out, "output_faces"), json_number(bounded.out, "output_faces"))
        << policy;
    EXPECT_GT(json_number(free.out, "hausdorff"), 0.002 * json_number(free.out, "bbox_diagonal"))
        << policy << ": the bound must have been needed";
  }
}

TEST_F(Cli, FitIsReportedAndTwoRunsWriteTheSameBytes) {
  // A small sphere, so that the sanitized build runs it in seconds.
  const fs::path sphere = file("sphere.off");
  const test_meshes::Mesh small = test_meshes::loop_sphere(2);
  ASSERT_TRUE(
      CGAL::IO::write_polygon_mesh(sphere.string(), small, CGAL::parameters::stream_precision(17)));
  std::string written[2];
  for (int run_index = 0; run_index < 2; ++run_index) {
    const fs::path out = file("sphere_" + std::to_string(run_index) + ".ply");
    const Command_result r =
        run("simplify", sphere.string() + " " + out.string() +
                            " 0.25 --policy lt --fit --fit-rounds 2 --json --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* field : {"\"fit_seconds\": ", "\"fit_rounds\": 2,",
                              "\"fit_flips\": ", "\"fit_moves\": ", "\"output_faces\": 80,"})
      EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing in " << r.out;
    written[run_index] = read_text(out);
  }
  EXPECT_FALSE(written[0].empty());
  EXPECT_TRUE(written[0] == written[1]) << "two fitted runs wrote different files";
  const fs::path in = write("tet.off", kTetrahedronOff), out = file("out.off");
  expect_failure(in.string() + " " + out.string() + " 1 --fit-rounds 2", 2, "--fit-rounds", out);
  expect_failure(in.string() + " " + out.string() + " 1 --fit --fit-rounds 0", 2, "--fit-rounds",
                 out);
}

TEST_F(Cli, TheFastPolicyRefusesMaxError) {
  const fs::path in = write("tet.off", kTetrahedronOff), out = file("out.off");
  const Command_result r =
      run("simplify", in.string() + " " + out.string() + " 0.5 --policy fast --max-error 0.01");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--max-error"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, TheBunnyAtTenPercentWithGhReachesItsTarget) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path out = file("bunny.ply");
  const Command_result r =
      run("simplify", test_meshes::data_file("bunny.obj") + " " + out.string() +
                          " 0.1 --policy gh --json --measure --samples 20000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch faces;
  ASSERT_TRUE(std::regex_search(r.out, faces, std::regex("\"output_faces\": ([0-9]+)")));
  EXPECT_NEAR(std::stod(faces[1]), 6945, 69.45);
  EXPECT_NE(r.out.find("\"valid\": true"), std::string::npos);
  EXPECT_NE(r.out.find("\"stop_reason\": \"target_reached\""), std::string::npos);
}

TEST_F(Cli, TheTargetIsCheckedBeforeTheInputIsRead) {
  const fs::path in = file("missing.off"), out = file("out.off");
  const std::vector<std::array<std::string, 2>> cases = {
      {"--faces", "0"},          {"--faces", "2.5"},        {"--ratio", "0"},
      {"--ratio", "1.5"},        {"--samples", "2.5"},      {"--time-limit", "-1"},
      {"--min-component", "-3"}, {"--min-component", "2.5"}};
  for (const auto& [option, value] : cases) {
    const std::string target = option == "--faces" || option == "--ratio" ? "" : " --faces 10";
    const Command_result r =
        run("simplify", in.string() + " " + out.string() + " " + option + " " + value + target);
    EXPECT_EQ(r.exit_code, 2) << option << " " << value << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
  }
  const Command_result fast =
      run("simplify", in.string() + " " + out.string() + " 0.5 --policy fast --time-limit 1");
  EXPECT_EQ(fast.exit_code, 2) << fast.err;
  EXPECT_NE(fast.err.find("--time-limit"), std::string::npos) << fast.err;
}

TEST_F(Cli, AMissingOutputFolderIsRefusedBeforeTheInputIsRead) {
  // The input does not exist: a check made after reading would give code 3, not 4.
  const fs::path in = file("missing.off"), folder = file("no_such_folder");
  const fs::path out = folder / "out.off";
  expect_failure(in.string() + " " + out.string() + " 0.5", 4, out, out);
  const bool with_viewer =
      run("simplify", "--help").out.find("not in this build") == std::string::npos;
  if (!with_viewer) return;  // --snapshot is then bad usage, before reading too
  const fs::path png = folder / "picture.png";
  expect_failure(in.string() + " " + file("out.off").string() + " 0.5 --snapshot " + png.string(),
                 4, png, file("out.off"));
}

TEST_F(Cli, ATimeLimitStopsTheRunWhereItIs) {
  const fs::path out = file("cow.off");
  // Long past at the first collapse: the queue alone takes longer to build.
  const Command_result r = run("simplify", test_meshes::data_file("cow.obj") + " " + out.string() +
                                               " 0.1 --time-limit 1e-9 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"stop_reason\": \"time_limit\""), std::string::npos) << r.out;
  EXPECT_EQ(json_number(r.out, "output_faces"), json_number(r.out, "input_faces")) << r.out;
  EXPECT_EQ(json_number(r.out, "time_limit_seconds"), 1e-9) << r.out;
  EXPECT_EQ(apps::read_triangle_mesh(out.string()).number_of_faces(),
            json_number(r.out, "input_faces"));
  const Command_result unlimited = run("simplify", test_meshes::data_file("cow.obj") + " " +
                                                       out.string() + " 0.1 --time-limit 0 --json");
  ASSERT_EQ(unlimited.exit_code, 0) << unlimited.err;
  EXPECT_NE(unlimited.out.find("\"stop_reason\": \"target_reached\""), std::string::npos);
}

TEST_F(Cli, HeaderCountsBeyondTheFileAreBadInputBeforeAnyAllocation) {
  const fs::path out = file("out.off");
  const fs::path off = write("huge.off", "OFF\n2000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
      "y\nproperty float z\nelement face 1000000000\nproperty list uchar int "
      "vertex_indices\nend_header\n";
  const float points[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  ply.append(reinterpret_cast<const char*>(points), sizeof points);
  const int triangle[3] = {0, 1, 2};
  ply += char(3);
  ply.append(reinterpret_cast<const char*>(triangle), sizeof triangle);
  const fs::path binary_ply = write("huge.ply", ply);
  std::string stl(80, ' ');
  const std::uint32_t triangles = 100000000;  // little-endian, as the format wants
  for (int byte = 0; byte < 4; ++byte) stl += char((triangles >> (8 * byte)) & 0xff);
  const fs::path binary_stl = write("huge.stl", stl);
  for (const fs::path& in : {off, binary_ply, binary_stl}) {
    expect_failure(in.string() + " " + out.string() + " 0.5", 3, in, out);
    EXPECT_NE(run("simplify", in.string() + " " + out.string() + " 0.5").err.find("declares"),
              std::string::npos)
        << in;
  }
}

TEST_F(Cli, HeaderCountsThatFitTheFileAreRead) {
  const fs::path out = file("out.off");
  const fs::path ascii_ply = write("tet.ply",
                                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                   "property float y\nproperty float z\nelement face 4\nproperty "
                                   "list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 "
                                   "0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3");
  std::string stl(80, ' ');
  stl += std::string("\x04\x00\x00\x00", 4);
  const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    const float normal[3] = {0, 0, 0};
    stl.append(reinterpret_cast<const char*>(normal), sizeof normal);
    for (int corner : f) stl.append(reinterpret_cast<const char*>(corners[corner]), 12);
    stl += std::string(2, '\0');  // the attribute byte count
  }
  const fs::path binary_stl = write("tet.stl", stl);
  for (const fs::path& in : {write("tet.off", kTetrahedronOff), ascii_ply, binary_stl}) {
    const Command_result r = run("simplify", in.string() + " " + out.string() + " 1 --json");
    ASSERT_EQ(r.exit_code, 0) << in << ": " << r.err;
    EXPECT_EQ(json_number(r.out, "output_faces"), 4) << in;
  }
}

// The argv execv wants, pointing into `args`.
std::vector<char*> argv_of(std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

// simplify ARGS in a child process, its output thrown away, killed by `signal` after `delay`
// (or not at all with a zero signal); its exit status.
int run_and_kill(std::vector<std::string> args, int signal, std::chrono::microseconds delay) {
  const std::string app = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify";
  args.insert(args.begin(), app);
  const std::vector<char*> argv = argv_of(args);
  const pid_t child = ::fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(app.c_str(), argv.data());
    ::_exit(127);
  }
  if (signal != 0) {
    std::this_thread::sleep_for(delay);
    ::kill(child, signal);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

// How many times InterruptedRunsLeaveTheOldOutputOrTheCompleteNewOne kills simplify:
// scripts/kill_test.sh N runs it N times.
int kill_count() {
  const char* count = std::getenv("CGAL_POLICIES_KILLS");
  return count ? std::atoi(count) : 40;
}

TEST_F(Cli, InterruptedRunsLeaveTheOldOutputOrTheCompleteNewOne) {
  // The cow: short enough for tens of runs; OFF, the slowest format to write.
  const std::string cow = test_meshes::data_file("cow.obj");
  const fs::path out = file("cow.off"), reference = file("reference.off");
  const std::vector<std::string> options = {"0.5", "--quiet"};
  std::vector<std::string> args = {cow, reference.string()};
  args.insert(args.end(), options.begin(), options.end());
  const auto start = std::chrono::steady_clock::now();
  const int reference_status = run_and_kill(args, 0, {});
  const auto whole_run = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now() - start);
  ASSERT_TRUE(WIFEXITED(reference_status) && WEXITSTATUS(reference_status) == 0);
  const std::string complete = read_text(reference);
  // The mesh the run writes is whole: every face of the target is there.
  EXPECT_EQ(apps::read_triangle_mesh(reference.string()).number_of_faces(),
            std::llround(0.5 * double(apps::read_triangle_mesh(cow).number_of_faces())));

  const std::string old_output = "an older output";
  args[1] = out.string();
  std::mt19937 random(15);
  // Over the whole run and a little after, so that every stage is hit: reading, simplifying,
  // writing the temporary, renaming it, exiting.
  std::uniform_int_distribution<long> delay_us(0, whole_run.count() * 11 / 10);
  int unguarded = 0, interrupted = 0, finished = 0, replaced = 0;
  for (int kill = 0; kill < kill_count(); ++kill) {
    std::ofstream(out, std::ios::binary) << old_output;
    const int signal = kill % 2 ? SIGTERM : SIGINT;
    const int status = run_and_kill(args, signal, std::chrono::microseconds(delay_us(random)));
    const std::string left = read_text(out);
    if (WIFSIGNALED(status)) {
      // Before main() installed the handlers: nothing was written yet.
      ++unguarded;
      EXPECT_EQ(WTERMSIG(status), signal) << "kill " << kill;
      EXPECT_EQ(left, old_output) << "kill " << kill;
      continue;
    }
    const int code = WEXITSTATUS(status);
    if (code == 0) {
      ++finished;
      EXPECT_EQ(left, complete) << "kill " << kill;
    } else {
      ++interrupted;
      EXPECT_EQ(code, 128 + signal) << "kill " << kill;
      EXPECT_TRUE(left == old_output || left == complete)
          << "kill " << kill << ": " << left.size() << " bytes";
    }
    replaced += left == complete;
    for (const auto& entry : fs::directory_iterator(m_dir))
      ASSERT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
          << "kill " << kill << " left " << entry.path();
  }
  std::printf(
      "%d kills: %d before main(), %d interrupted (%d after the new output was in place), %d "
      "finished\n",
      kill_count(), unguarded, interrupted, replaced - finished, finished);
  EXPECT_GT(interrupted, 0);
}

// simplify `args` in a child process that stops half-way through writing OUT's temporary file,
// which is a FIFO made beforehand under the name the child will give it (a FIFO holds 64 KiB
// unread), then `signal`; its exit status once it has ended.
int interrupt_while_writing(std::vector<std::string> args, const fs::path& out, int signal) {
  const std::string app = std::string(CGAL_POLICIES_BIN_DIR) + "/simplify";
  args.insert(args.begin(), app);
  const std::vector<char*> argv = argv_of(args);
  int go[2];
  if (::pipe(go) != 0) return -1;
  const pid_t child = ::fork();
  if (child == 0) {
    char byte;
    ::close(go[1]);
    if (::read(go[0], &byte, 1) != 1) ::_exit(126);  // not before the FIFO exists
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(app.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(go[0]);
  const fs::path fifo = out.parent_path() / ("." + out.stem().string() + ".tmp-" +
                                             std::to_string(child) + out.extension().string());
  const bool made = ::mkfifo(fifo.c_str(), 0600) == 0;
  const int reader = made ? ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK) : -1;
  [[maybe_unused]] const ssize_t sent = ::write(go[1], "g", 1);
  ::close(go[1]);
  // The first bytes of the mesh: the writer is at work, and blocks once the FIFO is full.
  bool writing = false;
  // Generous: the sanitized Debug build reads, simplifies and draws the cow for about a minute.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(20);
  char bytes[16];
  while (reader >= 0 && !writing && std::chrono::steady_clock::now() < deadline) {
    writing = ::read(reader, bytes, sizeof bytes) > 0;
    if (!writing) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(child, writing ? signal : SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (reader >= 0) ::close(reader);  // only now: a writer alone would get SIGPIPE
  return writing ? status : -1;
}

TEST_F(Cli, AnInterruptWhileWritingLeavesTheOldOutputAndNoTemporary) {
  const bool with_viewer =
      run("simplify", "--help").out.find("not in this build") == std::string::npos;
  const fs::path out = file("cow.off"), png = file("cow.png");
  const std::string old_output = "an older output";
  for (const int signal : {SIGINT, SIGTERM}) {
    std::ofstream(out, std::ios::binary) << old_output;
    std::vector<std::string> args = {test_meshes::data_file("cow.obj"), out.string(), "0.5"};
    // With the viewer, the picture is in place when the mesh is written: it must go too.
    const bool picture = with_viewer && signal == SIGTERM;
    if (picture) args.insert(args.end(), {"--snapshot", png.string(), "--size", "64x32"});
    const int status = interrupt_while_writing(args, out, signal);
    ASSERT_TRUE(WIFEXITED(status)) << signal << ": status " << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    EXPECT_EQ(read_text(out), old_output);
    EXPECT_FALSE(fs::exists(png));
    for (const auto& entry : fs::directory_iterator(m_dir))
      EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
          << "temporary file left behind: " << entry.path();
  }
}

// Three components: a tetrahedron (4 faces), an icosahedron (20), a 3 x 3 grid (18) and a lone
// triangle (1), 43 faces.
test_meshes::Mesh dirty_scan() {
  test_meshes::Mesh mesh = test_meshes::tetrahedron();
  CGAL::copy_face_graph(test_meshes::icosahedron(), mesh);
  CGAL::copy_face_graph(test_meshes::flat_grid(3), mesh);
  CGAL::copy_face_graph(test_meshes::from_triangles({{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}, {{0, 1, 2}}),
                        mesh);
  return mesh;
}

TEST(SmallComponents, DroppedBelowASizeButTheLargest) {
  test_meshes::Mesh mesh = dirty_scan();
  ASSERT_EQ(mesh.number_of_faces(), 43u);
  const apps::Dropped_components specks = apps::drop_components_smaller_than(mesh, 5);
  EXPECT_EQ(specks.components, 2u);
  EXPECT_EQ(specks.faces, 5u);
  EXPECT_EQ(mesh.number_of_faces(), 38u);
  EXPECT_FALSE(mesh.has_garbage());
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
  const apps::Dropped_components all = apps::drop_components_smaller_than(mesh, 1000);
  EXPECT_EQ(all.components, 1u);
  EXPECT_EQ(all.faces, 18u);
  EXPECT_EQ(mesh.number_of_faces(), 20u);  // the icosahedron, the largest, stays
  EXPECT_EQ(apps::drop_components_smaller_than(mesh, 0).components, 0u);
}

TEST(SmallComponents, DroppedSmallestFirstUntilTheTarget) {
  test_meshes::Mesh mesh = dirty_scan();
  const apps::Dropped_components none = apps::drop_smallest_components_until(mesh, 43);
  EXPECT_EQ(none.components, 0u);
  EXPECT_EQ(mesh.number_of_faces(), 43u);
  const apps::Dropped_components some = apps::drop_smallest_components_until(mesh, 40);
  EXPECT_EQ(some.components, 2u);  // the triangle, then the tetrahedron
  EXPECT_EQ(some.faces, 5u);
  EXPECT_EQ(mesh.number_of_faces(), 38u);
  const apps::Dropped_components rest = apps::drop_smallest_components_until(mesh, 0);
  EXPECT_EQ(rest.components, 1u);
  EXPECT_EQ(mesh.number_of_faces(), 20u);
  EXPECT_TRUE(test_meshes::is_valid_triangle_mesh(mesh));
}

// Two tetrahedra, which no collapse can simplify, and nothing else.
const char* const kTwoTetrahedraOff =
    "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n";

TEST_F(Cli, SmallPiecesAreDroppedOnlyWhenAsked) {
  const fs::path in = write("two.off", kTwoTetrahedraOff), out = file("out.off");
  const std::string io = in.string() + " " + out.string() + " --json --quiet --faces ";
  // A run the policy ended with no collapse left: its faces, distance to the target, pieces gone.
  const auto expect_stopped = [&](const Command_result& r, double faces, double gap,
                                  double vanished) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"stop_reason\": \"no_collapse_left\""), std::string::npos);
    EXPECT_EQ(json_number(r.out, "output_faces"), faces);
    EXPECT_EQ(json_number(r.out, "target_gap_faces"), gap);
    EXPECT_EQ(json_number(r.out, "vanished_components"), vanished);
  };
  expect_stopped(run("simplify", io + "4"), 8, 4, 0);

  const Command_result dropped = run("simplify", io + "4 --drop-small-pieces");
  expect_stopped(dropped, 4, 0, 1);
  EXPECT_EQ(json_number(dropped.out, "vanished_faces"), 4);
  EXPECT_EQ(apps::read_triangle_mesh(out.string()).number_of_faces(), 4u);

  const Command_result last = run("simplify", io + "1 --drop-small-pieces");
  ASSERT_EQ(last.exit_code, 0) << last.err;
  EXPECT_EQ(json_number(last.out, "output_faces"), 4);  // the last piece stays
  EXPECT_EQ(json_number(last.out, "target_gap_faces"), 3);

  const Command_result before = run("simplify", io + "8 --min-component 5");
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_EQ(json_number(before.out, "min_component"), 5);
  EXPECT_EQ(json_number(before.out, "dropped_components"), 1);
  EXPECT_EQ(json_number(before.out, "dropped_component_faces"), 4);
  EXPECT_EQ(json_number(before.out, "output_faces"), 4);
}

}  // namespace

// The OFF and PLY readers (apps/common/soup_readers.h), on hand-written files.
namespace readers {

using apps::Polygon_soup;
using Polygons = std::vector<std::vector<std::size_t>>;

std::vector<std::array<double, 3>> coordinates(const Polygon_soup& soup) {
  std::vector<std::array<double, 3>> result;
  for (const apps::Point& p : soup.points) result.push_back({p.x(), p.y(), p.z()});
  return result;
}

const std::vector<std::array<double, 3>> kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

void expect_square(const Polygon_soup& soup, const Polygons& polygons) {
  EXPECT_EQ(coordinates(soup), kSquare);
  EXPECT_EQ(soup.polygons, polygons);
}

// The cause of the bad-input error that parsing `bytes` gives; "" when it parses.
template <typename Parse>
std::string refusal(Parse parse, const std::string& bytes) {
  try {
    parse("f", bytes);
  } catch (const apps::App_error& e) {
    EXPECT_EQ(e.code(), apps::exit_bad_input);
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("f: ", 0), 0u) << message;
    return message;
  }
  return "";
}

TEST(Readers, ObjCornersWithTexturesNormalsAndNegativeIndices) {
  const Polygon_soup soup =
      apps::parse_obj("f",
                      "# a square\nmtllib a.mtl\nv 0 0 0\nv 1 0 0 1.0\nv +1 1 0e0 0.5 0.5 0.5\r\n"
                      "vt 0 0\nvn 0 0 1\ng square\nusemtl red\nf 1/1/1 2/1/1 3//1\n"
                      "v 0 1 0 # last\nl 1 2\nf -4 -2 -1\n");
  expect_square(soup, {{0, 1, 2}, {0, 2, 3}});
}

TEST(Readers, OffSkipsCommentsColoursAndNormals) {
  const Polygon_soup soup =
      apps::parse_off("f",
                      "# a square\nCOFF 4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255 # red\n\n"
                      "+1 1 0e0 0 0 255 255\n0 1 0 1 1 1 1\n3 0 1 2 0.5 0.5 0.5\n3 0 2 3\n");
  expect_square(soup, {{0, 1, 2}, {0, 2, 3}});
}

TEST(Readers, PlyAsciiSkipsOtherPropertiesAndElements) {
  const Polygon_soup soup = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\nproperty double x\n"
      "property float nx\nproperty float y\nproperty float z\nelement face 1\n"
      "property uchar flags\nproperty list uchar int vertex_indices\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nend_header\n"
      "0 9 0 0\n1 9 0 0\n1 9 1 0\n0 9 1 0\n7 4 0 1 2 3\n0 2\n");
  expect_square(soup, {{0, 1, 2, 3}});
}

// The same square in both byte orders, with a uint16 list count and uint32 indices.
std::string binary_square(bool big_endian) {
  std::string bytes = std::string("ply\nformat binary_") + (big_endian ? "big" : "little") +
                      "_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 2\n"
                      "property list ushort uint vertex_indices\nend_header\n";
  const auto append = [&](const void* value, std::size_t size) {
    std::string raw(static_cast<const char*>(value), size);
    if (big_endian) std::reverse(raw.begin(), raw.end());
    bytes += raw;
  };
  for (const auto& p : kSquare)
    for (double c : p) {
      const float f = float(c);
      append(&f, 4);
    }
  for (const std::array<std::uint32_t, 3>& face :
       {std::array<std::uint32_t, 3>{0, 1, 2}, std::array<std::uint32_t, 3>{0, 2, 3}}) {
    const std::uint16_t count = 3;
    append(&count, 2);
    for (std::uint32_t index : face) append(&index, 4);
  }
  return bytes;
}

TEST(Readers, PlyBinaryInBothByteOrders) {
  for (bool big_endian : {false, true}) {
    expect_square(apps::parse_ply("f", binary_square(big_endian)), {{0, 1, 2}, {0, 2, 3}});
  }
}

// Stanford's scans store faces as strips: every other triangle is turned back, -1 restarts, and
// the degenerate triangles that turn a strip are left out.
TEST(Readers, PlyTristripsBecomeTrianglesFacingOneWay) {
  const Polygon_soup soup = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 5 0\n6 5 0\n5 6 0\n"
      "10 0 1 2 3 3 -1 4 5 6 6\n");
  EXPECT_EQ(soup.polygons, (Polygons{{0, 1, 2}, {2, 1, 3}, {4, 5, 6}}));
}

TEST(Readers, MalformedFilesAreOneBadInputLine) {
  const auto off = [](const std::string& source, const std::string& bytes) {
    return apps::parse_off(source, bytes);
  };
  const auto ply = [](const std::string& source, const std::string& bytes) {
    return apps::parse_ply(source, bytes);
  };
  const auto obj = [](const std::string& source, const std::string& bytes) {
    return apps::parse_obj(source, bytes);
  };
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv inf 1\nf 1 2 3\n"), "");  // two coordinates
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 1,5 1 0\nf 1 2 3\n"), "");
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "");   // indices start at 1
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), "");  // back too far
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n"), "");
  EXPECT_NE(refusal(obj, "v 0 0 0\nv 1 0 0\nf 1 2\n"), "");  // two corners
  EXPECT_EQ(refusal(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
  EXPECT_NE(refusal(off, "OFF\n4 1 0\n0 0 0\n"), "");                          // truncated
  EXPECT_NE(refusal(off, "OFF\n900000 1 0\n0 0 0\n"), "");                     // forged count
  EXPECT_NE(refusal(off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n"), "");  // negative index
  EXPECT_NE(refusal(off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1.2 0 1\n"), "");  // bad corner count
  EXPECT_NE(refusal(off, "4OFF\n"), "");
  std::string cut = binary_square(false);
  cut.resize(cut.size() - 3);
  EXPECT_NE(refusal(ply, cut), "");
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nelement vertex 1\n"), "");  // no end_header
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nelemply\nend_header\n"), "");
  EXPECT_NE(refusal(ply, "ply\nformat ascii 1.0\nproperty float x\nend_header\n"), "");
  EXPECT_NE(refusal(ply,
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"),
            "");  // a negative index outside a strip
  EXPECT_NE(refusal(ply,
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                    "end_header\n0 0 0\n200 0 0 0\n"),
            "");  // a list longer than the file
}

}  // namespace readers

// The reader's fast path (apps/common/clean_triangle_soup.h): it takes exactly the soups CGAL's
// check calls polygon meshes (when all are triangles), and builds the mesh CGAL's path builds.
namespace clean_soups {

using Polygons = std::vector<std::vector<std::size_t>>;
using apps::Mesh;
using apps::Point;

const std::vector<Point> kPoints = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                    {1, 1, 1}, {2, 0, 0}, {0, 2, 0}, {5, 5, 5}};

bool builds(const Polygons& polygons, Mesh& mesh, std::size_t& unused) {
  const bool built = apps::build_mesh_from_clean_triangles(kPoints, polygons, mesh, unused);
  if (!built) {
    EXPECT_TRUE(mesh.is_empty());
  }
  return built;
}

bool builds(const Polygons& polygons) {
  Mesh mesh;
  std::size_t unused = 0;
  return builds(polygons, mesh, unused);
}

// halfedge by halfedge: the same target point, face and next (a Surface_mesh's opposite is fixed).
void expect_same_connectivity(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices());
  ASSERT_EQ(a.number_of_halfedges(), b.number_of_halfedges());
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  std::size_t differences = 0;
  for (auto h : a.halfedges())
    differences += a.point(a.target(h)) != b.point(b.target(h)) || a.face(h) != b.face(h) ||
                   a.next(h) != b.next(h);
  EXPECT_EQ(differences, 0u);
}

Mesh built_by_cgal(const std::vector<Point>& points, const Polygons& polygons) {
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  CGAL::Polygon_mesh_processing::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  return mesh;
}

TEST(CleanSoups, AClosedAndAnOpenMeshAreBuiltAsCgalBuildsThem) {
  const Polygons tetrahedron = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const Polygons fan_with_unused_points = {{0, 1, 2}, {0, 2, 6}, {5, 1, 0}};  // 3, 4, 7 unused
  for (const Polygons& polygons : {tetrahedron, fan_with_unused_points}) {
    Mesh mesh;
    std::size_t unused = 0;
    ASSERT_TRUE(builds(polygons, mesh, unused));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    EXPECT_TRUE(mesh.is_valid(false));
    expect_same_connectivity(mesh, built_by_cgal(kPoints, polygons));
    for (auto v : mesh.vertices())
      EXPECT_EQ(CGAL::is_border(v, mesh).has_value(), mesh.is_border(mesh.halfedge(v)));
  }
  Mesh fan;
  std::size_t unused = 0;
  ASSERT_TRUE(builds(fan_with_unused_points, fan, unused));
  EXPECT_EQ(unused, 3u);
  EXPECT_EQ(fan.number_of_vertices(), 5u);
  EXPECT_EQ(test_meshes::border_edge_count(fan), 5u);
}

TEST(CleanSoups, SoupsThatNeedRepairAreLeftToCgal) {
  EXPECT_FALSE(builds({{0, 1, 2, 3}}));                     // not a triangle
  EXPECT_FALSE(builds({{0, 1, 1}}));                        // a corner twice
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 1, 2}}));             // a face twice
  EXPECT_FALSE(builds({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));  // an edge of three faces
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 1, 3}}));             // faces facing apart
  EXPECT_FALSE(builds({{0, 1, 2}, {0, 5, 6}}));             // a bowtie
  EXPECT_FALSE(builds({{0, 2, 1},
                       {0, 1, 3},
                       {1, 2, 3},
                       {0, 3, 2},  // two tetrahedra that
                       {0, 5, 6},
                       {0, 7, 5},
                       {5, 7, 6},
                       {0, 6, 7}}));  // share a point
}

// Every shipped mesh the fast path takes is built as CGAL builds it; the others are left whole.
TEST(CleanSoups, ShippedMeshesAreBuiltAsCgalBuildsThem) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  std::size_t taken = 0;
  for (const std::string name :
       {"alligator.obj", "bob_tri.obj", "bunny.obj", "cow.obj", "dragon.ply", "dragon_res2.ply",
        "fandisk.obj", "nefertiti.obj", "rocker-arm.obj", "spot.obj", "teapot.obj", "woody.obj"}) {
    SCOPED_TRACE(name);
    std::vector<Point> points;
    Polygons polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(test_meshes::data_file(name), points, polygons));
    const bool all_triangles =
        std::all_of(polygons.begin(), polygons.end(), [](const auto& p) { return p.size() == 3; });
    const bool cgal_takes =
        all_triangles && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
    Mesh mesh;
    std::size_t unused = 0;
    ASSERT_EQ(apps::build_mesh_from_clean_triangles(points, polygons, mesh, unused), cgal_takes);
    if (!cgal_takes) continue;
    ++taken;
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
    expect_same_connectivity(mesh, built_by_cgal(points, polygons));
  }
  EXPECT_GE(taken, 6u);
}

}  // namespace clean_soups

// ---------------------------------------------------------------------------------------------
// Polygons that cross themselves are refused before CGAL's triangulation sees them.
namespace polygon_crossing {

using apps::Point;

std::vector<Point> in_plane(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Point> corners;
  for (const auto& p : xy) corners.emplace_back(p[0], p[1], 0.0);
  return corners;
}

bool crosses(const std::vector<std::array<double, 2>>& xy) {
  return apps::polygon_crosses_itself(in_plane(xy), apps::Kernel::Vector_3(0, 0, 1));
}

TEST(PolygonCrossing, SimplePolygonsPass) {
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {3, 1}, {1, 2}, {-1, 1}}));         // convex pentagon
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}));  // an L
  EXPECT_FALSE(crosses({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));          // a corner mid-edge
  EXPECT_FALSE(crosses({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}}));          // a notch to the centre
}

TEST(PolygonCrossing, CrossingsTouchesAndFoldsAreFound) {
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {0, 2}, {2, 2}}));                    // a bowtie
  EXPECT_TRUE(crosses({{0, 2}, {2, -1}, {-1, 1}, {1, 1}, {-2, -1}}));        // a pentagram
  EXPECT_TRUE(crosses({{0, 0}, {4, 0}, {4, 2}, {2, 0}, {0, 2}}));            // a corner on an edge
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {1, 0}, {1, 1}}));                    // folds back
  EXPECT_TRUE(crosses({{0, 0}, {2, 0}, {2, 2}, {0, 0}, {-2, 2}, {-2, 0}}));  // a corner twice
}

TEST(PolygonCrossing, IsJudgedAlongTheNormal) {
  // A pentagon whose corners alternate between two heights: simple seen from above, its edges
  // cross seen from the side.
  std::vector<Point> corners = in_plane({{0, 0}, {2, 0}, {3, 1}, {1, 2}, {-1, 1}});
  for (std::size_t i = 0; i < corners.size(); ++i)
    corners[i] = Point(corners[i].x(), corners[i].y(), 0.1 * double(i % 2));
  EXPECT_FALSE(apps::polygon_crosses_itself(corners, apps::Kernel::Vector_3(0, 0, 1)));
  EXPECT_TRUE(apps::polygon_crosses_itself(corners, apps::Kernel::Vector_3(0, 1, 0)));
}

// The cause the reader gives for the soup, "" when it reads it.
std::string refusal(const std::vector<std::array<double, 2>>& xy) {
  std::vector<Point> points = in_plane(xy);
  std::vector<std::vector<std::size_t>> polygons(1);
  for (std::size_t i = 0; i < points.size(); ++i) polygons[0].push_back(i);
  try {
    const apps::Mesh mesh = apps::triangle_mesh_from_soup("soup", points, polygons);
    EXPECT_EQ(mesh.number_of_faces(), points.size() - 2);
  } catch (const apps::App_error& e) {
    EXPECT_EQ(e.code(), apps::exit_bad_input);
    return e.what();
  }
  return "";
}

TEST(PolygonCrossing, TheReaderRefusesACrossingPolygonAndTriangulatesASimpleOne) {
  EXPECT_EQ(refusal({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), "");
  EXPECT_EQ(refusal({{0, 2}, {2, -1}, {-1, 1}, {1, 1}, {-2, -1}}),
            "soup: polygon 0 crosses itself");
  EXPECT_EQ(refusal({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}), "soup: polygon 0 has no area");
}

}  // namespace polygon_crossing

// ---------------------------------------------------------------------------------------------
// Texture coordinates, normals and materials of OBJ corners: read onto the mesh, written back.
namespace corner_attributes {

using apps::Corner_tables;
using apps::Mesh;
using Attributes = cgal_policies::Corner_attributes<apps::Point>;
constexpr std::size_t kNone = Corner_tables::kNoEntry;

TEST(CornerAttributes, ObjTablesAndTheEntriesOfEachCorner) {
  const apps::Polygon_soup soup = apps::parse_obj(
      "f",
      "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nvt 0 0\nvt 1 0\n"
      "vt 1 1 0\nvn 0 0 1\nusemtl red\nf 1/1 3/-1/1 4//-1\nusemtl blue\nf 1/1/1 2/2 3\n"
      "usemtl red\nf 4 1 3\n");
  const Corner_tables& t = soup.corners;
  EXPECT_EQ(t.uvs, (std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {1, 1}}));
  ASSERT_EQ(t.normals.size(), 1u);
  EXPECT_EQ(t.normals[0], apps::Kernel::Vector_3(0, 0, 1));
  EXPECT_EQ(t.polygon_uvs,
            (std::vector<std::vector<std::size_t>>{
                {kNone, kNone, kNone}, {0, 2, kNone}, {0, 1, kNone}, {kNone, kNone, kNone}}));
  EXPECT_EQ(t.polygon_normals,
            (std::vector<std::vector<std::size_t>>{
                {kNone, kNone, kNone}, {kNone, 0, 0}, {0, kNone, kNone}, {kNone, kNone, kNone}}));
  EXPECT_EQ(t.material_libraries, (std::vector<std::string>{"a.mtl", "b.mtl"}));
  EXPECT_EQ(t.material_names, (std::vector<std::string>{"red", "blue"}));
  EXPECT_EQ(t.polygon_materials, (std::vector<std::uint32_t>{Corner_tables::kNoMaterial, 0, 1, 0}));
}

TEST(CornerAttributes, AFileWithoutThemHasEmptyLists) {
  const apps::Polygon_soup soup =
      apps::parse_obj("f", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n");
  EXPECT_TRUE(soup.corners.polygon_uvs.empty());
  EXPECT_TRUE(soup.corners.polygon_normals.empty());
  EXPECT_TRUE(soup.corners.polygon_materials.empty());
}

// A PLY file's per-vertex normals and texture coordinates become the values of every corner of
// their vertex, on the mesh and in an OBJ file written from it; one that is not finite is bad
// input.
TEST(CornerAttributes, PlyVertexNormalsAndTextureCoordinatesGoToEveryCorner) {
  const auto square = [](const std::string& third_u) {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
           "property float texture_u\nproperty float texture_v\nelement face 2\n"
           "property list uchar int vertex_indices\nend_header\n"
           "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 0.5 0\n1 1 0 0 0 1 " +
           third_u + " 0.5\n0 1 0 0 0 1 0 0.5\n3 0 1 2\n3 0 2 3\n";
  };
  const apps::Polygon_soup soup = apps::parse_ply("f", square("0.5"));
  EXPECT_EQ(soup.corners.uvs,
            (std::vector<std::array<double, 2>>{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}));
  EXPECT_EQ(soup.corners.normals, std::vector<apps::Kernel::Vector_3>(4, {0, 0, 1}));
  EXPECT_EQ(soup.corners.polygon_uvs, soup.polygons);
  EXPECT_EQ(soup.corners.polygon_normals, soup.polygons);

  const fs::path folder = fs::temp_directory_path() / ("ply_corners_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "square.ply") << square("0.5");
  const Mesh mesh = apps::read_triangle_mesh((folder / "square.ply").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  apps::write_mesh_atomically(mesh, (folder / "square.obj").string());
  const Mesh reread = apps::read_triangle_mesh((folder / "square.obj").string(), nullptr,
                                               apps::Corner_attribute_reading::keep);
  for (const Mesh* m : {&mesh, &reread}) {
    const Attributes attributes(*m);
    ASSERT_TRUE(attributes.uvs && attributes.normals);
    for (const auto h : m->halfedges()) {
      if (m->is_border(h)) continue;
      const apps::Point& p = m->point(m->target(h));
      EXPECT_EQ((*attributes.uvs)[h], (std::array<double, 2>{p.x() / 2, p.y() / 2}));
      EXPECT_EQ((*attributes.normals)[h], apps::Kernel::Vector_3(0, 0, 1));
    }
  }
  fs::remove_all(folder);

  try {
    apps::parse_ply("f", square("nan"));
    ADD_FAILURE() << "a texture coordinate of nan was read";
  } catch (const apps::App_error& e) {
    EXPECT_EQ(e.code(), apps::exit_bad_input);
    EXPECT_EQ(std::string(e.what()), "f: vertex 2: its texture coordinate is not finite");
  }
}

// Colours of PLY vertices (integer channels scaled by their type's largest value, float ones kept,
// alpha 1 when absent) and of OBJ points (r g b [a]) become the values of every corner of their
// vertex; one that is not finite is bad input.
TEST(CornerAttributes, PlyAndObjVertexColoursGoToEveryCorner) {
  const std::string triangle_faces = "element face 1\nproperty list uchar int vertex_indices\n";
  const apps::Polygon_soup bytes = apps::parse_ply(
      "f",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" +
          triangle_faces + "end_header\n0 0 0 255 0 51\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_EQ(bytes.corners.colors,
            (std::vector<std::array<double, 4>>{{1, 0, 0.2, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}}));
  EXPECT_EQ(bytes.corners.polygon_colors, bytes.polygons);
  const auto float_ply = [&](const std::string& first_red) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nproperty float diffuse_red\nproperty float diffuse_green\n"
           "property float diffuse_blue\nproperty float diffuse_alpha\n" +
           triangle_faces + "end_header\n0 0 0 " + first_red +
           " 0 0 0.5\n1 0 0 0 0.25 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n";
  };
  EXPECT_EQ(apps::parse_ply("f", float_ply("0.75")).corners.colors,
            (std::vector<std::array<double, 4>>{{0.75, 0, 0, 0.5}, {0, 0.25, 0, 1}, {0, 0, 1, 1}}));
  const apps::Polygon_soup obj = apps::parse_obj(
      "f", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0 0.5\nv 0 1 0\nv 1 1 0 1\nf 1 2 3\nf 2 4 3\n");
  ASSERT_EQ(obj.corners.colors.size(), 4u);
  EXPECT_EQ(obj.corners.colors[0], (std::array<double, 4>{1, 0, 0, 1}));
  EXPECT_EQ(obj.corners.colors[1], (std::array<double, 4>{0, 1, 0, 0.5}));
  for (const std::size_t without : {2, 3})  // no colour, and a w
    for (const double channel : obj.corners.colors[without]) EXPECT_TRUE(std::isnan(channel));
  EXPECT_EQ(obj.corners.polygon_colors, obj.polygons);

  const auto cause = [](auto&& parse) {
    try {
      parse();
    } catch (const apps::App_error& e) {
      EXPECT_EQ(e.code(), apps::exit_bad_input);
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(cause([&] { apps::parse_ply("f", float_ply("nan")); }),
            "f: vertex 0: its colour is not finite");
  EXPECT_EQ(cause([] { apps::parse_obj("f", "v 0 0 0 1 red 0\n"); }),
            "f: line 1: a vertex's colour needs three or four finite numbers");
}

TEST(CornerAttributes, BadEntriesAreOneBadInputLine) {
  const auto cause = [](const std::string& bytes) {
    try {
      apps::parse_obj("f", bytes);
    } catch (const apps::App_error& e) {
      EXPECT_EQ(e.code(), apps::exit_bad_input);
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(cause(triangle + "vt 0 0\nf 1/2 2/1 3/1\n"),
            "f: line 5: '1/2' names a texture coordinate (vt) that is not read before it");
  EXPECT_EQ(cause(triangle + "f 1//1 2 3\nvn 0 0 1\n"),
            "f: line 4: '1//1' names a normal (vn) that is not read before it");
  EXPECT_EQ(cause(triangle + "vt nan 0\n"),
            "f: line 4: a texture coordinate needs one or two finite numbers, u [v]");
  EXPECT_EQ(cause(triangle + "vn 0 1\n"), "f: line 4: a normal needs three finite numbers, x y z");
  EXPECT_EQ(cause(triangle + "f 1/ 2 3\n"),
            "f: line 4: '1/' has a slash but names no texture coordinate or normal");
  EXPECT_EQ(cause(triangle + "usemtl\n"), "f: line 4: usemtl needs a material name");
}

// Each face's corners as (point, uv, normal), starting at the lowest point, and its material.
struct Face_corners {
  std::vector<std::array<double, 12>> corners;
  std::uint32_t material;
  bool operator==(const Face_corners& o) const {
    // NaN marks a corner without a value: compare bit patterns, not numbers.
    return material == o.material && corners.size() == o.corners.size() &&
           std::memcmp(corners.data(), o.corners.data(), corners.size() * sizeof corners[0]) == 0;
  }
};

std::vector<Face_corners> face_corners(const Mesh& mesh) {
  const Attributes a(mesh);
  std::vector<Face_corners> faces;
  for (const auto f : mesh.faces()) {
    Face_corners face{{}, a.materials ? (*a.materials)[f] : Attributes::kNoMaterial};
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      const Attributes::Uv uv = a.uvs ? (*a.uvs)[h] : Attributes::Uv{-1, -1};
      const apps::Kernel::Vector_3 n =
          a.normals ? (*a.normals)[h] : apps::Kernel::Vector_3(-1, -1, -1);
      const Attributes::Color c = a.colors ? (*a.colors)[h] : Attributes::Color{-1, -1, -1, -1};
      face.corners.push_back(
          {p.x(), p.y(), p.z(), uv[0], uv[1], n.x(), n.y(), n.z(), c[0], c[1], c[2], c[3]});
    }
    std::rotate(face.corners.begin(), std::min_element(face.corners.begin(), face.corners.end()),
                face.corners.end());
    faces.push_back(face);
  }
  return faces;
}

fs::path scratch_folder(const std::string& name) {
  const fs::path folder =
      fs::path(testing::TempDir()) / ("corner_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder / "out");
  return folder;
}

TEST(CornerAttributes, APolygonsTrianglesKeepItsCornersAndMaterial) {
  const fs::path folder = scratch_folder("polygon");
  // A pentagon with a corner of each texture coordinate, beside a triangle of no material.
  std::ofstream(folder / "in.obj")
      << "mtllib looks.mtl\nv 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 1 -1 0\n"
         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 1\nvt 0 1\nvn 0 0 1\nf 1 6 2\nusemtl wood\n"
         "f 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  ASSERT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(report.materials.names, std::vector<std::string>{"wood"});
  EXPECT_EQ(report.materials.libraries, std::vector<std::string>{(folder / "looks.mtl").string()});
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.normals && a.materials);
  std::size_t wood_corners = 0;
  for (const auto f : mesh.faces())
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      if ((*a.materials)[f] == Attributes::kNoMaterial) {
        EXPECT_TRUE(std::isnan((*a.uvs)[h][0]));
        continue;
      }
      ++wood_corners;
      EXPECT_EQ((*a.normals)[h], apps::Kernel::Vector_3(0, 0, 1));
      // The pentagon's texture coordinates go with its points.
      const std::map<std::pair<double, double>, Attributes::Uv> uv_of = {{{0, 0}, {0, 0}},
                                                                         {{2, 0}, {1, 0}},
                                                                         {{3, 1}, {1, 1}},
                                                                         {{1, 2}, {0.5, 1}},
                                                                         {{-1, 1}, {0, 1}}};
      EXPECT_EQ((*a.uvs)[h], uv_of.at({p.x(), p.y()}));
    }
  EXPECT_EQ(wood_corners, 9u);  // three triangles

  // Written into another folder and read back: the same corners, the material file found.
  const fs::path out = folder / "out" / "again.obj";
  apps::write_mesh_atomically(mesh, out.string(), report.materials);
  const std::string text = read_text(out);
  EXPECT_EQ(text.rfind("# written by cgal_policies\nmtllib ../looks.mtl\n", 0), 0u) << text;
  apps::Read_report again;
  EXPECT_EQ(face_corners(apps::read_triangle_mesh(out.string(), &again,
                                                  apps::Corner_attribute_reading::keep)),
            face_corners(mesh));
  EXPECT_EQ(again.materials.libraries, report.materials.libraries);
  fs::remove_all(folder);
}

TEST(CornerAttributes, ASoupThatNeedsRepairLosesThemAndSaysSo) {
  const fs::path folder = scratch_folder("repair");
  // Two triangles facing apart across their edge: the repair flips one.
  std::ofstream(folder / "in.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\n"
                                      "f 1/1 2/1 3/1\nf 2/1 3/1 4/1\n";
  apps::Read_report report;
  const Mesh mesh = apps::read_triangle_mesh((folder / "in.obj").string(), &report,
                                             apps::Corner_attribute_reading::keep);
  EXPECT_FALSE(Attributes(mesh).any());
  EXPECT_NE(std::find(report.repairs.begin(), report.repairs.end(),
                      "dropped the texture coordinates, normals and materials (the repair does "
                      "not carry them)"),
            report.repairs.end());
  fs::remove_all(folder);
}

TEST(CornerAttributes, ShippedTexturedMeshesRoundTripExactly) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path folder = scratch_folder("shipped");
  for (const std::string name : {"spot.obj", "bob_tri.obj"}) {
    SCOPED_TRACE(name);
    apps::Read_report report;
    const Mesh mesh = apps::read_triangle_mesh(test_meshes::data_file(name), &report,
                                               apps::Corner_attribute_reading::keep);
    const Attributes a(mesh);
    ASSERT_TRUE(a.uvs.has_value());
    std::size_t corners_without_uv = 0;
    for (const auto h : mesh.halfedges())
      corners_without_uv += !mesh.is_border(h) && std::isnan((*a.uvs)[h][0]);
    EXPECT_EQ(corners_without_uv, 0u);
    const fs::path out = folder / "out" / name;
    apps::write_mesh_atomically(mesh, out.string(), report.materials);
    apps::Read_report again;
    EXPECT_EQ(face_corners(apps::read_triangle_mesh(out.string(), &again,
                                                    apps::Corner_attribute_reading::keep)),
              face_corners(mesh));
    EXPECT_EQ(again.materials.names, report.materials.names);
    EXPECT_EQ(again.materials.libraries, report.materials.libraries);
  }
  fs::remove_all(folder);
}

// A mesh with texture coordinates, normals and colours, seams everywhere, written as PLY (a vertex
// per wedge) reads back as the same mesh, every corner's values exact and each seam whole.
TEST(CornerAttributes, PlyWrittenWithItsWedgesReadsBackExactly) {
  Mesh cube = test_meshes::six_sided_cube();
  test_meshes::paint_corners(
      cube,
      [&](Mesh::Face_index f, const apps::Point& p) {
        return test_meshes::cube_chart(test_meshes::cube_side(cube, f), p);
      },
      true);
  test_meshes::paint_colors(cube, [&](Mesh::Face_index f, const apps::Point& p) {
    // Whole steps of 1/255, which a byte holds exactly.
    return std::array<double, 4>{test_meshes::cube_side(cube, f) * 40 / 255.0, p.x() * 60 / 255.0,
                                 1, 1};
  });
  const fs::path folder = scratch_folder("ply_wedges");
  const std::string path = (folder / "cube.ply").string();
  apps::write_mesh_atomically(cube, path);
  const apps::Polygon_soup soup = apps::parse_ply(path, read_text(path));
  // A vertex per side it lies on: 3 at each of the 8 corners, 2 along the 12 edges' 3 inner
  // points, 1 at the 9 inner points of each side.
  EXPECT_EQ(soup.points.size(), 8u * 3 + 12u * 3 * 2 + 6u * 9);
  const Mesh reread = apps::read_triangle_mesh(path, nullptr, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(reread.number_of_vertices(), cube.number_of_vertices());
  EXPECT_TRUE(CGAL::is_closed(reread));
  EXPECT_EQ(face_corners(reread), face_corners(cube));
  // Every edge of the cube is a seam: 12 edges of 4 segments.
  EXPECT_EQ(apps::measure_attribute_error(cube, reread, 1000).seam_edges_b, 48u);
  fs::remove_all(folder);
}

TEST_F(Cli, SimplifyCarriesTextureCoordinatesIntoAnObjWithEveryKindOfPolicy) {
  // A flat 6 x 6 grid whose texture coordinates are its x and y over 6: a linear field, which
  // every carried collapse reproduces.
  Mesh grid = test_meshes::flat_grid(6);
  const Attributes painted = Attributes::add(grid, {true, false, false, false});
  for (const auto h : grid.halfedges())
    if (!grid.is_border(h))
      (*painted.uvs)[h] = {grid.point(grid.target(h)).x() / 6, grid.point(grid.target(h)).y() / 6};
  const fs::path input = file("grid.obj");
  apps::write_mesh_atomically(grid, input.string());
  const fs::path out = file("out.obj");

  // gh through CGAL's edge_collapse and the carrier, fast through its own engine.
  for (const std::string policy : {"gh", "fast"}) {
    const Command_result carried =
        run("simplify", input.string() + " " + out.string() + " --faces 8 --policy " + policy +
                            " --json --force --measure --samples 2000");
    ASSERT_EQ(carried.exit_code, 0) << policy << ": " << carried.err;
    EXPECT_NE(carried.out.find("\"attributes\": \"carried\""), std::string::npos) << carried.out;
    // The field is linear and the grid flat: the carried coordinates are right everywhere, and the
    // only seam is the border, in and out.
    EXPECT_LE(json_number(carried.out, "uv_max_rel"), 1e-12) << carried.out;
    EXPECT_EQ(json_number(carried.out, "flipped_uv_faces"), 0) << carried.out;
    EXPECT_EQ(json_number(carried.out, "seam_edges_a"), 24) << carried.out;
    EXPECT_EQ(json_number(carried.out, "seam_loops_a"), 1) << carried.out;
    EXPECT_EQ(json_number(carried.out, "seam_loops_b"), 1) << carried.out;
    const Mesh simplified =
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
    EXPECT_LE(simplified.number_of_faces(), 8u) << policy;
    const Attributes kept(simplified);
    ASSERT_TRUE(kept.uvs.has_value()) << policy;
    for (const auto h : simplified.halfedges()) {
      if (simplified.is_border(h)) continue;
      const apps::Point& p = simplified.point(simplified.target(h));
      EXPECT_NEAR((*kept.uvs)[h][0], p.x() / 6, 1e-12) << policy;
      EXPECT_NEAR((*kept.uvs)[h][1], p.y() / 6, 1e-12) << policy;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// glTF (.gltf, .glb): corners per glTF vertex, points welded, materials and images passed through.

// Each value as glTF stores it: through float.
std::vector<Face_corners> through_float(std::vector<Face_corners> faces) {
  for (Face_corners& face : faces)
    for (auto& corner : face.corners)
      for (double& c : corner) c = double(float(c));
  return faces;
}

std::vector<Face_corners> sorted(std::vector<Face_corners> faces) {
  std::sort(faces.begin(), faces.end(), [](const Face_corners& a, const Face_corners& b) {
    return std::tie(a.corners, a.material) < std::tie(b.corners, b.material);
  });
  return faces;
}

std::size_t seam_edge_count(const Mesh& mesh) {
  const Attributes a(mesh);
  std::size_t seams = 0;
  for (const auto e : mesh.edges()) seams += a.is_seam_edge(mesh, mesh.halfedge(e));
  return seams;
}

// six_sided_cube() moved off the float grid, each side its own texture chart, its normal, its
// colour and one of two materials.
Mesh painted_cube() {
  Mesh mesh = test_meshes::six_sided_cube();
  for (const auto v : mesh.vertices())
    mesh.point(v) = mesh.point(v) + apps::Kernel::Vector_3(0.1, 0.2, 1.0 / 3);
  const Attributes a = Attributes::add(mesh, {true, true, true, true});
  for (const auto f : mesh.faces()) {
    const int side = test_meshes::cube_side(mesh, f);
    (*a.materials)[f] = std::uint32_t(side % 2);
    const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh);
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point p = mesh.point(mesh.target(h)) - apps::Kernel::Vector_3(0.1, 0.2, 1.0 / 3);
      (*a.uvs)[h] = test_meshes::cube_chart(side, p);
      (*a.uvs)[h][1] += 1.0 / 7;
      (*a.normals)[h] = n;
      (*a.colors)[h] = {side / 7.0, 0.3, 1.0 / 3, 0.9};
    }
  }
  return mesh;
}

TEST(Gltf, ARoundTripKeepsEveryCornerToFloatPrecision) {
  const fs::path folder = scratch_folder("gltf_round_trip");
  const Mesh cube = painted_cube();
  const apps::Material_references names{{}, {"even", "odd"}, nullptr};
  for (const std::string name : {"cube.gltf", "cube.glb"}) {
    SCOPED_TRACE(name);
    const fs::path out = folder / name;
    apps::write_mesh_atomically(cube, out.string(), names);
    apps::Read_report report;
    const Mesh read =
        apps::read_triangle_mesh(out.string(), &report, apps::Corner_attribute_reading::keep);
    EXPECT_TRUE(report.repairs.empty());
    // One closed surface: the seams split no vertex of the mesh.
    EXPECT_EQ(read.number_of_vertices(), cube.number_of_vertices());
    EXPECT_EQ(read.number_of_faces(), 192u);
    EXPECT_EQ(test_meshes::border_edge_count(read), 0u);
    EXPECT_EQ(sorted(face_corners(read)), sorted(through_float(face_corners(cube))));
    EXPECT_EQ(seam_edge_count(read), 48u);  // the cube's 12 edges, 4 mesh edges each
    EXPECT_EQ(seam_edge_count(read), seam_edge_count(cube));
    EXPECT_EQ(report.materials.names, names.names);
    ASSERT_TRUE(report.materials.gltf);
    EXPECT_EQ(report.materials.gltf->materials.size(), 2u);
  }
  fs::remove_all(folder);
}

// A glTF model whose buffer 0 gets each array as an accessor of its own.
class Gltf_builder {
 public:
  Gltf_builder() {
    model.buffers.resize(1);
    model.asset.version = "2.0";
  }
  template <class T>
  int accessor(const std::vector<T>& values, int component_type, int type,
               bool normalized = false) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    data.insert(data.end(), bytes, bytes + view.byteLength);
    data.resize((data.size() + 3) / 4 * 4);
    model.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = int(model.bufferViews.size() - 1);
    a.componentType = component_type;
    a.type = type;
    a.normalized = normalized;
    a.count = values.size() / std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(type)));
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
  }
  // One mesh of these primitives, under one node moved by `translation`.
  void place(std::vector<tinygltf::Primitive> primitives, std::vector<double> translation) {
    model.meshes.emplace_back();
    model.meshes.back().primitives = std::move(primitives);
    model.nodes.emplace_back();
    model.nodes.back().mesh = 0;
    model.nodes.back().translation = std::move(translation);
    model.scenes.emplace_back();
    model.scenes.back().nodes = {0};
    model.defaultScene = 0;
  }
  void write(const fs::path& path) const {
    std::ofstream file(path, std::ios::binary);
    tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, file, false, path.extension() == ".glb");
  }
  tinygltf::Model model;
};

tinygltf::Primitive triangles(int position, int indices, int uv, int material) {
  tinygltf::Primitive p;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  p.attributes["POSITION"] = position;
  if (uv >= 0) p.attributes["TEXCOORD_0"] = uv;
  p.indices = indices;
  p.material = material;
  return p;
}

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// The unit square as two primitives that share no vertex: the first indexed by u16 with float
// texture coordinates (x, y) / 2 and normalized u8 RGB colours, the second without indices or
// colours, with normalized u16 texture coordinates that agree at (0, 0) and differ at (1, 1), so
// that the diagonal is a seam.
Gltf_builder two_primitive_square() {
  Gltf_builder b;
  const int first =
      b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  const int first_indices =
      b.accessor(std::vector<std::uint16_t>{0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                 TINYGLTF_TYPE_SCALAR);
  const int first_uvs =
      b.accessor(std::vector<float>{0, 0, 0.5f, 0, 0.5f, 0.5f}, kFloat, TINYGLTF_TYPE_VEC2);
  const int second =
      b.accessor(std::vector<float>{0, 0, 0, 1, 1, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  const int second_uvs =
      b.accessor(std::vector<std::uint16_t>{0, 0, 52428, 52428, 0, 65535},
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC2, true);
  tinygltf::Primitive colored = triangles(first, first_indices, first_uvs, 0);
  colored.attributes["COLOR_0"] =
      b.accessor(std::vector<std::uint8_t>{0, 51, 255, 0, 51, 255, 0, 51, 255},
                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC3, true);
  b.model.materials.resize(2);
  b.model.materials[0].name = "paint";
  b.place({colored, triangles(second, -1, second_uvs, 1)}, {10, 0, 0});
  return b;
}

TEST(Gltf, TwoPrimitivesWithAUvSeamAreOneConnectedMesh) {
  const fs::path folder = scratch_folder("gltf_seam");
  const fs::path in = folder / "square.glb";
  two_primitive_square().write(in);
  apps::Read_report report;
  const Mesh mesh =
      apps::read_triangle_mesh(in.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_TRUE(report.repairs.empty());
  ASSERT_EQ(mesh.number_of_faces(), 2u);
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_EQ(test_meshes::border_edge_count(mesh), 4u);  // the diagonal joins the two
  EXPECT_EQ(report.materials.names, (std::vector<std::string>{"paint", "material_1"}));
  const Attributes a(mesh);
  ASSERT_TRUE(a.uvs && a.materials);
  EXPECT_FALSE(a.normals);
  // The node's translation moved the points; the second primitive's corners are its own.
  const auto diagonal =
      test_meshes::halfedge_between(mesh, apps::Point(10, 0, 0), apps::Point(11, 1, 0));
  const auto other = mesh.opposite(diagonal);
  EXPECT_TRUE(a.is_seam_edge(mesh, diagonal));
  const Mesh::Halfedge_index in_first = (*a.materials)[mesh.face(diagonal)] == 0 ? diagonal : other;
  const Mesh::Halfedge_index in_second = in_first == diagonal ? other : diagonal;
  EXPECT_EQ((*a.materials)[mesh.face(in_second)], 1u);
  const auto corner_at = [&](Mesh::Halfedge_index h, const apps::Point& p) {
    return mesh.point(mesh.target(h)) == p ? h : mesh.prev(h);
  };
  EXPECT_EQ((*a.uvs)[corner_at(in_first, {11, 1, 0})], (Attributes::Uv{0.5, 0.5}));
  EXPECT_EQ((*a.uvs)[corner_at(in_second, {11, 1, 0})], (Attributes::Uv{0.8, 0.8}));
  EXPECT_EQ((*a.uvs)[corner_at(in_first, {10, 0, 0})], (Attributes::Uv{0, 0}));
  EXPECT_EQ((*a.uvs)[corner_at(in_second, {10, 0, 0})], (Attributes::Uv{0, 0}));
  // Colours: the first primitive's, RGB with alpha 1; none on the second's corners.
  ASSERT_TRUE(a.colors);
  EXPECT_EQ((*a.colors)[corner_at(in_first, {10, 0, 0})], (Attributes::Color{0, 0.2, 1, 1}));
  EXPECT_TRUE(std::isnan((*a.colors)[corner_at(in_second, {10, 0, 0})][0]));
  fs::remove_all(folder);
}

// A node's world transform: a child turned a quarter about z and mirrored in x, under a parent
// moved up by 5. The mirror turns the winding, so the reader turns the triangle back to face its
// normal, which the transform leaves at +z.
TEST(Gltf, NodeTransformsPlaceTurnAndMirror) {
  const fs::path folder = scratch_folder("gltf_nodes");
  Gltf_builder b;
  const int position =
      b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, TINYGLTF_TYPE_VEC3);
  tinygltf::Primitive primitive = triangles(position, -1, -1, -1);
  primitive.attributes["NORMAL"] =
      b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, TINYGLTF_TYPE_VEC3);
  b.place({primitive}, {0, 0, 5});
  b.model.nodes[0].mesh = -1;
  b.model.nodes[0].children = {1};
  b.model.nodes.emplace_back();
  b.model.nodes[1].mesh = 0;
  b.model.nodes[1].rotation = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  b.model.nodes[1].scale = {-1, 1, 1};
  b.write(folder / "turned.gltf");
  const Mesh mesh = apps::read_triangle_mesh((folder / "turned.gltf").string(), nullptr,
                                             apps::Corner_attribute_reading::keep);
  ASSERT_EQ(mesh.number_of_faces(), 1u);
  // The quarter turn's sines and cosines are rounded: the points snapped to a 1e-12 grid.
  const auto snap = [](double x) { return std::round(x * 1e12) / 1e12; };
  std::vector<std::array<double, 3>> points;
  for (const auto v : mesh.vertices())
    points.push_back({snap(mesh.point(v).x()), snap(mesh.point(v).y()), snap(mesh.point(v).z())});
  std::sort(points.begin(), points.end());
  EXPECT_EQ(points, (std::vector<std::array<double, 3>>{{-1, 0, 5}, {0, -1, 5}, {0, 0, 5}}));
  const auto face_normal =
      CGAL::Polygon_mesh_processing::compute_face_normal(*mesh.faces().begin(), mesh);
  EXPECT_NEAR(face_normal.z(), 1, 1e-15);
  const Attributes a(mesh);
  ASSERT_TRUE(a.normals);
  for (const auto h : mesh.halfedges())
    if (!mesh.is_border(h)) {
      EXPECT_NEAR((*a.normals)[h].x(), 0, 1e-15);
      EXPECT_NEAR((*a.normals)[h].y(), 0, 1e-15);
      EXPECT_NEAR((*a.normals)[h].z(), 1, 1e-15);
    }
  fs::remove_all(folder);
}

// Any bytes: the reader and the writer never decode an image.
const std::string kImageBytes = std::string("\x89PNG\r\n\x1a\n", 8) + "not decoded";

TEST_F(Cli, SimplifyPassesAGlbsMaterialsAndImagesThrough) {
  // A textured 6 x 6 grid written by the apps, then given an embedded and an external image.
  Mesh grid = test_meshes::flat_grid(6);
  test_meshes::paint_corners(
      grid,
      [](Mesh::Face_index, const apps::Point& p) {
        return std::array<double, 2>{p.x() / 6, p.y() / 6};
      },
      false);
  const Attributes painted = Attributes::add(grid, {false, false, false, true});
  for (const auto f : grid.faces()) (*painted.materials)[f] = 0;
  const fs::path plain = file("plain.glb");
  apps::write_mesh_atomically(grid, plain.string(), {{}, {"skin"}, nullptr});
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&model, &error, &warning, plain.string()))
      << error;
  std::vector<unsigned char>& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = kImageBytes.size();
  data.insert(data.end(), kImageBytes.begin(), kImageBytes.end());
  model.bufferViews.push_back(view);
  model.images.resize(2);
  model.images[0].bufferView = int(model.bufferViews.size() - 1);
  model.images[0].mimeType = "image/png";
  model.images[1].uri = "tex/skin.png";
  model.textures.resize(2);
  model.textures[0].source = 0;
  model.textures[1].source = 1;
  model.materials[0].pbrMetallicRoughness.baseColorTexture.index = 0;
  model.materials[0].emissiveTexture.index = 1;
  const fs::path in = file("in.glb");
  {
    std::ofstream out(in, std::ios::binary);
    tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, out, false, true);
  }

  fs::create_directories(file("out"));
  const fs::path out = file("out") / "out.glb";
  const Command_result r =
      run("simplify", in.string() + " " + out.string() + " 0.5 --policy gh --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  const apps::Gltf_soup read = apps::read_gltf(out.string(), true);
  EXPECT_LE(read.soup.polygons.size(), 36u);
  ASSERT_EQ(read.looks->images.size(), 2u);
  EXPECT_EQ(std::string(read.looks->images[0].image.begin(), read.looks->images[0].image.end()),
            kImageBytes);
  EXPECT_EQ(read.looks->images[0].mimeType, "image/png");
  EXPECT_TRUE(read.looks->images[0].uri.empty());  // still in the file
  EXPECT_EQ(read.looks->images[1].uri, file("tex/skin.png").string());
  ASSERT_EQ(read.looks->materials.size(), 1u);
  EXPECT_EQ(read.looks->materials[0].name, "skin");
  EXPECT_EQ(read.looks->materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_EQ(read.looks->materials[0].emissiveTexture.index, 1);
  EXPECT_EQ(read.looks->textures.size(), 2u);
  EXPECT_EQ(read.soup.corners.polygon_materials,
            std::vector<std::uint32_t>(read.soup.polygons.size(), 0));
  // The file names the image by its path from its own folder.
  EXPECT_NE(read_text(out).find("\"uri\":\"../tex/skin.png\""), std::string::npos);
}

TEST_F(Cli, SimplifyWritesATexturedObjAsGlb) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const std::string spot = test_meshes::data_file("spot.obj");
  const fs::path out = file("spot.glb");
  const Command_result r = run("simplify", spot + " " + out.string() + " 0.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  apps::Read_report spot_report, report;
  const Mesh original =
      apps::read_triangle_mesh(spot, &spot_report, apps::Corner_attribute_reading::keep);
  const Mesh simplified =
      apps::read_triangle_mesh(out.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(double(simplified.number_of_faces()), json_number(r.out, "output_faces")) << r.out;
  EXPECT_LE(json_number(r.out, "target_gap_faces"), 0) << r.out;
  EXPECT_LT(simplified.number_of_faces(), original.number_of_faces() / 9);
  EXPECT_EQ(report.materials.names, spot_report.materials.names);
  const Attributes a(simplified);
  ASSERT_TRUE(a.uvs.has_value());
  for (const auto h : simplified.halfedges())
    if (!simplified.is_border(h)) {
      EXPECT_TRUE(std::isfinite((*a.uvs)[h][0]));
    }
  // The seams are where they were: one loop, as in spot.
  const Command_result compared =
      run("mesh_error", spot + " " + out.string() + " --attributes --json --samples 2000");
  ASSERT_EQ(compared.exit_code, 0) << compared.err;
  EXPECT_EQ(json_number(compared.out, "seam_loops_b"), 1) << compared.out;
}

TEST_F(Cli, SimplifyCarriesPlyColoursIntoAGltf) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path out = file("spot.gltf");
  const Command_result r = run(
      "simplify", test_meshes::data_file("spot_colors.ply") + " " + out.string() + " 0.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  EXPECT_NE(read_text(out).find("\"COLOR_0\""), std::string::npos);
  const Mesh simplified =
      apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
  const Attributes a(simplified);
  ASSERT_TRUE(a.colors.has_value());
  for (const auto h : simplified.halfedges()) {
    if (simplified.is_border(h)) continue;
    for (double c : (*a.colors)[h]) {
      EXPECT_GE(c, 0);
      EXPECT_LE(c, 1);
    }
  }
}

TEST_F(Cli, BadGltfIsOneBadInputLineAndNoOutput) {
  const fs::path out = file("out.glb");
  const auto one_triangle = [](std::vector<float> positions, std::vector<std::uint32_t> indices) {
    Gltf_builder b;
    const int p = b.accessor(positions, kFloat, TINYGLTF_TYPE_VEC3);
    const int i = b.accessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
    b.place({triangles(p, i, -1, -1)}, {});
    return b;
  };
  const float nan = std::nanf("");
  one_triangle({0, 0, 0, 1, 0, 0, 0, nan, 0}, {0, 1, 2}).write(file("nan.glb"));
  one_triangle({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 3}).write(file("index.glb"));
  Gltf_builder raw_uvs = two_primitive_square();
  raw_uvs.model.accessors[4].normalized = false;  // the second primitive's u16 coordinates
  raw_uvs.write(file("raw_uvs.glb"));
  Gltf_builder cycle = two_primitive_square();
  cycle.model.nodes[0].children = {0};  // its own child
  cycle.write(file("cycle.glb"));
  two_primitive_square().write(file("whole.glb"));
  const std::string whole = read_text(file("whole.glb"));
  write("truncated.glb", whole.substr(0, whole.size() / 2));
  write("malformed.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [");
  write("missing_buffer.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"gone.bin\", "
        "\"byteLength\": 36}]}");
  const std::map<std::string, std::string> causes = {
      {"nan.glb", "mesh 0 primitive 0: the position of vertex 2 is not finite"},
      {"index.glb", "mesh 0 primitive 0: index 3 is out of range (3 vertices)"},
      {"raw_uvs.glb",
       "mesh 0 primitive 1 TEXCOORD_0 (accessor 4): integer values must be normalized"},
      {"cycle.glb", "the node hierarchy has a cycle"},
      {"truncated.glb", "cannot parse: "},
      {"malformed.gltf", "cannot parse: "},
      {"missing_buffer.gltf", "cannot parse: "}};
  for (const auto& [name, cause] : causes) {
    SCOPED_TRACE(name);
    expect_failure(file(name).string() + " " + out.string() + " 0.5", apps::exit_bad_input,
                   file(name), out);
    EXPECT_EQ(read_text(file("stderr")).find("simplify: " + file(name).string() + ": " + cause), 0u)
        << read_text(file("stderr"));
  }
}

}  // namespace corner_attributes
