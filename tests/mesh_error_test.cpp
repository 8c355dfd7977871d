// The two-sided Metro-style evaluator behind mesh_error (docs/evaluation.md).
#include "test_meshes.h"

#include "common/mesh_io.h"

#include "common/mesh_measures.h"
#include "common/policy_registry.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <gtest/gtest.h>

namespace {

using namespace test_meshes;

constexpr std::size_t kSamples = 50000;

Mesh unit_cube() {
  Mesh mesh;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                        Point(0, 1, 1), Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), mesh);
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  return mesh;
}

Mesh translated(Mesh mesh, double dx, double dy, double dz) {
  CGAL::Polygon_mesh_processing::transform(
      CGAL::Aff_transformation_3<apps::Kernel>(CGAL::TRANSLATION,
                                               apps::Kernel::Vector_3(dx, dy, dz)),
      mesh);
  return mesh;
}

Mesh simplified_by_gh(const Mesh& input, double ratio) {
  Mesh mesh = input;
  const apps::Policy_entry& gh = *apps::find_policy("gh");
  gh.run(mesh, apps::default_settings(gh, std::size_t(ratio * input.number_of_faces())));
  mesh.collect_garbage();
  return mesh;
}

TEST(MeshError, IdenticalMeshesAreAtDistanceZero) {
  const Mesh cube = unit_cube();
  const apps::Mesh_error e = apps::measure_mesh_error(cube, cube, kSamples);
  EXPECT_NEAR(e.bbox_diagonal, std::sqrt(3.0), 1e-12);
  EXPECT_LE(e.hausdorff, 1e-12);
  EXPECT_LE(e.mean_a_to_b, 1e-12);
  EXPECT_LE(e.mean_b_to_a, 1e-12);
  EXPECT_EQ(e.samples, kSamples);
}

TEST(MeshError, ATranslatedCubeIsAtTheTranslationDistance) {
  // The back face of the cube lies exactly d behind the moved cube; nothing lies farther.
  const double d = 0.05;
  const apps::Mesh_error e =
      apps::measure_mesh_error(unit_cube(), translated(unit_cube(), d, 0, 0), kSamples);
  EXPECT_NEAR(e.hausdorff, d, 0.01 * d);
  EXPECT_NEAR(e.hausdorff_a_to_b, d, 0.01 * d);
  EXPECT_NEAR(e.hausdorff_b_to_a, d, 0.01 * d);
  EXPECT_LT(e.mean_a_to_b, d);
}

TEST(MeshError, ATranslatedClosedScanIsAtTheTranslationDistance) {
  // A smooth closed surface has a point whose normal faces against any translation: it moves by d.
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Mesh cow =
      apps::read_triangle_mesh(std::string(CGAL_POLICIES_SOURCE_DIR) + "/data/cow.obj");
  ASSERT_TRUE(CGAL::is_closed(cow));
  const double d = 0.005 * apps::bbox_diagonal(cow);
  const apps::Mesh_error e = apps::measure_mesh_error(cow, translated(cow, 0, d, 0));
  EXPECT_NEAR(e.hausdorff, d, 0.01 * d);
}

TEST(MeshError, AMissingPartShowsInOneDirectionOnly) {
  // B is A without its top face: every point of B lies on A, while the centre of A's top is 0.5
  // away from the nearest wall of B.
  const Mesh a = unit_cube();
  Mesh b = a;
  std::vector<Mesh::Face_index> top;
  for (auto f : faces(b)) {
    bool on_top = true;
    for (auto v : vertices_around_face(halfedge(f, b), b)) on_top = on_top && b.point(v).z() == 1;
    if (on_top) top.push_back(f);
  }
  ASSERT_EQ(top.size(), 2u);
  for (auto f : top) CGAL::Euler::remove_face(halfedge(f, b), b);
  b.collect_garbage();
  const apps::Mesh_error e = apps::measure_mesh_error(a, b, kSamples);
  EXPECT_LE(e.hausdorff_b_to_a, 1e-12);
  EXPECT_NEAR(e.hausdorff_a_to_b, 0.5, 0.01);
  EXPECT_GT(e.mean_a_to_b, e.mean_b_to_a);
  EXPECT_DOUBLE_EQ(e.hausdorff, e.hausdorff_a_to_b);
}

TEST(MeshError, IsDeterministicAndItsDefaultSamplingIsDenseEnough) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Mesh bunny = apps::read_triangle_mesh(data_file("bunny.obj"));
  const Mesh simplified = simplified_by_gh(bunny, 0.1);

  const apps::Mesh_error once = apps::measure_mesh_error(bunny, simplified);
  const apps::Mesh_error again = apps::measure_mesh_error(bunny, simplified);
  EXPECT_EQ(once.hausdorff, again.hausdorff);
  EXPECT_EQ(once.mean_a_to_b, again.mean_a_to_b);
  EXPECT_EQ(once.rms, again.rms);

  const apps::Mesh_error doubled =
      apps::measure_mesh_error(bunny, simplified, 2 * apps::kDefaultErrorSamples);
  EXPECT_NEAR(doubled.mean_a_to_b, once.mean_a_to_b, 0.01 * once.mean_a_to_b);
  EXPECT_NEAR(doubled.mean_b_to_a, once.mean_b_to_a, 0.01 * once.mean_b_to_a);
}

TEST(MeshError, AgreesWithCgalsCertifiedHausdorffDistanceOnTheBunny) {
  // CGAL's bounded_error_Hausdorff_distance subdivides triangles until its answer is certain to
  // within the bound: an independent check of the sampled maxima, which can only fall short.
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Mesh bunny = apps::read_triangle_mesh(data_file("bunny.obj"));
  const Mesh simplified = simplified_by_gh(bunny, 0.1);
  const double bound = 1e-4 * apps::bbox_diagonal(bunny);
  namespace PMP = CGAL::Polygon_mesh_processing;
  const double certified_ab =
      PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(bunny, simplified, bound);
  const double certified_ba =
      PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(simplified, bunny, bound);
  const apps::Mesh_error e = apps::measure_mesh_error(bunny, simplified);
  EXPECT_NEAR(e.hausdorff_a_to_b, certified_ab, 0.05 * certified_ab);
  EXPECT_NEAR(e.hausdorff_b_to_a, certified_ba, 0.05 * certified_ba);
  EXPECT_LE(e.hausdorff_a_to_b, certified_ab + bound);
  EXPECT_LE(e.hausdorff_b_to_a, certified_ba + bound);
}

TEST(MeshValidity, CountsBordersAndTopology) {
  const apps::Mesh_validity grid = apps::check_mesh_validity(flat_grid(3));
  EXPECT_TRUE(grid.valid);
  EXPECT_FALSE(grid.closed);
  EXPECT_EQ(grid.boundary_edges, 12u);
  EXPECT_EQ(grid.euler_characteristic, 1);
  EXPECT_EQ(grid.degenerate_faces, 0u);
  EXPECT_NEAR(grid.min_angle_deg, 45.0, 1e-9);
  const apps::Mesh_validity ico = apps::check_mesh_validity(icosahedron());
  EXPECT_TRUE(ico.closed);
  EXPECT_EQ(ico.euler_characteristic, 2);
  EXPECT_NEAR(ico.min_angle_deg, 60.0, 1e-9);
}

}  // namespace
