// mesh_viewer: the collapse recording and its replay, the background task, the heat map's pieces,
// and the headless snapshots (OSMesa: no display needed), a glTF file's levels of detail among
// them.
#include "Collapse_replay.h"
#include "Latest_task.h"
#include "Render_mesh.h"
#include "Scene_renderer.h"
#include "Surface_distance.h"
#include "pipeline_runs.h"
#include "test_meshes.h"

#include "io/mesh_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using apps::Collapse_history;
using apps::Collapse_replay;
using apps::Indexed_mesh;
using apps::Mesh;
using apps::Point;
using Triangle = std::array<Point, 3>;

// The triangles as point triples, each turned to start at its smallest point (orientation kept),
// sorted: equal lists mean equal meshes up to vertex and face numbering.
std::vector<Triangle> canonical_triangles(const Indexed_mesh& mesh) {
  std::vector<Triangle> result;
  for (const auto& t : mesh.triangles) {
    Triangle p = {mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]};
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    result.push_back(p);
  }
  std::sort(result.begin(), result.end());
  return result;
}

Mesh simplified_straight(const Mesh& input, const apps::Policy_entry& policy, std::size_t target) {
  Mesh mesh = input;
  pipeline_runs::simplify(mesh, policy.name, target);
  return mesh;
}

Collapse_history record_all(const Mesh& input, const apps::Policy_entry& policy) {
  return apps::record_collapses(input, pipeline_runs::policy_alone(policy.name, 0));
}

// Replays the policy's recorded collapses at each face count in `counts` and compares with
// simplifying straight there. False when the policy reports no collapse: it simplifies outside
// the edge-collapse visitor (e.g. the fast threshold engine), and the viewer runs it straight.
bool replay_equals_straight(const Mesh& input, const apps::Policy_entry& policy,
                            const std::vector<std::size_t>& counts) {
  const Collapse_history history = record_all(input, policy);
  if (history.collapses.empty()) return false;
  const Collapse_replay replay(input, history);
  EXPECT_EQ(replay.faces_after(0), input.number_of_faces());
  EXPECT_EQ(replay.faces_after(replay.steps()), history.final_faces) << policy.name;
  for (std::size_t target : counts) {
    const Indexed_mesh replayed = replay.mesh_after(replay.step_for_target(target));
    const Mesh straight = simplified_straight(input, policy, target);
    EXPECT_EQ(replayed.triangles.size(), straight.number_of_faces())
        << policy.name << " " << target;
    EXPECT_EQ(replayed.vertex_count, straight.number_of_vertices()) << policy.name << " " << target;
    EXPECT_TRUE(canonical_triangles(replayed) ==
                canonical_triangles(Indexed_mesh::from_mesh(straight)))
        << policy.name << " at " << target << " faces";
  }
  return true;
}

// Every policy that reports its collapses replays exactly; CGAL's and the classic one must.
void expect_every_policy_replays(const Mesh& input, const std::vector<std::size_t>& counts) {
  std::vector<std::string> replayed;
  for (const apps::Policy_entry& policy : apps::policy_registry())
    if (replay_equals_straight(input, policy, counts)) replayed.push_back(policy.name);
  for (const char* name : {"gh", "gh-prob", "lt", "classic"})
    EXPECT_EQ(std::count(replayed.begin(), replayed.end(), name), 1) << name;
}

TEST(CollapseReplay, EveryFaceCountOfTheIcosahedronEqualsStraightSimplification) {
  const Mesh ico = test_meshes::icosahedron();
  std::vector<std::size_t> counts;
  for (std::size_t f = 20; f >= 1; --f) counts.push_back(f);
  expect_every_policy_replays(ico, counts);
}

TEST(CollapseReplay, EachCollapseRemovesOneFaceOnTheBorderAndTwoInside) {
  const Mesh grid = test_meshes::flat_grid(4);  // 32 triangles
  const Collapse_history history = record_all(grid, *apps::find_policy("classic"));
  const Collapse_replay replay(grid, history);
  ASSERT_EQ(replay.steps(), history.collapses.size());
  for (std::size_t s = 0; s < replay.steps(); ++s) {
    const std::size_t removed = replay.faces_after(s) - replay.faces_after(s + 1);
    EXPECT_TRUE(removed == 1 || removed == 2) << "collapse " << s << " removed " << removed;
    // The replay keeps every vertex index: the removed vertex is no longer used.
    const Indexed_mesh after = replay.mesh_after(s + 1);
    const auto gone = std::uint32_t(history.collapses[s].removed);
    for (const auto& t : after.triangles) EXPECT_EQ(std::count(t.begin(), t.end(), gone), 0);
    EXPECT_EQ(after.points[std::size_t(history.collapses[s].kept)],
              history.collapses[s].kept_point);
  }
  // No collapse is replayed at step 0: the input itself.
  EXPECT_TRUE(canonical_triangles(replay.mesh_after(0)) ==
              canonical_triangles(Indexed_mesh::from_mesh(grid)));
  EXPECT_EQ(replay.step_for_target(32), 0u);
  EXPECT_EQ(replay.step_for_target(0), replay.steps());
}

TEST(CollapseReplay, RealMeshAtSeveralCountsEqualsStraightSimplification) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  Mesh fandisk = apps::read_triangle_mesh(test_meshes::data_file("fandisk.obj"));
  fandisk.collect_garbage();
  const std::size_t f = fandisk.number_of_faces();
  expect_every_policy_replays(fandisk, {f, f - 1, f / 2 + 1, f / 10, f / 100, 4});
}

TEST(LatestTask, OnlyTheLatestJobHandsBackItsResult) {
  apps::Latest_task<int> task;
  std::promise<void> started, release;
  std::shared_future<void> released = release.get_future().share();
  task.submit([&started, released] {
    started.set_value();
    released.wait();
    return 1;
  });
  started.get_future().wait();
  task.submit([] { return 2; });
  task.submit([] { return 3; });  // replaces job 2, which never runs
  release.set_value();
  while (task.busy()) std::this_thread::yield();
  EXPECT_EQ(task.take(), std::optional<int>(3));
  EXPECT_EQ(task.take(), std::nullopt);  // once
}

TEST(LatestTask, RethrowsTheJobsError) {
  apps::Latest_task<int> task;
  task.submit([]() -> int { throw std::runtime_error("policy failed"); });
  while (task.busy()) std::this_thread::yield();
  EXPECT_THROW(task.take(), std::runtime_error);
}

TEST(SurfaceDistance, DistancesToAFlatGridAreHeights) {
  const apps::Surface_distance distance(test_meshes::flat_grid(2));
  EXPECT_DOUBLE_EQ(distance(Point(1, 1, 0.5)), 0.5);
  EXPECT_DOUBLE_EQ(distance(Point(3, 1, 0)), 1.0);  // beyond the border x = 2

  // Cached per point version: the second mesh reuses the first one's slot 0.
  Indexed_mesh lifted = Indexed_mesh::from_mesh(test_meshes::flat_grid(2));
  for (Point& p : lifted.points) p = Point(p.x(), p.y(), 0.25);
  std::vector<double> cache;
  const std::vector<double> d = distance.vertex_distances(lifted, cache);
  EXPECT_EQ(d, std::vector<double>(9, 0.25));
  lifted.points[0] = Point(0, 0, 7);  // the same version: the cache answers
  EXPECT_DOUBLE_EQ(distance.vertex_distances(lifted, cache)[0], 0.25);
}

TEST(RenderMesh, FrameCentresTheOriginalAtUnitDiagonal) {
  const Indexed_mesh grid = Indexed_mesh::from_mesh(test_meshes::flat_grid(2));  // [0,2]^2
  const apps::Mesh_frame frame = apps::Mesh_frame::of(grid);
  EXPECT_EQ(frame.center, Point(1, 1, 0));
  EXPECT_DOUBLE_EQ(frame.scale, 1 / std::sqrt(8.0));
  const apps::Render_mesh render =
      apps::make_render_mesh(grid, frame, std::vector<double>(9, 1.0), 1.0);
  ASSERT_EQ(render.vertices.size(), 9u * apps::Render_mesh::kFloatsPerVertex);
  EXPECT_EQ(render.indices.size(), 8u * 3);
  // Vertex 0 is (0, 0, 0): at (-1, -1, 0) / sqrt(8), normal +z, red (the top of the heat map).
  EXPECT_FLOAT_EQ(render.vertices[0], float(-1 / std::sqrt(8.0)));
  EXPECT_FLOAT_EQ(render.vertices[5], 1.0f);
  EXPECT_EQ(apps::heat_color(1), apps::heat_color(2));
  EXPECT_FLOAT_EQ(render.vertices[6], apps::heat_color(1)[0]);
  EXPECT_GT(apps::heat_color(0)[2], apps::heat_color(0)[0]);  // blue at 0
}

TEST(RenderMesh, ATexturedMeshHasAVertexPerCornerWithItsCoordinatesRowsDown) {
  Mesh grid = test_meshes::flat_grid(1);  // two triangles
  test_meshes::paint_corners(
      grid,
      [](Mesh::Face_index, const Point&) {
        return std::array<double, 2>{0.25, 0.75};
      },
      false);
  const apps::Render_mesh render =
      apps::make_corner_render_mesh(grid, apps::Mesh_frame::of(Indexed_mesh::from_mesh(grid)));
  ASSERT_EQ(render.vertices.size(), 6u * apps::Render_mesh::kFloatsPerVertex);
  EXPECT_EQ(render.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  for (std::size_t v = 0; v < 6; ++v) {
    const float* vertex = &render.vertices[v * apps::Render_mesh::kFloatsPerVertex];
    EXPECT_FLOAT_EQ(vertex[5], 1.0f);  // normal +z
    EXPECT_FLOAT_EQ(vertex[9], 0.25f);
    EXPECT_FLOAT_EQ(vertex[10], 0.25f);  // 1 - 0.75: the image's rows run down
  }
}

// The snapshots run the real binary: the same path as the command line, in a fresh folder.
class Snapshot : public ::testing::Test {
 protected:
  void SetUp() override {
    m_folder =
        std::filesystem::temp_directory_path() / ("viewer_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(m_folder);
  }
  void TearDown() override { std::filesystem::remove_all(m_folder); }

  int run_app(const std::string& app, const std::string& arguments) const {
    const std::string command = std::string(CGAL_POLICIES_BIN_DIR) + "/" + app + " " + arguments +
                                " > " + (m_folder / "out.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  int run_viewer(const std::string& arguments) const { return run_app("mesh_viewer", arguments); }
  int run_simplify(const std::string& arguments) const { return run_app("simplify", arguments); }
  std::string path(const std::string& name) const { return (m_folder / name).string(); }
  std::string output_text() const {
    std::ifstream in(m_folder / "out.txt");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

  // A square facing the camera, textured with a 2 x 1 image, red then blue: square.obj, its
  // square.mtl and red_blue.png.
  void write_textured_square() const {
    std::ofstream(path("square.obj"))
        << "mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl checker\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    std::ofstream(path("square.mtl")) << "newmtl checker\nmap_Kd -clamp on red_blue.png\n";
    const unsigned char red_blue[] = {255, 0, 0, 0, 0, 255};
    ASSERT_NE(stbi_write_png(path("red_blue.png").c_str(), 2, 1, 3, red_blue, 6), 0);
  }
  // A square whose left half is red and right half blue, stored per vertex in halves.ply (the
  // middle points twice, once per colour: a colour seam once read).
  void write_coloured_halves() const {
    std::ofstream(path("halves.ply"))
        << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
           "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
           "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
           "-1 -1 0 255 0 0\n0 -1 0 255 0 0\n0 1 0 255 0 0\n-1 1 0 255 0 0\n"
           "0 -1 0 0 0 255\n1 -1 0 0 0 255\n1 1 0 0 0 255\n0 1 0 0 0 255\n"
           "3 0 1 2\n3 0 2 3\n3 4 5 6\n3 4 6 7\n";
  }

  std::filesystem::path m_folder;
};

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  bool background(int x, int y) const {
    const unsigned char* p = &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
    return p[0] == apps::kBackground[0] && p[1] == apps::kBackground[1] &&
           p[2] == apps::kBackground[2];
  }
};

Picture load_png(const std::string& path) {
  Picture picture;
  int channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load(path.c_str(), &picture.width, &picture.height, &channels, 3), stbi_image_free);
  if (data)
    picture.rgb.assign(data.get(), data.get() + std::size_t(picture.width) * picture.height * 3);
  return picture;
}

// The pixels that differ between two pictures of one size in the columns [x0, x1), from row
// `first_row` down: below it the captions, which name the level, are out of the way.
std::size_t differing_pixels(const Picture& a, const Picture& b, int x0, int x1, int first_row) {
  std::size_t count = 0;
  for (int y = first_row; y < a.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = (std::size_t(y) * std::size_t(a.width) + std::size_t(x)) * 3;
      count += !std::equal(&a.rgb[i], &a.rgb[i] + 3, &b.rgb[i]);
    }
  return count;
}

TEST_F(Snapshot, BunnyAtTenPercentIsCentredAndDiffersFromFiftyPercent) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const std::string bunny = test_meshes::data_file("bunny.obj");
  ASSERT_EQ(run_viewer(bunny + " --policy classic --ratio 0.1 --size 640x300 --snapshot " +
                       path("ten.png")),
            0);
  ASSERT_EQ(run_viewer(bunny + " --policy classic --ratio 0.5 --size 640x300 --snapshot " +
                       path("fifty.png")),
            0);
  const Picture ten = load_png(path("ten.png")), fifty = load_png(path("fifty.png"));
  ASSERT_EQ(ten.width, 640);
  ASSERT_EQ(ten.height, 300);
  ASSERT_EQ(fifty.rgb.size(), ten.rgb.size());

  // Not blank, and the mesh where the camera looks: the middle of each pane.
  std::size_t drawn = 0, central = 0;
  for (int y = 0; y < ten.height; ++y)
    for (int x = 0; x < ten.width; ++x) {
      if (ten.background(x, y)) continue;
      ++drawn;
      const double pane_x = double(x % (ten.width / 2)) / (ten.width / 2),
                   pane_y = double(y) / ten.height;
      if (std::abs(pane_x - 0.5) < 0.3 && std::abs(pane_y - 0.5) < 0.3) ++central;
    }
  EXPECT_GT(drawn, std::size_t(ten.width * ten.height / 20));
  EXPECT_GT(central, drawn * 3 / 4);

  // The left panes show the same original; the right panes differ.
  const std::size_t left_differs = differing_pixels(ten, fifty, 0, ten.width / 2, 0),
                    right_differs = differing_pixels(ten, fifty, ten.width / 2, ten.width, 0);
  EXPECT_GT(right_differs, std::size_t(100));
  EXPECT_LT(left_differs, right_differs / 10);  // only the captions' text
}

TEST_F(Snapshot, HeatMapColoursTheSimplifiedPane) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  ASSERT_EQ(run_viewer(test_meshes::data_file("fandisk.obj") +
                       " --policy classic --ratio 0.02 --heat-map --size 400x200 --snapshot " +
                       path("heat.png")),
            0);
  const Picture picture = load_png(path("heat.png"));
  ASSERT_EQ(picture.width, 400);
  // Grey surfaces have r == g == b within a few levels; the heat map's colours do not.
  auto coloured = [&](int x0, int x1) {
    std::size_t count = 0;
    for (int y = 0; y < picture.height; ++y)
      for (int x = x0; x < x1; ++x) {
        const unsigned char* p = &picture.rgb[(std::size_t(y) * picture.width + x) * 3];
        count += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 40;
      }
    return count;
  };
  EXPECT_EQ(coloured(0, 200), 0u);
  EXPECT_GT(coloured(200, 400), 500u);
}

TEST_F(Snapshot, BadArgumentsAndUnwritableOutputsHaveTheirExitCodes) {
  const std::string tetra = path("t.off");
  {
    std::ofstream off(tetra);
    off << "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";
  }
  EXPECT_EQ(run_viewer(tetra + " --snapshot " + path("a.jpg")), 2);
  EXPECT_EQ(run_viewer(tetra + " --size 10x10 --snapshot " + path("a.png")), 2);
  EXPECT_EQ(run_viewer(tetra + " --size 64x64"), 2);
  EXPECT_EQ(run_viewer(tetra + " --snapshot " + path("missing/a.png")), 4);
  EXPECT_EQ(run_viewer(path("none.off") + " --snapshot " + path("a.png")), 3);
  EXPECT_EQ(run_viewer(tetra + " --ratio 1 --size 64x48 --snapshot " + path("a.png")), 0);
  EXPECT_EQ(load_png(path("a.png")).width, 64);
  EXPECT_FALSE(std::filesystem::exists(path("missing")));
}

TEST_F(Snapshot, SimplifyWritesTheMeshAndItsPicture) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  ASSERT_EQ(
      run_simplify(test_meshes::data_file("bunny.obj") + " " + path("bunny.off") +
                   " 0.1 --policy gh --json --snapshot " + path("bunny.png") + " --size 320x240"),
      0)
      << output_text();
  EXPECT_TRUE(std::filesystem::exists(path("bunny.off")));
  EXPECT_NE(output_text().find("\"snapshot\": \"" + path("bunny.png") + "\""), std::string::npos)
      << output_text();
  const Picture picture = load_png(path("bunny.png"));
  ASSERT_EQ(picture.width, 320);
  ASSERT_EQ(picture.height, 240);
  std::size_t left = 0, right = 0;  // drawn pixels in each pane
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x)
      if (!picture.background(x, y)) ++(x < picture.width / 2 ? left : right);
  EXPECT_GT(left, std::size_t(picture.width * picture.height / 40));
  EXPECT_GT(right, std::size_t(picture.width * picture.height / 40));
}

TEST_F(Snapshot, SimplifyWithABadSizeWritesNothing) {
  const std::string tetra = path("t.off");
  std::ofstream(tetra) << "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 "
                          "2 3\n3 1 3 2\n";
  for (const char* size : {"10x10", "320by240", "320x240x2", "0x240"}) {
    EXPECT_EQ(run_simplify(tetra + " " + path("t_out.off") + " 1 --snapshot " + path("t.png") +
                           " --size " + size),
              2)
        << size;
    EXPECT_FALSE(std::filesystem::exists(path("t_out.off"))) << size;
    EXPECT_FALSE(std::filesystem::exists(path("t.png"))) << size;
  }
  EXPECT_EQ(run_simplify(tetra + " " + path("t_out.off") + " 1 --size 64x64"), 2);
  EXPECT_EQ(run_simplify(tetra + " " + path("t_out.off") + " 1 --snapshot " + path("t.jpg")), 2);
  EXPECT_FALSE(std::filesystem::exists(path("t_out.off")));
}

// In both panes of a 200 x 100 picture of a square: red at a quarter of its width, blue at three
// quarters.
void expect_red_left_and_blue_right(const Picture& picture) {
  ASSERT_EQ(picture.width, 200);
  const int y = picture.height * 3 / 5;  // below the captions
  for (int pane = 0; pane < 2; ++pane) {
    int first = -1, last = -1;
    for (int x = pane * 100; x < pane * 100 + 100; ++x)
      if (!picture.background(x, y)) {
        if (first < 0) first = x;
        last = x;
      }
    ASSERT_GT(last - first, 20) << "pane " << pane;
    const auto at = [&](double t) {
      return &picture.rgb[(std::size_t(y) * 200 + std::size_t(first + t * (last - first))) * 3];
    };
    EXPECT_GT(int(at(0.25)[0]), int(at(0.25)[2]) + 100) << "pane " << pane;
    EXPECT_GT(int(at(0.75)[2]), int(at(0.75)[0]) + 100) << "pane " << pane;
  }
}

// The textured square: the picture shows red on the left of each square and blue on its right. A
// texture the material names but that is missing is bad input, and nothing is written.
TEST_F(Snapshot, ATexturedMeshIsDrawnWithItsTexture) {
  write_textured_square();
  ASSERT_EQ(run_simplify(path("square.obj") + " " + path("out.obj") + " 1 --snapshot " +
                         path("square.png") + " --size 200x100"),
            0)
      << output_text();
  const Picture picture = load_png(path("square.png"));
  expect_red_left_and_blue_right(picture);

  std::filesystem::remove(path("red_blue.png"));
  std::filesystem::remove(path("out.obj"));
  std::filesystem::remove(path("square.png"));
  EXPECT_EQ(run_simplify(path("square.obj") + " " + path("out.obj") + " 1 --snapshot " +
                         path("square.png")),
            3);
  EXPECT_NE(output_text().find("square.mtl: texture 'red_blue.png' does not exist"),
            std::string::npos)
      << output_text();
  EXPECT_FALSE(std::filesystem::exists(path("out.obj")));
  EXPECT_FALSE(std::filesystem::exists(path("square.png")));
  // Without a picture the texture is not needed.
  EXPECT_EQ(run_simplify(path("square.obj") + " " + path("out.obj") + " 1"), 0) << output_text();
}

// The coloured halves are drawn with their colours in both panes.
TEST_F(Snapshot, AColouredMeshIsDrawnWithItsColours) {
  write_coloured_halves();
  ASSERT_EQ(run_simplify(path("halves.ply") + " " + path("out.ply") + " 1 --snapshot " +
                         path("halves.png") + " --size 200x100"),
            0)
      << output_text();
  const Picture picture = load_png(path("halves.png"));
  expect_red_left_and_blue_right(picture);
  std::filesystem::remove(path("out.ply"));
  std::filesystem::remove(path("halves.png"));
}

// mesh_viewer draws both squares with their texture and colours as simplify does, the original and
// its simplification (which carries them); a missing texture is bad input there too.
TEST_F(Snapshot, TheViewerDrawsTexturesAndColours) {
  write_textured_square();
  write_coloured_halves();
  for (const std::string mesh : {"square.obj", "halves.ply"}) {
    ASSERT_EQ(run_viewer(path(mesh) + " --policy lt --ratio 1 --size 200x100 --snapshot " +
                         path("view.png")),
              0)
        << mesh << ": " << output_text();
    expect_red_left_and_blue_right(load_png(path("view.png")));
    std::filesystem::remove(path("view.png"));
  }
  std::filesystem::remove(path("red_blue.png"));
  EXPECT_EQ(run_viewer(path("square.obj") + " --snapshot " + path("view.png")), 3);
  EXPECT_NE(output_text().find("square.mtl: texture 'red_blue.png' does not exist"),
            std::string::npos)
      << output_text();
  EXPECT_FALSE(std::filesystem::exists(path("view.png")));
}

// The rows of a 200 x 100 picture below its captions (three lines of 12 pixels from row 10).
constexpr int kBelowCaptions = 60;

// A 2 x 2 grid of squares over the textured square, textured alike: plane.obj, sharing square.mtl.
void write_textured_plane(const std::string& obj) {
  std::ofstream(obj) << "mtllib square.mtl\n"
                        "v -1 -1 0\nv 0 -1 0\nv 1 -1 0\nv -1 0 0\nv 0 0 0\nv 1 0 0\n"
                        "v -1 1 0\nv 0 1 0\nv 1 1 0\n"
                        "vt 0 0\nvt 0.5 0\nvt 1 0\nvt 0 0.5\nvt 0.5 0.5\nvt 1 0.5\n"
                        "vt 0 1\nvt 0.5 1\nvt 1 1\nusemtl checker\n"
                        "f 1/1 2/2 5/5\nf 1/1 5/5 4/4\nf 2/2 3/3 6/6\nf 2/2 6/6 5/5\n"
                        "f 4/4 5/5 8/8\nf 4/4 8/8 7/7\nf 5/5 6/6 9/9\nf 5/5 9/9 8/8\n";
}

// The pixels whose red or blue exceeds the other two channels by 100: the texture's colours.
std::size_t texture_coloured_pixels(const Picture& picture) {
  std::size_t count = 0;
  for (std::size_t i = 0; i + 2 < picture.rgb.size(); i += 3) {
    const int r = picture.rgb[i], g = picture.rgb[i + 1], b = picture.rgb[i + 2];
    count += r > std::max(g, b) + 100 || b > std::max(r, g) + 100;
  }
  return count;
}

// The textured square and plane written as glTF by write_mesh_atomically and
// write_lod_chain_atomically: a GLB with the PNG in its BIN chunk, a .gltf with it in its buffer,
// a .gltf naming it by a percent-encoded uri, and a GLB of two levels, the plane then the square.
// Below the captions, mesh_viewer draws each as it draws the OBJ of the same mesh with its .mtl,
// pixel for pixel, every level of the chain included, and simplify --snapshot draws the GLB
// textured too; no warning.
TEST_F(Snapshot, AGltfBaseColourTextureIsDrawnAsTheObjsDiffuseMap) {
  write_textured_square();
  write_textured_plane(path("plane.obj"));
  apps::Read_report square_report, plane_report;
  const Mesh square = apps::read_triangle_mesh(path("square.obj"), &square_report,
                                               apps::Corner_attribute_reading::keep);
  const Mesh plane = apps::read_triangle_mesh(path("plane.obj"), &plane_report,
                                              apps::Corner_attribute_reading::keep);
  ASSERT_TRUE(
      apps::write_mesh_atomically(square, path("square.glb"), square_report.materials).empty());
  ASSERT_TRUE(
      apps::write_mesh_atomically(square, path("square.gltf"), square_report.materials).empty());
  ASSERT_TRUE(apps::write_lod_chain_atomically({{&plane, 0.5}, {&square, 0}}, path("chain.glb"),
                                               plane_report.materials)
                  .empty());
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(path("square.gltf")));
  ASSERT_EQ(gltf["images"].size(), 1u);
  gltf["images"][0] = {{"uri", "red%20blue.png"}};
  std::ofstream(path("external.gltf")) << gltf.dump();
  std::filesystem::copy_file(path("red_blue.png"), path("red blue.png"));

  const std::string options = " --policy lt --ratio 1 --size 200x100 --snapshot ";
  const auto snapshot = [&](const std::string& mesh, const std::string& arguments) {
    EXPECT_EQ(run_viewer(path(mesh) + arguments + options + path("view.png")), 0) << mesh;
    EXPECT_EQ(output_text().find("warning"), std::string::npos) << mesh << ": " << output_text();
    return load_png(path("view.png"));
  };
  const Picture square_obj = snapshot("square.obj", ""), plane_obj = snapshot("plane.obj", "");
  expect_red_left_and_blue_right(square_obj);
  expect_red_left_and_blue_right(plane_obj);
  std::filesystem::remove(path("red_blue.png"));  // the OBJ files' texture: not the glTF files'

  for (const std::string mesh : {"square.glb", "square.gltf", "external.gltf"}) {
    const Picture picture = snapshot(mesh, "");
    ASSERT_EQ(picture.rgb.size(), square_obj.rgb.size()) << mesh;
    EXPECT_EQ(differing_pixels(picture, square_obj, 0, 200, kBelowCaptions), 0u) << mesh;
  }
  const Picture level0 = snapshot("chain.glb", ""),
                level1 = snapshot("chain.glb", " --lod-level 1");
  ASSERT_EQ(level0.rgb.size(), plane_obj.rgb.size());
  ASSERT_EQ(level1.rgb.size(), square_obj.rgb.size());
  EXPECT_EQ(differing_pixels(level0, plane_obj, 0, 200, kBelowCaptions), 0u);
  EXPECT_EQ(differing_pixels(level1, square_obj, 0, 200, kBelowCaptions), 0u);

  ASSERT_EQ(run_simplify(path("square.glb") + " " + path("out.glb") + " 1 --snapshot " +
                         path("simplified.png") + " --size 200x100"),
            0)
      << output_text();
  EXPECT_EQ(output_text().find("warning"), std::string::npos) << output_text();
  expect_red_left_and_blue_right(load_png(path("simplified.png")));
}

// A base colour texture mesh_viewer cannot draw: a WebP file (stb decodes no WebP), a texture
// whose image is in KHR_texture_basisu alone (KTX2), an image file that is missing. Each is one
// warning line naming the file and the material; the picture is that of the file without the
// texture, in which no pixel has the texture's colours; exit 0. A morph target, which the reader
// leaves out, is the reader's one line, and the base shape's picture.
TEST_F(Snapshot, AGltfTextureThatCannotBeDecodedIsOneWarningAndAnUntexturedPicture) {
  write_textured_square();
  apps::Read_report report;
  const Mesh square =
      apps::read_triangle_mesh(path("square.obj"), &report, apps::Corner_attribute_reading::keep);
  apps::write_mesh_atomically(square, path("square.gltf"), report.materials);
  const nlohmann::json textured = nlohmann::json::parse(std::ifstream(path("square.gltf")));
  const auto write_variant = [&](const std::string& name, const auto& change) {
    nlohmann::json gltf = textured;
    change(gltf);
    std::ofstream(path(name)) << gltf.dump();
  };
  write_variant("plain.gltf", [](nlohmann::json& gltf) {
    gltf["materials"][0]["pbrMetallicRoughness"].erase("baseColorTexture");
  });
  write_variant("webp.gltf", [](nlohmann::json& gltf) {
    gltf["images"][0] = {{"uri", "skin.webp"}};
  });
  std::ofstream(path("skin.webp")) << std::string("RIFF\x1a\0\0\0WEBPVP8 \x0e\0\0\0", 20);
  write_variant("ktx2.gltf", [](nlohmann::json& gltf) {
    gltf["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};
    gltf["extensionsUsed"].push_back("KHR_texture_basisu");
  });
  write_variant("missing.gltf", [](nlohmann::json& gltf) {
    gltf["images"][0] = {{"uri", "none.png"}};
  });
  // A morph target (its positions, any accessor will do): the reader's line, the base shape drawn.
  write_variant("morphed.gltf", [](nlohmann::json& gltf) {
    gltf["materials"][0]["pbrMetallicRoughness"].erase("baseColorTexture");
    nlohmann::json& primitive = gltf["meshes"][0]["primitives"][0];
    primitive["targets"] = {{{"POSITION", primitive["attributes"]["POSITION"]}}};
  });

  const std::string options = " --policy lt --ratio 1 --size 200x100 --snapshot ";
  ASSERT_EQ(run_viewer(path("plain.gltf") + options + path("plain.png")), 0) << output_text();
  EXPECT_EQ(output_text().find("warning"), std::string::npos) << output_text();
  const Picture plain = load_png(path("plain.png"));
  ASSERT_EQ(plain.width, 200);
  EXPECT_EQ(texture_coloured_pixels(plain), 0u);

  const std::string material = ": material 'checker': its base colour texture ";
  const std::vector<std::pair<std::string, std::string>> warnings = {
      {"webp.gltf", "cannot be decoded (" + path("skin.webp") + ": unknown image type)"},
      {"ktx2.gltf", "has no PNG or JPEG image"},
      {"missing.gltf", "cannot be decoded (" + path("none.png") + ": can't fopen)"}};
  for (const auto& [mesh, cause] : warnings) {
    ASSERT_EQ(run_viewer(path(mesh) + options + path("view.png")), 0) << output_text();
    const std::string line =
        "mesh_viewer: warning: " + path(mesh) + material + cause + "; drawn without it\n";
    const std::string output = output_text();
    EXPECT_EQ(output.rfind(line, 0), 0u) << output;
    EXPECT_EQ(output.find("warning", line.size()), std::string::npos) << output;
    const Picture picture = load_png(path("view.png"));
    ASSERT_EQ(picture.rgb.size(), plain.rgb.size()) << mesh;
    EXPECT_EQ(differing_pixels(picture, plain, 0, 200, 0), 0u) << mesh;
  }
  ASSERT_EQ(run_viewer(path("morphed.gltf") + options + path("view.png")), 0) << output_text();
  const std::string morph_line =
      "mesh_viewer: warning: " + path("morphed.gltf") +
      ": mesh 0: its morph targets are left out; its base shape is read\n";
  const std::string output = output_text();
  EXPECT_EQ(output.rfind(morph_line, 0), 0u) << output;
  EXPECT_EQ(output.find("warning", morph_line.size()), std::string::npos) << output;
  EXPECT_EQ(differing_pixels(load_png(path("view.png")), plain, 0, 200, 0), 0u);
}

// Three spheres of 320, 80 and 20 faces (loop_sphere(2), loop_sphere(1), the icosahedron) written
// as one chain by write_lod_chain_atomically. The viewer shows level 0 unless --lod-level says
// otherwise, draws the level on the left and simplifies it on the right, and its summary line
// names the level and its faces. Below the captions, level 1's picture is that of the same sphere
// in a file of its own, and differs from level 0's in both panes.
TEST_F(Snapshot, ALodLevelIsDrawnAndSimplifiedAsAFileOfItsOwn) {
  const std::vector<Mesh> spheres = {test_meshes::loop_sphere(2), test_meshes::loop_sphere(1),
                                     test_meshes::icosahedron()};
  apps::write_lod_chain_atomically({{&spheres[0], 0.5}, {&spheres[1], 0.2}, {&spheres[2], 0}},
                                   path("chain.glb"));
  apps::write_mesh_atomically(spheres[1], path("level1.glb"));
  const std::string options = " --policy lt --ratio 0.5 --size 400x200 --snapshot ";
  const std::vector<std::string> level_arguments = {"", " --lod-level 1", " --lod-level 2"};
  const std::vector<std::string> summaries = {"level 0 of 0-2, lt: 320 -> 160 faces",
                                              "level 1 of 0-2, lt: 80 -> 40 faces",
                                              "level 2 of 0-2, lt: 20 -> 10 faces"};
  std::vector<Picture> levels;
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    const std::string png = path("level" + std::to_string(k) + ".png");
    ASSERT_EQ(run_viewer(path("chain.glb") + level_arguments[k] + options + png), 0)
        << output_text();
    EXPECT_EQ(output_text().rfind(summaries[k], 0), 0u) << output_text();
    levels.push_back(load_png(png));
    ASSERT_EQ(levels.back().width, 400);
  }
  ASSERT_EQ(run_viewer(path("level1.glb") + options + path("alone.png")), 0) << output_text();
  EXPECT_EQ(output_text().rfind("lt: 80 -> 40 faces", 0), 0u) << output_text();
  const Picture alone = load_png(path("alone.png"));
  ASSERT_EQ(alone.rgb.size(), levels[1].rgb.size());
  const int below_captions = 60;  // three lines of 12 pixels from row 10
  EXPECT_EQ(differing_pixels(levels[1], alone, 0, 400, below_captions), 0u);
  for (const int pane : {0, 1}) {
    SCOPED_TRACE("pane " + std::to_string(pane));
    EXPECT_GT(differing_pixels(levels[0], levels[1], pane * 200, pane * 200 + 200, below_captions),
              std::size_t(100));
  }
}

// --lod-level past the file's levels is one usage line (exit 2), as is one that is not a whole
// number; a bad MSFT_lod reference is one bad-input line naming the file (exit 3). No picture.
TEST_F(Snapshot, BadLodLevelsAndLodReferencesHaveTheirExitCodes) {
  const std::vector<Mesh> spheres = {test_meshes::loop_sphere(1), test_meshes::icosahedron()};
  const std::string chain = path("chain.gltf"), png = path("level.png");
  apps::write_lod_chain_atomically({{&spheres[0], 0.2}, {&spheres[1], 0}}, chain);
  EXPECT_EQ(run_viewer(chain + " --lod-level 2 --snapshot " + png), 2);
  EXPECT_EQ(output_text(), "mesh_viewer: --lod-level must be a whole number in [0, 1]: " + chain +
                               " has 2 levels of detail\n");
  apps::write_mesh_atomically(spheres[1], path("one.off"));
  EXPECT_EQ(run_viewer(path("one.off") + " --lod-level 1 --snapshot " + png), 2);
  EXPECT_EQ(output_text(), "mesh_viewer: --lod-level must be a whole number in [0, 0]: " +
                               path("one.off") + " has 1 level of detail\n");
  EXPECT_EQ(run_viewer(chain + " --lod-level 0.5 --snapshot " + png), 2);
  EXPECT_EQ(output_text(), "mesh_viewer: --lod-level must be a whole number in [0, 1e+15]\n");

  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(chain));
  gltf["nodes"][0]["extensions"]["MSFT_lod"]["ids"] = {5};
  std::ofstream(path("bad.gltf")) << gltf.dump();
  EXPECT_EQ(run_viewer(path("bad.gltf") + " --snapshot " + png), 3);
  EXPECT_EQ(output_text(), "mesh_viewer: " + path("bad.gltf") +
                               ": node 0's MSFT_lod names node 5, which does not exist\n");
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
