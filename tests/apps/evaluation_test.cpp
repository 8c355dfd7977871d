// The two-sided Metro-style evaluator behind mesh_error (docs/evaluation.md), and its comparison of
// corner attributes (mesh_error --attributes).
#include "test_meshes.h"

#include "io/mesh_io.h"

#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "pipeline_runs.h"

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <cgal_policies/Corner_attributes.h>

#include <gtest/gtest.h>

#include <utility>

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
  pipeline_runs::simplify(mesh, "gh", std::size_t(ratio * input.number_of_faces()));
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

// A triangle whose last two corners are the same point: CGAL 5.5's projection onto it, with its
// corners in this order, gives a corner for the middle point, half its length away (the fuzz
// finding of fuzz/regressions/policies/evaluator_zero_area_triangle).
TEST(MeshError, ATriangleWithTwoEqualCornersIsAtDistanceZeroFromItself) {
  const Mesh sliver = from_triangles({{4, 8, 1}, {0, 0, 0}, {0, 0, 0}}, {{0, 1, 2}});
  const apps::Mesh_error e = apps::measure_mesh_error(sliver, sliver, kSamples);
  EXPECT_NEAR(e.bbox_diagonal, 9.0, 1e-12);
  EXPECT_LE(e.hausdorff, 1e-12);
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

TEST(MeshError, FaceSamplesKnowTheirFaceAndWeights) {
  const Mesh sphere = loop_sphere(2);
  const std::vector<apps::Face_sample> samples = apps::sample_face_points(sphere, 1000);
  const std::vector<Point> points = apps::sample_faces(sphere, 1000);
  ASSERT_EQ(samples.size(), 1000u);
  ASSERT_EQ(points.size(), 1000u);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const apps::Face_sample& s = samples[i];
    EXPECT_EQ(s.point, points[i]);
    const auto h = halfedge(s.face, sphere);
    const Point& p = sphere.point(target(h, sphere));
    const Point& q = sphere.point(target(next(h, sphere), sphere));
    const Point& r = sphere.point(target(prev(h, sphere), sphere));
    for (double w : s.weights) EXPECT_GE(w, 0);
    EXPECT_NEAR(s.weights[0] + s.weights[1] + s.weights[2], 1, 1e-15);
    EXPECT_EQ(s.point, Point(p.x() * s.weights[0] + q.x() * s.weights[1] + r.x() * s.weights[2],
                             p.y() * s.weights[0] + q.y() * s.weights[1] + r.y() * s.weights[2],
                             p.z() * s.weights[0] + q.z() * s.weights[1] + r.z() * s.weights[2]));
  }
}

// mesh_error --attributes on tiny meshes whose every figure is known.
using Attributes = cgal_policies::Corner_attributes<Point>;
constexpr std::size_t kAttributeSamples = 20000;

TEST(AttributeError, ATexturedPlaneAgainstItselfHasNone) {
  const Mesh plane = textured_plane(true);
  const apps::Attribute_error e = apps::measure_attribute_error(plane, plane, kAttributeSamples);
  ASSERT_TRUE(e.uv_mean_rel && e.uv_max_rel && e.normal_angle_mean_deg && e.flipped_uv_faces);
  // Zero up to the round-off of the closest point's weights.
  EXPECT_LE(*e.uv_mean_rel, 1e-15);
  EXPECT_LE(*e.uv_max_rel, 1e-15);
  EXPECT_EQ(*e.normal_angle_mean_deg, 0);
  EXPECT_EQ(*e.normal_angle_max_deg, 0);
  EXPECT_EQ(*e.flipped_uv_faces, 0u);
  // No seam inside: the 16 border edges, one loop.
  EXPECT_EQ(e.seam_edges_a, 16u);
  EXPECT_EQ(e.seam_edges_b, 16u);
  EXPECT_EQ(e.seam_loops_a, 1u);
  EXPECT_EQ(e.seam_loops_b, 1u);
}

TEST(AttributeError, ShiftedTextureCoordinatesAreOffByTheShiftOverTheExtent) {
  const Mesh a = textured_plane(false);
  Mesh b = a;
  const Attributes shifted(b);
  for (auto h : halfedges(b))
    if (!b.is_border(h)) (*shifted.uvs)[h][0] += 0.1;
  const apps::Attribute_error e = apps::measure_attribute_error(a, b, kAttributeSamples);
  ASSERT_TRUE(e.uv_mean_rel && e.uv_max_rel);
  EXPECT_NEAR(*e.uv_mean_rel, 0.1 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(*e.uv_max_rel, 0.1 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(e.flipped_uv_faces, 0u);
  EXPECT_FALSE(e.normal_angle_mean_deg);  // neither has normals
  EXPECT_EQ(e.seam_loops_b, 1u);
}

TEST(AttributeError, NormalsTurnedByThirtyDegrees) {
  const Mesh a = textured_plane(true);
  Mesh b = a;
  const double angle = 30 * M_PI / 180;
  const Attributes turned(b);
  for (auto h : halfedges(b))
    if (!b.is_border(h))
      (*turned.normals)[h] = Kernel::Vector_3(std::sin(angle), 0, std::cos(angle));
  const apps::Attribute_error e = apps::measure_attribute_error(a, b, kAttributeSamples);
  ASSERT_TRUE(e.normal_angle_mean_deg && e.normal_angle_max_deg && e.uv_max_rel);
  EXPECT_NEAR(*e.normal_angle_mean_deg, 30, 1e-9);
  EXPECT_NEAR(*e.normal_angle_max_deg, 30, 1e-9);
  EXPECT_LE(*e.uv_max_rel, 1e-15);
}

// A colour field x / 4 in red against the same field with green raised by 0.3 and alpha lowered by
// 0.4: off by 0.5 everywhere. Without colours on one side, no colour field.
TEST(AttributeError, ColoursOffByAConstantAreOffByItsLength) {
  Mesh a = flat_grid(4);
  paint_colors(a, [](Mesh::Face_index, const Point& p) {
    return std::array<double, 4>{p.x() / 4, 0.2, 0.1, 1};
  });
  Mesh b = a;
  const Attributes changed(b);
  for (auto h : halfedges(b))
    if (!b.is_border(h)) {
      (*changed.colors)[h][1] += 0.3;
      (*changed.colors)[h][3] -= 0.4;
    }
  const apps::Attribute_error e = apps::measure_attribute_error(a, b, kAttributeSamples);
  ASSERT_TRUE(e.color_mean && e.color_max);
  EXPECT_NEAR(*e.color_mean, 0.5, 1e-12);
  EXPECT_NEAR(*e.color_max, 0.5, 1e-12);
  EXPECT_FALSE(e.uv_mean_rel);
  EXPECT_EQ(e.seam_loops_a, 1u);
  const apps::Attribute_error same = apps::measure_attribute_error(a, a, kAttributeSamples);
  EXPECT_LE(*same.color_max, 1e-15);
  EXPECT_FALSE(apps::measure_attribute_error(a, flat_grid(4), kAttributeSamples).color_mean);
}

TEST(AttributeError, AMirroredTextureTriangleIsOneFlippedFaceInsideASeamLoop) {
  const Mesh a = textured_plane(false);
  Mesh b = a;
  // The face (1, 1) -> (2, 1) -> (2, 2), inside the grid, with the texture coordinates of its
  // corners at (2, 1) and (2, 2) swapped: it turns clockwise in the texture.
  const auto h = halfedge_between(b, Point(1, 1, 0), Point(2, 1, 0));
  const Attributes mirrored(b);
  std::swap((*mirrored.uvs)[h], (*mirrored.uvs)[next(h, b)]);
  ASSERT_GT(uv_area(a, face(h, a)), 0);
  ASSERT_LT(uv_area(b, face(h, b)), 0);
  const apps::Attribute_error e = apps::measure_attribute_error(a, b, kAttributeSamples);
  ASSERT_TRUE(e.uv_max_rel);
  EXPECT_EQ(e.flipped_uv_faces, 1u);
  // Its three edges disagree with their neighbours: a second seam loop besides the border.
  EXPECT_EQ(e.seam_edges_a, 16u);
  EXPECT_EQ(e.seam_edges_b, 19u);
  EXPECT_EQ(e.seam_loops_a, 1u);
  EXPECT_EQ(e.seam_loops_b, 2u);
  EXPECT_GT(*e.uv_max_rel, 0.1);
}

TEST(AttributeError, SeamsOfCubesWithSixAndWithThreeCharts) {
  // Six charts, one per side: each of the 12 cube edges is a seam of 4 grid edges, and they all
  // meet at the cube's corners: 48 seam edges, one component.
  Mesh six = six_sided_cube();
  paint_corners(
      six, [&](Mesh::Face_index f, const Point& p) { return cube_chart(cube_side(six, f), p); },
      false);
  const apps::Attribute_error e = apps::measure_attribute_error(six, six, kAttributeSamples);
  EXPECT_EQ(e.seam_edges_a, 48u);
  EXPECT_EQ(e.seam_loops_a, 1u);
  EXPECT_EQ(e.seam_edges_b, 48u);
  EXPECT_EQ(e.seam_loops_b, 1u);
  EXPECT_EQ(e.flipped_uv_faces, 0u);
  ASSERT_TRUE(e.uv_max_rel);
  EXPECT_LE(*e.uv_max_rel, 1e-15);
  // The four upright sides one chart, (x, y), top and bottom each their own, shifted away: two
  // rings of 4 cube edges, 16 grid edges each, that do not touch.
  Mesh three = six_sided_cube();
  paint_corners(
      three,
      [&](Mesh::Face_index f, const Point& p) {
        const int side = cube_side(three, f);
        return std::array<double, 2>{p.x() + (side == 0 ? 10 : side == 1 ? 20 : 0), p.y()};
      },
      false);
  const apps::Attribute_error rings = apps::measure_attribute_error(three, three, 100);
  EXPECT_EQ(rings.seam_edges_a, 32u);
  EXPECT_EQ(rings.seam_loops_a, 2u);
}

TEST(AttributeError, OnlyWhatBothMeshesHaveIsCompared) {
  const Mesh textured = textured_plane(false), bare = flat_grid(4);
  Mesh with_normals = flat_grid(4);
  const Attributes normals =
      Attributes::add(with_normals, {false, true, false, false, false, false});
  for (auto h : halfedges(with_normals))
    if (!with_normals.is_border(h)) (*normals.normals)[h] = Kernel::Vector_3(0, 0, 1);

  const apps::Attribute_error none = apps::measure_attribute_error(textured, bare, 100);
  EXPECT_FALSE(none.uv_mean_rel || none.uv_max_rel || none.flipped_uv_faces ||
               none.normal_angle_mean_deg || none.normal_angle_max_deg || none.seam_edges_a ||
               none.seam_edges_b || none.seam_loops_a || none.seam_loops_b);
  int present = 0;
  apps::for_each_field(none,
                       [&present](const char*, const auto& field) { present += bool(field); });
  EXPECT_EQ(present, 0);

  // Normals alone on both sides: their angle and the seams, no texture figure.
  const apps::Attribute_error normal_only =
      apps::measure_attribute_error(with_normals, with_normals, 100);
  EXPECT_FALSE(normal_only.uv_mean_rel || normal_only.uv_max_rel || normal_only.flipped_uv_faces);
  EXPECT_EQ(normal_only.normal_angle_max_deg, 0.0);
  EXPECT_EQ(normal_only.seam_edges_a, 16u);
  // Texture coordinates against normals: nothing in common, seams judged on different values.
  const apps::Attribute_error different =
      apps::measure_attribute_error(textured, with_normals, 100);
  EXPECT_FALSE(different.uv_mean_rel || different.normal_angle_mean_deg || different.seam_edges_a);
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
