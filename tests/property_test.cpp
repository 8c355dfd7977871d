// Every policy of the registry on real meshes (style.md's property tests): valid output, the face
// target reached or a stop reason given, closed stays closed, Euler characteristic kept, finite
// coordinates, and two runs that write identical files. Also every policy on a tiny closed mesh.
#include "test_meshes.h"

#include "common/mesh_measures.h"
#include "common/policy_registry.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <tuple>

namespace {

using namespace test_meshes;

std::vector<std::string> policy_names() {
  std::vector<std::string> names;
  for (const apps::Policy_entry& p : apps::policy_registry()) names.push_back(p.name);
  return names;
}

// A gtest parameter name: letters, digits and underscores only.
std::string identifier(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return text;
}

std::string file_contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Simplifies `mesh` in place with the named policy and its default options.
apps::Simplify_outcome simplify(Mesh& mesh, const std::string& policy, std::size_t target) {
  const apps::Policy_entry* entry = apps::find_policy(policy);
  EXPECT_NE(entry, nullptr);
  const apps::Simplify_outcome outcome = entry->run(mesh, apps::default_settings(*entry, target));
  mesh.collect_garbage();
  return outcome;
}

class Every_policy_on_real_meshes
    : public testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(Every_policy_on_real_meshes, KeepsTheInvariantsAtTenPercent) {
  SKIP_WITHOUT_SHARED_DATA();
  const auto& [policy, mesh_name] = GetParam();
  const Mesh input = apps::read_triangle_mesh(shared_data(mesh_name));
  const apps::Mesh_validity before = apps::check_mesh_validity(input);
  const std::size_t target = std::size_t(std::llround(0.1 * input.number_of_faces()));

  std::string written[2];
  for (int run = 0; run < 2; ++run) {
    Mesh mesh = input;
    const apps::Simplify_outcome outcome = simplify(mesh, policy, target);
    const apps::Mesh_validity after = apps::check_mesh_validity(mesh);
    EXPECT_TRUE(after.valid);
    if (outcome.stop_reason == "target_reached")
      EXPECT_NEAR(double(mesh.number_of_faces()), double(target), 0.01 * double(target));
    else
      EXPECT_EQ(outcome.stop_reason, "no_collapse_left");
    EXPECT_LT(mesh.number_of_faces(), input.number_of_faces());
    if (before.closed) {
      EXPECT_TRUE(after.closed);
    }
    EXPECT_EQ(after.euler_characteristic, before.euler_characteristic);
    for (auto v : vertices(mesh)) {
      const Point& p = mesh.point(v);
      ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
    }
    const std::string path =
        testing::TempDir() + "property_" + policy + "_" + std::to_string(run) + ".ply";
    apps::write_mesh_atomically(mesh, path);
    written[run] = file_contents(path);
    std::remove(path.c_str());
  }
  EXPECT_FALSE(written[0].empty());
  EXPECT_TRUE(written[0] == written[1]) << "two runs wrote different files";
}

INSTANTIATE_TEST_SUITE_P(
    Registry, Every_policy_on_real_meshes,
    testing::Combine(testing::ValuesIn(policy_names()),
                     testing::Values("bunny.obj", "fandisk.obj", "rocker-arm.obj", "teapot.obj")),
    [](const auto& test) {
      return identifier(std::get<0>(test.param) + "_" + std::get<1>(test.param));
    });

class Every_policy : public testing::TestWithParam<std::string> {};

TEST_P(Every_policy, CollapsesAnIcosahedronToATetrahedronAtMost) {
  // With its error bound lifted (a tolerance of ten diagonals), every policy can go as far as the
  // link condition lets it: four faces.
  Mesh mesh = icosahedron();
  const apps::Policy_entry& entry = *apps::find_policy(GetParam());
  apps::Simplify_settings settings = apps::default_settings(entry, 0);
  if (settings.options.count("tolerance")) settings.options["tolerance"] = 10;
  const apps::Simplify_outcome outcome = entry.run(mesh, settings);
  mesh.collect_garbage();
  EXPECT_EQ(outcome.stop_reason, "no_collapse_left");
  EXPECT_EQ(mesh.number_of_faces(), 4u);
  EXPECT_EQ(mesh.number_of_vertices(), 4u);
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_TRUE(apps::check_mesh_validity(mesh).valid);
}

TEST_P(Every_policy, LeavesAMeshAtItsTargetUntouched) {
  Mesh mesh = icosahedron();
  const Mesh before = mesh;
  const apps::Simplify_outcome outcome = simplify(mesh, GetParam(), 20);
  EXPECT_EQ(outcome.stop_reason, "target_reached");
  ASSERT_EQ(mesh.number_of_vertices(), before.number_of_vertices());
  for (auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v), before.point(v));
}

INSTANTIATE_TEST_SUITE_P(Registry, Every_policy, testing::ValuesIn(policy_names()),
                         [](const auto& test) { return identifier(test.param); });

}  // namespace
