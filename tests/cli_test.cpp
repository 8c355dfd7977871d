// The apps from the outside: exit codes, one error line naming the file, no partial output, the
// input never overwritten (README.md "Interfaces that others rely on").
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
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

// A number field of simplify's JSON object; NaN when missing.
double json_number(const std::string& json, const std::string& field) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + field + "\": ([-+.e0-9]+)")))
    return std::nan("");
  return std::stod(match[1]);
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
  const std::string cow = std::string(CGAL_POLICIES_SOURCE_DIR) + "/data/cow.obj";
  const fs::path out = file("cow.off");
  for (const char* policy : {"gh", "classic", "curvature"}) {
    const std::string args = cow + " " + out.string() + " --ratio 0.01 --policy " + policy +
                             " --json --quiet --measure --samples 20000";
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
  const std::string cow = std::string(CGAL_POLICIES_DATA_DIR) + "/cow.obj";
  std::string written[2];
  for (int run_index = 0; run_index < 2; ++run_index) {
    const fs::path out = file("cow_" + std::to_string(run_index) + ".ply");
    const Command_result r =
        run("simplify",
            cow + " " + out.string() + " 0.1 --policy lt --fit --fit-rounds 2 --json --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* field : {"\"fit_seconds\": ", "\"fit_rounds\": 2,",
                              "\"fit_flips\": ", "\"fit_moves\": ", "\"output_faces\": 580,"})
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

}  // namespace
