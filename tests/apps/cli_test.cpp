// The apps from the outside (apps/cli/ and the tools): exit codes, one error line naming the file,
// no partial output even when interrupted, the input never overwritten (docs/cli.md), the passes
// simplify runs on dirty scans, and corner attributes, materials and images carried through
// simplify into OBJ and glTF.
#include "gltf_builder.h"
#include "test_meshes.h"

#include <cgal_policies/small_components.h>
#include "cli/App_error.h"
#include "cli/tuned_allocator.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/clean_triangle_soup.h"
#include "io/gltf_io.h"
#include "io/material_texture.h"
#include "io/mesh_io.h"
#include "io/obj_writer.h"
#include "io/polygon_crossing.h"
#include "io/soup_readers.h"

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
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Attributes = cgal_policies::Corner_attributes<apps::Point>;
using apps::Mesh;
using gltf_fixtures::Gltf_builder;
using gltf_fixtures::kFloat;
using gltf_fixtures::kImageBytes;
using gltf_fixtures::triangles;
using gltf_fixtures::two_primitive_square;

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

// A number field of an app's JSON object; NaN when missing.
double json_number(const std::string& json, const std::string& field) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + field + "\": ([-+.e0-9]+)")))
    return std::nan("");
  return std::stod(match[1]);
}

// Every value of a number field of an app's JSON, in order (a report's levels each have one).
std::vector<double> json_numbers(const std::string& json, const std::string& field) {
  std::vector<double> numbers;
  const std::regex pattern("\"" + field + "\": ([-+.e0-9]+)");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), pattern);
       it != std::sregex_iterator(); ++it)
    numbers.push_back(std::stod((*it)[1]));
  return numbers;
}

// test_meshes::loop_sphere(levels) written to `path` as OFF, its points read back exactly: at 2
// levels a closed sphere of 320 faces, which loses two faces a collapse, so that every even target
// is met exactly.
fs::path write_sphere(const fs::path& path, int levels = 2) {
  const test_meshes::Mesh sphere = test_meshes::loop_sphere(levels);
  EXPECT_TRUE(
      CGAL::IO::write_polygon_mesh(path.string(), sphere, CGAL::parameters::stream_precision(17)));
  return path;
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

  // Whether this build draws snapshots (built with the viewer); without, simplify's help says so.
  bool snapshots_in_this_build() const {
    return run("simplify", "--help").out.find("not in this build") == std::string::npos;
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

  // mesh_error --attributes on IN and OUT: no seam torn (as many seam loops) and no texture
  // triangle turned over.
  void expect_texture_kept(const fs::path& in, const fs::path& out, int samples) const {
    const Command_result compared =
        run("mesh_error", in.string() + " " + out.string() + " --attributes --json --samples " +
                              std::to_string(samples));
    ASSERT_EQ(compared.exit_code, 0) << compared.err;
    EXPECT_EQ(json_number(compared.out, "flipped_uv_faces"), 0) << compared.out;
    EXPECT_EQ(json_number(compared.out, "seam_loops_b"), json_number(compared.out, "seam_loops_a"))
        << compared.out;
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
  // No --policy: the library's default pipeline, lt and then the fitting pass.
  for (const char* field :
       {"\"policy\": \"lt\"", "\"fit\": true", "\"input_faces\": 4", "\"output_faces\": 4",
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
                                                         {"fast", "--max-error", "0.01"},
                                                         {"flat-lt", "--volume-weight", "-1"},
                                                         {"flat-lt", "--time-limit", "5"}};
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
  const bool with_viewer = snapshots_in_this_build();
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

TEST_F(Cli, OsmesaIsOpenedOnlyForAPicture) {
  if (!snapshots_in_this_build()) GTEST_SKIP() << "this build has no snapshots";
  // The dynamic loader's trace names every library it opens. Linked, OSMesa and the LLVM it brings
  // along were most of the start of every run.
  const fs::path in = write("tet.off", kTetrahedronOff);
  const std::string args = in.string() + " " + file("out.off").string() + " 1 --quiet";
  ASSERT_EQ(::setenv("LD_DEBUG", "libs", 1), 0);
  const Command_result plain = run("simplify", args);
  const Command_result drawn =
      run("simplify", args + " --snapshot " + file("tet.png").string() + " --size 32x16");
  ASSERT_EQ(::unsetenv("LD_DEBUG"), 0);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_EQ(plain.err.find("libOSMesa"), std::string::npos);
  EXPECT_EQ(plain.err.find("libLLVM"), std::string::npos);
  EXPECT_NE(drawn.err.find("libOSMesa"), std::string::npos);
  EXPECT_TRUE(fs::exists(file("tet.png")));
}

TEST_F(Cli, MaxErrorBoundsEveryEdgeCollapsePolicy) {
  // A sphere of 320 faces: curved everywhere, so a bound of 1% of its diagonal stops every policy
  // early (near 140 faces), and small enough for the sanitized build, where certifying 1,280
  // faces took a minute a run.
  const fs::path sphere = write_sphere(file("sphere.off"));
  const fs::path out = file("sphere_out.off");
  for (const char* policy : {"gh", "classic", "curvature"}) {
    const std::string args = sphere.string() + " " + out.string() + " --ratio 0.01 --policy " +
                             policy + " --json --quiet --measure --samples 20000";
    const Command_result bounded = run("simplify", args + " --max-error 0.01");
    ASSERT_EQ(bounded.exit_code, 0) << policy << ": " << bounded.err;
    EXPECT_NE(bounded.out.find("\"stop_reason\": \"error_bound_reached\""), std::string::npos)
        << policy << ": " << bounded.out;
    EXPECT_NE(bounded.out.find("\"valid\": true"), std::string::npos) << policy;
    EXPECT_LT(json_number(bounded.out, "output_faces"), 320) << policy << ": nothing collapsed";
    EXPECT_LE(json_number(bounded.out, "hausdorff"),
              0.01 * json_number(bounded.out, "bbox_diagonal"))
        << policy;
    const Command_result free = run("simplify", args);
    ASSERT_EQ(free.exit_code, 0) << policy << ": " << free.err;
    EXPECT_LT(json_number(free.out, "output_faces"), json_number(bounded.out, "output_faces"))
        << policy;
    EXPECT_GT(json_number(free.out, "hausdorff"), 0.01 * json_number(free.out, "bbox_diagonal"))
        << policy << ": the bound must have been needed";
  }
}

TEST_F(Cli, FitIsReportedAndTwoRunsWriteTheSameBytes) {
  // A small sphere, so that the sanitized build runs it in seconds.
  const fs::path sphere = write_sphere(file("sphere.off"));
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
  // A policy named runs alone, and its fit options need --fit.
  expect_failure(in.string() + " " + out.string() + " 1 --policy lt --fit-rounds 2", 2,
                 "--fit-rounds", out);
  expect_failure(in.string() + " " + out.string() + " 1 --fit --fit-rounds 0", 2, "--fit-rounds",
                 out);
}

// --prepass K: reported, and refused where fast cannot keep what the run asks (a bound, a time
// limit) or would run twice.
TEST_F(Cli, PrepassIsReportedAndRefusedWhereFastCannotRun) {
  const fs::path sphere = write_sphere(file("sphere.off"), 3);
  const fs::path out = file("sphere_out.ply");
  const Command_result r = run("simplify", sphere.string() + " " + out.string() +
                                               " --faces 64 --policy flat-lt --prepass 4 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* field : {"\"prepass\": 4,", "\"output_faces\": 64,"})
    EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing in " << r.out;
  const std::string in = sphere.string() + " " + file("refused.ply").string() + " 0.1 ";
  for (const std::string& args :
       {in + "--prepass 0.5", in + "--prepass 4 --policy fast", in + "--prepass 4 --max-error 0.01",
        in + "--prepass 4 --policy hausdorff", in + "--prepass 4 --policy classic --time-limit 5"})
    expect_failure(args, apps::exit_usage, "--prepass", file("refused.ply"));
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
  const bool with_viewer = snapshots_in_this_build();
  if (!with_viewer) return;  // --snapshot is then bad usage, before reading too
  const fs::path png = folder / "picture.png";
  expect_failure(in.string() + " " + file("out.off").string() + " 0.5 --snapshot " + png.string(),
                 4, png, file("out.off"));
}

TEST_F(Cli, ATimeLimitStopsTheRunWhereItIs) {
  const fs::path out = file("cow.off");
  // Long past at the first collapse: the queue alone takes longer to build.
  const Command_result r = run("simplify", test_meshes::data_file("cow.obj") + " " + out.string() +
                                               " 0.1 --policy classic --time-limit 1e-9 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"stop_reason\": \"time_limit\""), std::string::npos) << r.out;
  EXPECT_EQ(json_number(r.out, "output_faces"), json_number(r.out, "input_faces")) << r.out;
  EXPECT_EQ(json_number(r.out, "time_limit_seconds"), 1e-9) << r.out;
  EXPECT_EQ(apps::read_triangle_mesh(out.string()).number_of_faces(),
            json_number(r.out, "input_faces"));
  const Command_result unlimited =
      run("simplify", test_meshes::data_file("cow.obj") + " " + out.string() +
                          " 0.1 --policy classic --time-limit 0 --json");
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
  // classic: a run of the cow in a fraction of a second, even in the sanitized build.
  const std::vector<std::string> options = {"0.5", "--policy", "classic", "--quiet"};
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
  const bool with_viewer = snapshots_in_this_build();
  const fs::path out = file("cow.off"), png = file("cow.png");
  const std::string old_output = "an older output";
  for (const int signal : {SIGINT, SIGTERM}) {
    std::ofstream(out, std::ios::binary) << old_output;
    std::vector<std::string> args = {test_meshes::data_file("cow.obj"), out.string(), "0.5",
                                     "--policy", "classic"};
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

// --lod writes every level's temporary before it renames any: an interrupt while level 1's is
// written leaves level 0's older file as it was, and no temporary (level 0's is complete by then).
TEST_F(Cli, AnInterruptWhileWritingALevelLeavesTheOlderLevelsAndNoTemporary) {
  const fs::path out = file("cow.off"), level_0 = file("cow_lod0.off");
  const std::string old_level = "an older level";
  std::ofstream(level_0, std::ios::binary) << old_level;
  const int status =
      interrupt_while_writing({test_meshes::data_file("cow.obj"), out.string(), "--lod", "0.5,0.25",
                               "--policy", "classic", "--quiet"},
                              file("cow_lod1.off"), SIGTERM);
  ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  EXPECT_EQ(read_text(level_0), old_level);
  EXPECT_FALSE(fs::exists(file("cow_lod1.off")));
  EXPECT_FALSE(fs::exists(out));
  for (const auto& entry : fs::directory_iterator(m_dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "temporary file left behind: " << entry.path();
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

TEST_F(Cli, SimplifyCarriesTextureCoordinatesIntoAnObjWithEveryKindOfPolicy) {
  // A flat 6 x 6 grid whose texture coordinates are its x and y over 6: a linear field, which
  // every carried collapse reproduces.
  Mesh grid = test_meshes::flat_grid(6);
  const Attributes painted = Attributes::add(grid, {true, false, false, false, false, false});
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

// A flat 6 x 6 grid whose texture coordinates are its x and y over 6, every face of material 0.
Mesh textured_grid() {
  Mesh grid = test_meshes::flat_grid(6);
  test_meshes::paint_corners(
      grid,
      [](Mesh::Face_index, const apps::Point& p) {
        return std::array<double, 2>{p.x() / 6, p.y() / 6};
      },
      false);
  const Attributes painted = Attributes::add(grid, {false, false, false, true, false, false});
  for (const auto f : grid.faces()) (*painted.materials)[f] = 0;
  return grid;
}

TEST_F(Cli, SimplifyPassesAGlbsMaterialsAndImagesThrough) {
  // A textured grid written by the apps, then given an embedded and an external image.
  const fs::path plain = file("plain.glb");
  apps::write_mesh_atomically(textured_grid(), plain.string(), {{}, {"skin"}, nullptr, {}});
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
  const std::string skin = std::string("\xff\xd8\xff\xe0", 4) + "the skin's pixels";
  fs::create_directories(file("tex"));
  std::ofstream(file("tex") / "skin.png", std::ios::binary) << skin;

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
  // The image file, outside OUT's folder, is embedded: OUT names no file outside its folder.
  EXPECT_TRUE(read.looks->images[1].uri.empty());
  EXPECT_EQ(std::string(read.looks->images[1].image.begin(), read.looks->images[1].image.end()),
            skin);
  EXPECT_EQ(read.looks->images[1].mimeType, "image/jpeg");
  ASSERT_EQ(read.looks->materials.size(), 1u);
  EXPECT_EQ(read.looks->materials[0].name, "skin");
  EXPECT_EQ(read.looks->materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_EQ(read.looks->materials[0].emissiveTexture.index, 1);
  EXPECT_EQ(read.looks->textures.size(), 2u);
  EXPECT_EQ(read.soup.corners.polygon_materials,
            std::vector<std::uint32_t>(read.soup.polygons.size(), 0));
  EXPECT_EQ(read_text(out).find("\"uri\""), std::string::npos);

  // Written beside IN, the file names the image by its path from its own folder.
  const fs::path beside = file("beside.glb");
  ASSERT_EQ(
      run("simplify", in.string() + " " + beside.string() + " 0.5 --policy gh --quiet").exit_code,
      0);
  EXPECT_NE(read_text(beside).find("\"uri\":\"tex/skin.png\""), std::string::npos);
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

// bob's material names bob_diffuse.png (map_Kd), as gltfpack and obj2gltf embed it: the GLB holds
// the file's bytes as its one image, the base colour texture of bob's material.
TEST_F(Cli, SimplifyEmbedsAnObjsTextureInAGlb) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path out = file("bob.glb");
  const Command_result r =
      run("simplify", test_meshes::data_file("bob_tri.obj") + " " + out.string() + " 0.5 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const apps::Gltf_soup read = apps::read_gltf(out.string(), true);
  ASSERT_EQ(read.looks->images.size(), 1u);
  const tinygltf::Image& image = read.looks->images[0];
  EXPECT_EQ(std::string(image.image.begin(), image.image.end()),
            read_text(test_meshes::data_file("bob_diffuse.png")));
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_TRUE(image.uri.empty());  // in the BIN chunk
  ASSERT_EQ(read.looks->textures.size(), 1u);
  EXPECT_EQ(read.looks->textures[0].source, 0);
  ASSERT_EQ(read.looks->materials.size(), 1u);
  EXPECT_EQ(read.looks->materials[0].pbrMetallicRoughness.baseColorTexture.index, 0);
}

// Real assets name textures they do not ship: the GLB is written all the same, without the
// texture, and one line says so, even with --quiet.
TEST_F(Cli, SimplifyWritesAGlbWithoutAMissingTextureAndOneWarning) {
  const fs::path in = file("grid.obj"), out = file("grid.glb");
  const fs::path library = write("grid.mtl", "newmtl skin\nmap_Kd missing.png\n");
  apps::write_mesh_atomically(textured_grid(), in.string(),
                              {{library.string()}, {"skin"}, nullptr, {}});
  const Command_result r =
      run("simplify", in.string() + " " + out.string() + " 0.5 --policy gh --quiet --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "simplify: warning: " + library.string() +
                       ": texture 'missing.png' does not exist; written without it\n");
  const apps::Gltf_soup read = apps::read_gltf(out.string(), true);
  EXPECT_EQ(double(read.soup.polygons.size()), json_number(r.out, "output_faces")) << r.out;
  EXPECT_EQ(read.looks->images.size(), 0u);
  EXPECT_EQ(read.looks->textures.size(), 0u);
  ASSERT_EQ(read.looks->materials.size(), 1u);
  EXPECT_EQ(read.looks->materials[0].name, "skin");
  EXPECT_EQ(read.looks->materials[0].pbrMetallicRoughness.baseColorTexture.index, -1);
}

// The faces of the mesh in `path`, after checking that every corner has a texture coordinate.
std::size_t uv_at_every_corner(const fs::path& path) {
  const Mesh mesh =
      apps::read_triangle_mesh(path.string(), nullptr, apps::Corner_attribute_reading::keep);
  const Attributes a(mesh);
  EXPECT_TRUE(a.uvs.has_value()) << path;
  std::size_t without = 0;
  for (const auto h : mesh.halfedges())
    without += a.uvs && !mesh.is_border(h) && !std::isfinite((*a.uvs)[h][0]);
  EXPECT_EQ(without, 0u) << path;
  return mesh.number_of_faces();
}

// A strip of four flat quads with a twisted quad at each end, each of which crosses itself seen
// along its normal (the reader refused them with exit 3 before it triangulated every polygon):
// all six are split, and their texture coordinates go through the run.
TEST_F(Cli, SimplifyTakesTwistedQuadsWithTheirTextureCoordinates) {
  std::ostringstream obj;
  const auto corner = [&obj](double x, double y, double z) {
    obj << "v " << x << ' ' << y << ' ' << z << "\nvt " << (x + 5) / 6 << ' ' << (y + 1) / 2
        << '\n';
  };
  const auto quad = [&obj](int first) {
    obj << "f";
    for (int k = first; k < first + 4; ++k) obj << ' ' << k << '/' << k;
    obj << '\n';
  };
  for (int x = -4; x < 0; ++x) {
    corner(x, -1, 0), corner(x + 1, -1, 0), corner(x + 1, 1, 0), corner(x, 1, 0);
    quad(4 * (x + 4) + 1);
  }
  // io_test's twisted quad, and the same turned half a turn about the strip's middle.
  corner(0, -1, 0), corner(1, 0, -0.5), corner(1, -1, -1), corner(0, 1, 0);
  quad(17);
  corner(-4, 1, 0), corner(-5, 0, -0.5), corner(-5, 1, -1), corner(-4, -1, 0);
  quad(21);
  const fs::path in = write("twisted.obj", obj.str()), out = file("out.obj");
  const Command_result r =
      run("simplify", in.string() + " " + out.string() + " --faces 8 --policy gh --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"triangulated 6 polygons\""), std::string::npos) << r.out;
  EXPECT_EQ(json_number(r.out, "input_faces"), 12) << r.out;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  EXPECT_LE(uv_at_every_corner(out), 8u);
  expect_texture_kept(in, out, 2000);
}

// Spot with what files from other tools carry: two degenerate faces, and a textured triangle
// that touches it at one point. The repair keeps every texture coordinate, and the simplified
// mesh tears no seam and turns no texture triangle over.
TEST_F(Cli, ARepairedTexturedMeshKeepsItsSeamsThroughSimplification) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const std::string spot = read_text(test_meshes::data_file("spot.obj"));
  // Spot's first point is where the extra triangle touches.
  const fs::path in = write("dirty.obj", spot +
                                             "f 1/1 1/1 2/2\nf 2/2 3/3 3/3\n"
                                             "v 2 2 2\nv 2 3 2\nvt 0.1 0.1\nvt 0.2 0.1\n"
                                             "vt 0.1 0.2\nf 1/-3 -2/-2 -1/-1\n");
  const fs::path out = file("out.obj");
  const Command_result r = run("simplify", in.string() + " " + out.string() + " 0.1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"dropped 2 degenerate or duplicate faces\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"oriented the faces and split 1 non-manifold vertices\""),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("dropped the texture coordinates"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  EXPECT_EQ(uv_at_every_corner(in), 5856u + 1);
  expect_texture_kept(in, out, 20000);
}

// glTF counts v from the image's top, OBJ from its bottom: bob's first corner, at v 0.728214 in
// the OBJ, is at 1 - 0.728214 in the GLB (gltfpack and obj2gltf write 0.271786 too), and back in
// an OBJ at 0.728214 to float precision.
TEST_F(Cli, ObjToGltfCountsVFromTheImagesTopAndBack) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const fs::path glb = file("bob.glb"), obj = file("bob.obj");
  ASSERT_EQ(
      run("simplify", test_meshes::data_file("bob_tri.obj") + " " + glb.string() + " 1 --policy gh")
          .exit_code,
      0);
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&model, &error, &warning, glb.string()))
      << error;
  const tinygltf::Primitive& primitive = model.meshes.at(0).primitives.at(0);
  const auto floats = [&model](int accessor) {
    const tinygltf::Accessor& a = model.accessors.at(std::size_t(accessor));
    const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(a.bufferView));
    const unsigned char* first = model.buffers.at(0).data.data() + view.byteOffset + a.byteOffset;
    std::vector<float> values(a.count *
                              std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type))));
    std::memcpy(values.data(), first, values.size() * sizeof(float));
    return values;
  };
  const std::vector<float> uvs = floats(primitive.attributes.at("TEXCOORD_0"));
  std::size_t at_first_corner = 0;
  for (std::size_t i = 0; i < uvs.size(); i += 2)
    if (uvs[i] == 0.799687f) {
      ++at_first_corner;
      EXPECT_EQ(uvs[i + 1], float(1 - 0.728214));
    }
  EXPECT_EQ(at_first_corner, 1u);
  ASSERT_EQ(run("simplify", glb.string() + " " + obj.string() + " 1 --policy gh").exit_code, 0);
  // The corner's coordinates as the GLB held them, v turned back: 0.728214 to float precision.
  const apps::Polygon_soup back = apps::parse_obj(obj.string(), read_text(obj));
  const std::array<double, 2> expected = {double(0.799687f), 1 - double(float(1 - 0.728214))};
  EXPECT_EQ(std::count(back.corners.uvs.begin(), back.corners.uvs.end(), expected), 1);
  EXPECT_NEAR(expected[1], 0.728214, 3e-8);
}

// bob as a GLB, its texture embedded, simplified into an OBJ: the OBJ's material library names
// bob's material and its image, written beside as the PNG's bytes, which the OBJ reader finds; the
// texture lies where it lay on bob (a v not turned back would turn every texture triangle over).
TEST_F(Cli, SimplifyWritesAGlbsMaterialsAndImagesBesideAnObj) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const std::string bob = test_meshes::data_file("bob_tri.obj");
  const fs::path glb = file("bob.glb");
  ASSERT_EQ(run("simplify", bob + " " + glb.string() + " 1 --policy gh --quiet").exit_code, 0);
  fs::create_directories(file("out"));
  const fs::path out = file("out") / "bob.obj";
  const Command_result r =
      run("simplify", glb.string() + " " + out.string() + " 0.5 --policy gh --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(read_text(file("out") / "bob.mtl"),
            "# written by cgal_policies\n\nnewmtl feathers\nKd 1 1 1\nmap_Kd bob_image0.png\n");
  EXPECT_EQ(read_text(file("out") / "bob_image0.png"),
            read_text(test_meshes::data_file("bob_diffuse.png")));
  EXPECT_EQ(read_text(out).rfind("# written by cgal_policies\nmtllib bob.mtl\nv ", 0), 0u);
  apps::Read_report report;
  apps::read_triangle_mesh(out.string(), &report, apps::Corner_attribute_reading::keep);
  EXPECT_EQ(apps::diffuse_texture_file(report.materials),
            (file("out") / "bob_image0.png").string());
  expect_texture_kept(bob, out, 20000);
}

// A file the OBJ's library would write that is an image file of IN: refused, one line naming it,
// exit 4, and nothing written.
TEST_F(Cli, SimplifyRefusesToOverwriteAnImageOfIn) {
  Gltf_builder square = gltf_fixtures::textured_square(0, 2);
  square.model.images[1].uri = "out_image0.png";
  square.write(file("in.glb"));
  const fs::path image = write("out_image0.png", "the input's");
  expect_failure(file("in.glb").string() + " " + file("out.obj").string() + " 1 --policy gh", 4,
                 image, file("out.obj"));
  EXPECT_FALSE(fs::exists(file("out.mtl")));
  EXPECT_EQ(read_text(image), "the input's");
}

// gltfpack's -c output (tests/apps/gltfpack/): quantized, meshopt-compressed, its texture
// coordinates under a transform. simplify reads it, carries them and writes a plain GLB.
TEST_F(Cli, SimplifyTakesGltfpacksCompressedOutput) {
  const fs::path in = fs::path(CGAL_POLICIES_SOURCE_DIR) / "tests" / "apps" / "gltfpack" /
                      "grid_meshopt.glb",
                 out = file("grid.glb");
  const Command_result r =
      run("simplify", in.string() + " " + out.string() + " --faces 32 --policy gh --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_number(r.out, "input_faces"), 128) << r.out;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
  EXPECT_LE(uv_at_every_corner(out), 32u);
  EXPECT_EQ(read_text(out).find("EXT_meshopt_compression"), std::string::npos);
  expect_texture_kept(in, out, 2000);
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

// spot at 10% in each glTF encoding: each file reads back with the faces simplify reports and
// texture coordinates at every corner; quantized is smaller than float and meshopt than
// quantized, and the meshopt file reads back exactly as the quantized one.
TEST_F(Cli, SimplifyWritesEachGltfEncoding) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const std::string spot = test_meshes::data_file("spot.obj");
  std::map<std::string, std::uintmax_t> bytes;
  std::map<std::string, std::vector<apps::Point>> points;
  for (const std::string encoding : {"float", "quantized", "meshopt"}) {
    SCOPED_TRACE(encoding);
    const fs::path out = file(encoding + ".glb");
    const Command_result r =
        run("simplify",
            spot + " " + out.string() + " 0.1 --policy gh --json --gltf-encoding " + encoding);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LE(json_number(r.out, "target_gap_faces"), 0) << r.out;
    EXPECT_EQ(double(uv_at_every_corner(out)), json_number(r.out, "output_faces")) << r.out;
    const Mesh read =
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
    for (const auto v : read.vertices()) points[encoding].push_back(read.point(v));
    bytes[encoding] = fs::file_size(out);
  }
  EXPECT_LT(bytes["quantized"], bytes["float"]);
  EXPECT_LT(bytes["meshopt"], bytes["quantized"]);
  EXPECT_EQ(points["meshopt"], points["quantized"]);
  EXPECT_EQ(points["quantized"].size(), points["float"].size());
}

// --gltf-encoding is for a glTF OUT, and takes one of three names: anything else is one usage line
// naming it, before IN is read, and no file.
TEST_F(Cli, GltfEncodingIsRefusedUnlessOutIsGltf) {
  const fs::path in = write("tet.off", kTetrahedronOff);
  for (const char* out : {"out.obj", "out.ply"})
    expect_failure(in.string() + " " + file(out).string() + " 1 --gltf-encoding quantized",
                   apps::exit_usage, "--gltf-encoding", file(out));
  expect_failure(
      in.string() + " " + file("out.obj").string() + " --lod 0.5,0.25 --gltf-encoding meshopt",
      apps::exit_usage, "--gltf-encoding", file("out_lod0.obj"));
  expect_failure(in.string() + " " + file("out.glb").string() + " 1 --gltf-encoding draco",
                 apps::exit_usage, "--gltf-encoding", file("out.glb"));
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
  Gltf_builder no_view = one_triangle({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2});
  no_view.model.accessors[0].bufferView = 7;  // only views 0 and 1 exist
  no_view.write(file("no_view.glb"));
  Gltf_builder raw_uvs = two_primitive_square();
  raw_uvs.model.accessors[4].normalized = false;  // the second primitive's u16 coordinates
  raw_uvs.write(file("raw_uvs.glb"));
  Gltf_builder cycle = two_primitive_square();
  cycle.model.nodes[0].children = {0};  // its own child
  cycle.write(file("cycle.glb"));
  two_primitive_square().write(file("whole.glb"));
  const std::string whole = read_text(file("whole.glb"));
  write("truncated.glb", whole.substr(0, whole.size() / 2));
  // Eight bytes fewer, the header's length to match: the BIN chunk now ends past the file.
  std::string overrun = whole.substr(0, whole.size() - 8);
  const std::uint32_t overrun_length = std::uint32_t(overrun.size());
  overrun.replace(8, 4, reinterpret_cast<const char*>(&overrun_length), 4);
  write("chunk_overrun.glb", overrun);
  // gltf-pipeline's Draco file (tests/apps/draco), its compressed view cut from 6,799 bytes to
  // 100 (the JSON keeps its length: a space pads the number).
  std::string draco =
      read_text(fs::path(CGAL_POLICIES_SOURCE_DIR) / "tests/apps/draco/bob_draco.glb");
  const std::size_t view_length = draco.find("\"byteLength\":6799}");
  ASSERT_NE(view_length, std::string::npos);
  draco.replace(view_length, 18, "\"byteLength\":100 }");
  write("truncated_draco.glb", draco);
  write("malformed.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [");
  write("missing_buffer.gltf",
        "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"gone.bin\", "
        "\"byteLength\": 36}]}");
  const std::map<std::string, std::string> causes = {
      {"nan.glb", "mesh 0 primitive 0: the position of vertex 2 is not finite"},
      {"index.glb", "mesh 0 primitive 0: index 3 is out of range (3 vertices)"},
      {"no_view.glb", "mesh 0 primitive 0 POSITION (accessor 0): no bufferView"},
      {"raw_uvs.glb",
       "mesh 0 primitive 1 TEXCOORD_0 (accessor 4): integer values must be normalized"},
      {"cycle.glb", "the node hierarchy has a cycle"},
      {"truncated.glb", "cannot parse: "},
      {"chunk_overrun.glb", "cannot parse: the GLB chunk at byte "},
      {"truncated_draco.glb",
       "mesh 0 primitive 0: its Draco data do not decode (Failed to decode geometry data.)"},
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

// A sphere streamed in two cells from a binary PLY (with a property besides x, y, z and its
// texture coordinates u, v) and from an OBJ (the same texture coordinates on its corners, indices
// counted back from the last vertex and the last vt): the same output from both, texture
// coordinates on every corner, at the target, closed, and no spill file left in TMPDIR.
TEST_F(Cli, OutOfCoreReadsBinaryPlyAndObjAlike) {
  const Mesh sphere = test_meshes::loop_sphere(2);
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(sphere.number_of_vertices()) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float confidence\nproperty float u\nproperty float v\nelement face " +
                    std::to_string(sphere.number_of_faces()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string obj;
  const auto append = [&ply](const auto value) {
    ply.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  for (const auto v : sphere.vertices()) {
    const apps::Point& p = sphere.point(v);
    const float u = float(0.5 + 0.25 * p.x()), w = float(0.5 + 0.25 * p.y());
    for (const double c : {p.x(), p.y(), p.z(), 1.0}) append(float(c));
    append(u);
    append(w);
    char line[160];  // each float exactly, as the PLY holds it
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", double(float(p.x())),
                  double(float(p.y())), double(float(p.z())), double(u), double(w));
    obj += line;
  }
  const int vertices = int(sphere.number_of_vertices());
  for (const auto f : sphere.faces()) {
    append(std::uint8_t(3));
    obj += "f";
    for (const auto v : CGAL::vertices_around_face(sphere.halfedge(f), sphere)) {
      append(std::int32_t(v));
      obj += " " + std::to_string(int(v) - vertices) + "/" + std::to_string(int(v) - vertices);
    }
    obj += "\n";
  }
  const fs::path spill = file("spill");
  fs::create_directories(spill);
  ::setenv("TMPDIR", spill.c_str(), 1);
  std::string outputs[2];
  for (const std::string name : {"sphere.ply", "sphere.obj"}) {
    const fs::path in = write(name, name == "sphere.ply" ? ply : obj),
                   out = file(name + ".out.ply");
    const Command_result r = run("simplify", in.string() + " " + out.string() +
                                                 " 0.5 --out-of-core --policy fast --parts 2 "
                                                 "--json --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(json_number(r.out, "input_faces"), 320) << r.out;
    EXPECT_EQ(json_number(r.out, "output_faces"), 160) << r.out;
    EXPECT_EQ(json_number(r.out, "parts"), 2) << r.out;
    EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
    const Mesh written =
        apps::read_triangle_mesh(out.string(), nullptr, apps::Corner_attribute_reading::keep);
    const apps::Mesh_validity validity = apps::check_mesh_validity(written);
    EXPECT_TRUE(validity.valid);
    EXPECT_TRUE(validity.closed);
    const cgal_policies::Corner_attributes<apps::Point> attributes(written);
    ASSERT_TRUE(attributes.uvs.has_value());
    for (const auto h : written.halfedges())
      if (!written.is_border(h)) {
        EXPECT_TRUE(std::isfinite((*attributes.uvs)[h][0]));
      }
    outputs[name == "sphere.obj"] = read_text(out);
  }
  ::unsetenv("TMPDIR");
  EXPECT_TRUE(outputs[0].substr(outputs[0].find("end_header")) ==
              outputs[1].substr(outputs[1].find("end_header")))
      << "the PLY and the OBJ gave different outputs";
  EXPECT_TRUE(fs::is_empty(spill));
}

// --lod with an OBJ or PLY OUT: a file per level, OUT's stem with _lod0, _lod1, ..., each level
// with exactly its share of IN's faces and made from the level before, as the JSON says.
TEST_F(Cli, LodWritesAFilePerLevelWithItsShareOfTheFaces) {
  const fs::path in = write_sphere(file("sphere.off"));
  const Command_result r = run("simplify", in.string() + " " + file("out.ply").string() +
                                               " --lod 0.5,0.25,0.1 --json --samples 2000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(file("out.ply")));
  const std::vector<double> faces = {160, 80, 32};
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const fs::path level = file("out_lod" + std::to_string(k) + ".ply");
    EXPECT_NE(r.out.find("\"output\": \"" + level.string() + "\""), std::string::npos) << r.out;
    EXPECT_EQ(double(apps::read_triangle_mesh(level.string()).number_of_faces()), faces[k]);
  }
  EXPECT_FALSE(fs::exists(file("out_lod3.ply")));
  EXPECT_EQ(json_numbers(r.out, "level"), std::vector<double>({0, 1, 2})) << r.out;
  EXPECT_EQ(json_numbers(r.out, "ratio"), std::vector<double>({0.5, 0.25, 0.1})) << r.out;
  EXPECT_EQ(json_numbers(r.out, "output_faces"), faces) << r.out;
  // IN's, then each level's input: the level before it.
  EXPECT_EQ(json_numbers(r.out, "input_faces"), std::vector<double>({320, 320, 160, 80})) << r.out;
  EXPECT_EQ(json_numbers(r.out, "hausdorff").size(), 3u) << r.out;
  EXPECT_EQ(json_numbers(r.out, "total_seconds").size(), 3u) << r.out;
  EXPECT_EQ(r.out.find("\"node\": "), std::string::npos) << r.out;  // a glTF OUT's alone
}

// The chain on bob, textured: each level within the error of the next coarser one, against IN, and
// its texture seams kept.
TEST_F(Cli, LodLevelsNeverHaveMoreErrorThanTheNextCoarserOne) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Command_result r =
      run("simplify", test_meshes::data_file("bob_tri.obj") + " " + file("bob.obj").string() +
                          " --lod 0.5,0.25,0.1,0.03 --json --samples 20000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_numbers(r.out, "output_faces"), std::vector<double>({5344, 2672, 1068, 320}))
      << r.out;
  for (const char* measure : {"hausdorff", "mean_a_to_b", "mean_b_to_a", "rms"}) {
    SCOPED_TRACE(measure);
    const std::vector<double> errors = json_numbers(r.out, measure);
    ASSERT_EQ(errors.size(), 4u) << r.out;
    EXPECT_GT(errors[0], 0);
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) EXPECT_LE(errors[k], errors[k + 1]);
  }
  EXPECT_EQ(json_numbers(r.out, "flipped_uv_faces"), std::vector<double>(4, 0)) << r.out;
  EXPECT_EQ(json_numbers(r.out, "seam_loops_b"), json_numbers(r.out, "seam_loops_a")) << r.out;
  EXPECT_NE(r.out.find("\"attributes\": \"carried\""), std::string::npos) << r.out;
}

// A glTF OUT holds every level: a mesh and a node each, the scene's node (the finest level)
// naming the others with MSFT_lod and giving their screen coverages.
TEST_F(Cli, LodGlbHoldsEveryLevelUnderMsftLod) {
  const fs::path in = write_sphere(file("sphere.off")), out = file("out.glb");
  const Command_result r = run("simplify", in.string() + " " + out.string() +
                                               " --lod 0.5,0.25,0.1 --json --quiet --samples 2000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(file("out_lod0.glb")));
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&model, &error, &warning, out.string()))
      << error;
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>({"MSFT_lod"}));
  EXPECT_TRUE(model.extensionsRequired.empty());
  ASSERT_EQ(model.scenes.size(), 1u);
  EXPECT_EQ(model.scenes[0].nodes, std::vector<int>({0}));
  const std::vector<std::size_t> faces = {160, 80, 32};
  ASSERT_EQ(model.nodes.size(), faces.size());
  ASSERT_EQ(model.meshes.size(), faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    EXPECT_EQ(model.nodes[k].mesh, int(k));
    std::size_t indices = 0;
    for (const tinygltf::Primitive& primitive : model.meshes[k].primitives)
      indices += model.accessors[std::size_t(primitive.indices)].count;
    EXPECT_EQ(indices, 3 * faces[k]) << "level " << k;
  }
  const tinygltf::Value& ids = model.nodes[0].extensions.at("MSFT_lod").Get("ids");
  ASSERT_TRUE(ids.IsArray());
  ASSERT_EQ(ids.ArrayLen(), 2u);
  EXPECT_EQ(ids.Get(0).GetNumberAsInt(), 1);
  EXPECT_EQ(ids.Get(1).GetNumberAsInt(), 2);
  for (std::size_t k = 1; k < faces.size(); ++k) EXPECT_TRUE(model.nodes[k].extensions.empty());
  // Level k suits ratio_k / ratio_0 of the screen: each gives way where the next suffices.
  const tinygltf::Value& coverage = model.nodes[0].extras.Get("MSFT_screencoverage");
  ASSERT_TRUE(coverage.IsArray());
  ASSERT_EQ(coverage.ArrayLen(), 3u);
  EXPECT_DOUBLE_EQ(coverage.Get(0).GetNumberAsDouble(), 0.5);
  EXPECT_DOUBLE_EQ(coverage.Get(1).GetNumberAsDouble(), 0.2);
  EXPECT_DOUBLE_EQ(coverage.Get(2).GetNumberAsDouble(), 0);
  EXPECT_EQ(json_numbers(r.out, "node"), std::vector<double>({0, 1, 2})) << r.out;
  EXPECT_EQ(json_numbers(r.out, "screen_coverage"), std::vector<double>({0.5, 0.2, 0})) << r.out;
  // A reader without MSFT_lod, ours included, sees the finest level.
  EXPECT_EQ(apps::read_gltf(out.string(), true).soup.polygons.size(), faces[0]);
}

// A bad --lod is one usage line naming it, before IN is read (it does not exist here: reading it
// would fail with 3), and no file.
TEST_F(Cli, BadLodValuesAreOneUsageLineAndNoFile) {
  const fs::path in = file("missing.off"), out = file("out.obj");
  for (const char* lod :
       {"''", "0.5,0.5", "0.1,0.25", "0", "-0.5", "1.5", "0.5,abc", "0.5,,0.1", "x",
        "1,0.9,0.8,0.7,0.6,0.5,0.4,0.3,0.2,0.1,0.09,0.08,0.07,0.06,0.05,0.04,0.03", "0.5,0.25 0.5",
        "0.5,0.25 --faces 10"}) {
    SCOPED_TRACE(lod);
    expect_failure(in.string() + " " + out.string() + " --lod " + std::string(lod),
                   apps::exit_usage, "--lod", out);
    EXPECT_FALSE(fs::exists(file("out_lod0.obj")));
  }
  const fs::path sphere = write_sphere(file("sphere_lod1.off"));
  expect_failure(sphere.string() + " " + out.string() + " --lod 0.5 --out-of-core",
                 apps::exit_usage, "--lod", out);
  // Level 1's file would be IN.
  expect_failure(sphere.string() + " " + file("sphere.off").string() + " --lod 0.5,0.25",
                 apps::exit_usage, sphere, file("sphere_lod0.off"));
}

// The level files land all together or not at all: when level 1's cannot be put in place, level
// 0's, written already, is removed again, and no temporary is left.
TEST_F(Cli, LodFilesLandAllOrNone) {
  const fs::path in = write_sphere(file("sphere.off"));
  fs::create_directories(file("out_lod1.obj"));
  expect_failure(in.string() + " " + file("out.obj").string() + " --lod 0.5,0.25,0.1 --quiet",
                 apps::exit_bad_output, file("out_lod1.obj"), file("out_lod0.obj"));
  EXPECT_FALSE(fs::exists(file("out_lod2.obj")));
}

// What --out-of-core cannot read is one bad-input line naming the file, and what it cannot do
// with the input never whole, a usage error.
TEST_F(Cli, OutOfCoreRefusesWhatItCannotStream) {
  const fs::path out = file("out.ply");
  const std::string triangle_ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const std::map<std::string, std::pair<std::string, std::string>> cases = {
      {"ascii.ply",
       {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "an ASCII PLY cannot be read out of core"}},
      {"truncated.ply", {triangle_ply + std::string(20, '\0'), "truncated"}},
      {"far.obj", {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4: '9' names no vertex"}},
      {"flat.obj", {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n", "no faces"}},
      {"tet.off", {kTetrahedronOff, "--out-of-core reads binary PLY and OBJ files only"}}};
  for (const auto& [name, contents_and_cause] : cases) {
    SCOPED_TRACE(name);
    const fs::path in = write(name, contents_and_cause.first);
    expect_failure(in.string() + " " + out.string() + " 0.5 --out-of-core", apps::exit_bad_input,
                   in, out);
    EXPECT_EQ(read_text(file("stderr"))
                  .find("simplify: " + in.string() + ": " + contents_and_cause.second),
              0u)
        << read_text(file("stderr"));
  }
  const fs::path in = write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\n");
  for (const char* option : {"--max-error 0.01", "--measure", "--min-component 5"}) {
    SCOPED_TRACE(option);
    const Command_result r =
        run("simplify", in.string() + " " + out.string() + " 0.5 --out-of-core " + option);
    EXPECT_EQ(r.exit_code, apps::exit_usage) << r.err;
    EXPECT_NE(r.err.find("--out-of-core never holds IN whole"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// The security defect of the glTF buffer with ".." (docs/reliability.md, "What an asset can make
// the tools read"): a buffer naming /etc/passwd, its size right, read as 32-bit float points. The
// tools refuse it, in one line naming the asset and the reference and nothing of the file, and
// write nothing; --asset-root widens the folder to a root that holds the asset, and no further.
TEST_F(Cli, AnAssetNamingAFileOutsideItsFolderIsBadInput) {
  const auto gltf = [](const std::string& uri, std::uintmax_t bytes) {
    const std::size_t points = std::size_t(bytes / 12);
    return R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" + uri + R"(","byteLength":)" +
           std::to_string(bytes) + R"(}],"bufferViews":[{"buffer":0,"byteLength":)" +
           std::to_string(points * 12) +
           R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" +
           std::to_string(points) +
           R"(,"type":"VEC3"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
  };
  fs::create_directories(file("asset"));
  const std::string passwd = "../../../../../../../../../../../../etc/passwd";
  const fs::path leak = write("asset/leak.gltf", gltf(passwd, fs::file_size("/etc/passwd")));
  const fs::path out = file("out.obj");
  for (const std::string& root : {std::string(), " --asset-root " + file("").string()}) {
    SCOPED_TRACE(root);
    expect_failure(leak.string() + " " + out.string() + " 1" + root, 3, leak, out);
    const Command_result r = run("simplify", leak.string() + " " + out.string() + " 1" + root);
    EXPECT_NE(r.err.find("a buffer's uri '" + passwd + "' leads outside the asset's folder"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("root:"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(std::to_string(fs::file_size("/etc/passwd"))), std::string::npos) << r.err;
  }
  const Command_result measured = run("mesh_error", leak.string() + " " + leak.string());
  EXPECT_EQ(measured.exit_code, 3) << measured.err;
  EXPECT_NE(measured.err.find("leads outside the asset's folder"), std::string::npos);

  // A folder the assets share, above their own: read with --asset-root alone.
  const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  write("common.bin", std::string(reinterpret_cast<const char*>(triangle), sizeof triangle));
  const fs::path above = write("asset/above.gltf", gltf("../common.bin", 36));
  expect_failure(above.string() + " " + out.string() + " 1", 3, above, out);
  const Command_result widened =
      run("simplify", above.string() + " " + out.string() + " 1 --asset-root " + file("").string());
  EXPECT_EQ(widened.exit_code, 0) << widened.err;
  const Command_result no_folder =
      run("simplify", above.string() + " " + out.string() + " 1 --force --asset-root " +
                          file("missing").string());
  EXPECT_EQ(no_folder.exit_code, 2) << no_folder.err;
  EXPECT_EQ(no_folder.err,
            "simplify: --asset-root: '" + file("missing").string() + "' is not a folder\n");
}

}  // namespace

// The apps restart once with glibc's malloc tunables; a user's own malloc tunables stand, and so
// does a restart's, so that it happens once.
TEST(TunedAllocator, TheTunablesAreAddedOnceAndAUsersMallocTunablesStand) {
  const std::optional<std::string> fresh = apps::tuned_allocator_tunables(nullptr);
  ASSERT_TRUE(fresh.has_value());
  EXPECT_EQ(*fresh,
            "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=67108864:"
            "glibc.malloc.trim_threshold=4294967296:glibc.malloc.mmap_threshold=33554432");
  EXPECT_EQ(apps::tuned_allocator_tunables(""), fresh);
  EXPECT_EQ(apps::tuned_allocator_tunables("glibc.rtld.optional_static_tls=4096"),
            "glibc.rtld.optional_static_tls=4096:" + *fresh);
  EXPECT_EQ(apps::tuned_allocator_tunables(fresh->c_str()), std::nullopt);
  EXPECT_EQ(apps::tuned_allocator_tunables("glibc.malloc.hugetlb=0"), std::nullopt);
}
