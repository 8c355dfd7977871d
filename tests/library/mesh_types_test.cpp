// Every part of the library that models a concept of CGAL's edge collapse (the cost and placement
// policies, the filters, the stop predicate) and the passes templated on the mesh, on every mesh
// type the edge collapse takes: Surface_mesh over two kernels, Polyhedron_3 with and without item
// ids, and OpenMesh's TriMesh_ArrayKernelT through CGAL's graph traits (when OpenMesh is found).
// Each reaches the target as a face-count stop does (the target, or one below it when the last
// collapse removes two faces), a valid mesh, and the same mean error as on Surface_mesh within a
// few percent: the collapse order may differ (OpenMesh orders its edges otherwise and rounds its
// default points to floats). docs/compatibility.md is the table these tests fill in.
#include "test_meshes.h"

#include "evaluation/surface_error.h"

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Bounded_normal_angle_filter.h>
#include <cgal_policies/Classic_quadric_policies.h>
#include <cgal_policies/Curvature_weighted_quadric_policies.h>
#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Fast_threshold_simplifier.h>
#include <cgal_policies/Feature_fusion_policies.h>
#include <cgal_policies/Flat_lindstrom_turk_simplifier.h>
#include <cgal_policies/Hausdorff_bounded_policies.h>
#include <cgal_policies/Laplacian_smoother.h>
#include <cgal_policies/Simplification_pipeline.h>
#include <cgal_policies/Two_sided_fitter.h>
#include <cgal_policies/small_components.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version.h>

#ifdef CGAL_POLICIES_WITH_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cartesian = CGAL::Simple_cartesian<double>;

// A mesh type and the kernel its points are in.
template <class TriangleMesh, class Kernel>
struct Mesh_type {
  using Mesh = TriangleMesh;
  using Traits = Kernel;
};

using Surface_mesh_epick = Mesh_type<CGAL::Surface_mesh<Epick::Point_3>, Epick>;
using Surface_mesh_cartesian = Mesh_type<CGAL::Surface_mesh<Cartesian::Point_3>, Cartesian>;
using Polyhedron = Mesh_type<CGAL::Polyhedron_3<Epick>, Epick>;
using Polyhedron_with_ids =
    Mesh_type<CGAL::Polyhedron_3<Epick, CGAL::Polyhedron_items_with_id_3>, Epick>;
#ifdef CGAL_POLICIES_WITH_OPENMESH
// CGAL's graph traits read OpenMesh's points as Epick's. OpenMesh's default points are floats;
// doubles are a traits class away.
using Open_mesh = Mesh_type<OpenMesh::TriMesh_ArrayKernelT<>, Epick>;
struct Double_points : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Open_mesh_double = Mesh_type<OpenMesh::TriMesh_ArrayKernelT<Double_points>, Epick>;
#endif

// The test input: a wavy sheet of 20 x 20 squares, each cut along alternating diagonals (800
// faces, a border, curvature of both signs), its heights a little uneven so that no two collapses
// cost the same (the order of equal costs follows the edges' order, which differs between mesh
// types), as a soup of the reference kernel.
struct Soup {
  std::vector<Epick::Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

constexpr int kSide = 20;
constexpr std::size_t kFaces = 2 * kSide * kSide;

Soup wavy_sheet() {
  constexpr int n = kSide;
  Soup soup;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      const unsigned hash = (unsigned(i) * 73856093u) ^ (unsigned(j) * 19349663u);
      const double unevenness = 0.002 * (double(hash % 1000) / 1000 - 0.5);
      soup.points.emplace_back(x, y, 0.15 * std::sin(6 * x) * std::cos(4 * y) + unevenness);
    }
  const auto at = [](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) {
        soup.triangles.push_back({a, b, c});
        soup.triangles.push_back({a, c, d});
      } else {
        soup.triangles.push_back({a, b, d});
        soup.triangles.push_back({b, c, d});
      }
    }
  return soup;
}

constexpr std::size_t kTarget = kFaces / 10;

// The soup as a mesh of that type, its points in the mesh's kernel.
template <class Mesh>
Mesh mesh_of(const Soup& soup) {
  using Point = typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  for (const auto& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.triangles, mesh);
  return mesh;
}

// The mesh as the error measure takes it: a Surface_mesh over Epick.
template <class Mesh>
test_meshes::Mesh reference_copy(const Mesh& mesh) {
  test_meshes::Mesh copy;
  CGAL::copy_face_graph(mesh, copy);
  return copy;
}

std::size_t faces_of(const test_meshes::Mesh& mesh) { return mesh.number_of_faces(); }

// The mean distance of the vertices of `a` to the surface of `b`.
double mean_vertex_distance(const test_meshes::Mesh& a, const test_meshes::Mesh& b) {
  const apps::Face_tree tree(faces(b).first, faces(b).second, b);
  double sum = 0;
  for (const auto v : a.vertices()) sum += std::sqrt(tree.squared_distance(a.point(v)));
  return sum / double(a.number_of_vertices());
}

// What a run left: the output as a Surface_mesh over Epick, its face count, its validity and its
// mean error against the input, both ways, at the vertices (each side's vertices to the other's
// surface: cheap enough for the sanitized Debug build, which runs every test too; the Metro-style
// measure of evaluation/ samples the faces as well).
struct Outcome {
  test_meshes::Mesh output;
  std::size_t faces = 0;
  bool valid = false;
  double mean_error = 0;
};

template <class Mesh>
Outcome outcome_of(const Mesh& mesh) {
  Outcome outcome;
  outcome.output = reference_copy(mesh);
  const test_meshes::Mesh input = mesh_of<test_meshes::Mesh>(wavy_sheet());
  outcome.faces = faces_of(outcome.output);
  outcome.valid = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh) &&
                  test_meshes::degenerate_face_count(outcome.output) == 0;
  outcome.mean_error =
      (mean_vertex_distance(input, outcome.output) + mean_vertex_distance(outcome.output, input)) /
      2;
  return outcome;
}

// A run on each mesh type: `simplify(mesh)` changes the mesh in place.
enum class Pass_run {
  classic,
  classic_with_normal_filter,
  curvature,
  fusion,
  hausdorff,
  fast,
  flat_lindstrom_turk,
  classic_then_fit,
  classic_then_smoothing,
};

template <class Mesh, class Policies, class Filter>
void collapse(Mesh& mesh, const Policies& policies, const Filter& filter) {
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh, kTarget);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .filter(filter));
  ASSERT_EQ(stop.reason(), cgal_policies::Stop_reason::target_reached);
}

template <class Type>
void simplify(typename Type::Mesh& mesh, Pass_run run) {
  using Mesh = typename Type::Mesh;
  using Traits = typename Type::Traits;
  const SMS::internal::Dummy_filter no_filter;
  switch (run) {
    case Pass_run::classic:
    case Pass_run::classic_then_fit:
    case Pass_run::classic_then_smoothing:
      collapse(mesh, cgal_policies::Classic_quadric_policies<Mesh, Traits>(mesh), no_filter);
      break;
    case Pass_run::classic_with_normal_filter:
      collapse(mesh, cgal_policies::Classic_quadric_policies<Mesh, Traits>(mesh),
               cgal_policies::Bounded_normal_angle_filter<>(30));
      break;
    case Pass_run::curvature:
      collapse(mesh, cgal_policies::Curvature_weighted_quadric_policies<Mesh, Traits>(mesh),
               no_filter);
      break;
    case Pass_run::fusion:
      collapse(mesh, cgal_policies::Feature_fusion_policies<Mesh, Traits>(mesh), no_filter);
      break;
    case Pass_run::hausdorff: {
      cgal_policies::Hausdorff_bounded_options options;
      options.beta = 0.02;
      const cgal_policies::Hausdorff_bounded_policies<Mesh, Traits> policies(mesh, options);
      collapse(mesh, policies, policies.get_filter());
      break;
    }
    case Pass_run::fast:
      ASSERT_TRUE(cgal_policies::Fast_threshold_simplifier()(mesh, kTarget).target_reached);
      break;
    case Pass_run::flat_lindstrom_turk:
      ASSERT_TRUE(cgal_policies::Flat_lindstrom_turk_simplifier()(mesh, kTarget).target_reached);
      break;
  }
  if (run == Pass_run::classic_then_fit) {
    const Mesh input = mesh_of<Mesh>(wavy_sheet());
    cgal_policies::Two_sided_fit_options options;
    options.rounds = 2;
    options.min_input_samples = 2000;
    cgal_policies::Two_sided_fitter<Mesh>(input, options).fit(mesh);
  }
  if (run == Pass_run::classic_then_smoothing)
    cgal_policies::Laplacian_smoother<Mesh>(0.3).smooth(mesh, 2);
}

template <class Type>
class MeshTypes : public testing::Test {
 protected:
  static void SetUpTestSuite() { RecordProperty("cgal", CGAL_VERSION_STR); }

  // The run on this mesh type beside the same run on Surface_mesh over Epick; `outcome`, when
  // given, gets this type's.
  static void expect_as_on_surface_mesh(Pass_run run, Outcome* outcome = nullptr) {
    typename Type::Mesh mesh = mesh_of<typename Type::Mesh>(wavy_sheet());
    ASSERT_NO_FATAL_FAILURE(simplify<Type>(mesh, run));
    test_meshes::Mesh reference = mesh_of<test_meshes::Mesh>(wavy_sheet());
    ASSERT_NO_FATAL_FAILURE(simplify<Surface_mesh_epick>(reference, run));
    Outcome got = outcome_of(mesh);
    const Outcome expected = outcome_of(reference);
    EXPECT_TRUE(got.valid);
    EXPECT_LE(got.faces, kTarget);
    EXPECT_GE(got.faces + 1, kTarget);
    // For docs/compatibility.md (scripts/compatibility_table.py reads them).
    RecordProperty("faces", std::to_string(got.faces));
    RecordProperty("mean_error_vs_surface_mesh",
                   std::to_string(got.mean_error / expected.mean_error));
    EXPECT_NEAR(got.mean_error, expected.mean_error, 0.05 * expected.mean_error);
    if (outcome) *outcome = std::move(got);
  }
};

using Types =
    testing::Types<Surface_mesh_epick, Surface_mesh_cartesian, Polyhedron, Polyhedron_with_ids
#ifdef CGAL_POLICIES_WITH_OPENMESH
                   ,
                   Open_mesh, Open_mesh_double
#endif
                   >;

class Type_names {
 public:
  template <class Type>
  static std::string GetName(int) {
    if (std::is_same_v<Type, Surface_mesh_epick>) return "Surface_mesh_Epick";
    if (std::is_same_v<Type, Surface_mesh_cartesian>) return "Surface_mesh_Simple_cartesian";
    if (std::is_same_v<Type, Polyhedron>) return "Polyhedron_3";
    if (std::is_same_v<Type, Polyhedron_with_ids>) return "Polyhedron_3_with_ids";
#ifdef CGAL_POLICIES_WITH_OPENMESH
    if (std::is_same_v<Type, Open_mesh_double>) return "OpenMesh_TriMesh_double";
#endif
    return "OpenMesh_TriMesh";
  }
};
TYPED_TEST_SUITE(MeshTypes, Types, Type_names);

TYPED_TEST(MeshTypes, ClassicQuadricPolicies) {
  this->expect_as_on_surface_mesh(Pass_run::classic);
}

TYPED_TEST(MeshTypes, BoundedNormalAngleFilter) {
  this->expect_as_on_surface_mesh(Pass_run::classic_with_normal_filter);
}

TYPED_TEST(MeshTypes, CurvatureWeightedQuadricPolicies) {
  this->expect_as_on_surface_mesh(Pass_run::curvature);
}

TYPED_TEST(MeshTypes, FeatureFusionPolicies) { this->expect_as_on_surface_mesh(Pass_run::fusion); }

TYPED_TEST(MeshTypes, HausdorffBoundedPolicies) {
  Outcome got;
  this->expect_as_on_surface_mesh(Pass_run::hausdorff, &got);
  // And within its bound, 2% of the diagonal, both ways, by the evaluator.
  const test_meshes::Mesh input = mesh_of<test_meshes::Mesh>(wavy_sheet());
  EXPECT_LE(apps::measure_mesh_error(input, got.output, 5000).hausdorff,
            0.02 * test_meshes::bbox_diagonal(input));
}

TYPED_TEST(MeshTypes, FastThresholdSimplifier) { this->expect_as_on_surface_mesh(Pass_run::fast); }

TYPED_TEST(MeshTypes, FlatLindstromTurkSimplifier) {
  this->expect_as_on_surface_mesh(Pass_run::flat_lindstrom_turk);
}

TYPED_TEST(MeshTypes, TwoSidedFitter) {
  this->expect_as_on_surface_mesh(Pass_run::classic_then_fit);
}

TYPED_TEST(MeshTypes, LaplacianSmoother) {
  this->expect_as_on_surface_mesh(Pass_run::classic_then_smoothing);
}

// The stop predicate counts faces exactly on every type, though it counts them only now and
// then: a run stops at the first collapse that reaches the target, whatever the target.
TYPED_TEST(MeshTypes, FaceCountStopPredicateStopsAtTheTarget) {
  using Mesh = typename TypeParam::Mesh;
  for (const std::size_t target :
       {kFaces - 1, kFaces - 100, kFaces / 2 + 1, kFaces / 2, std::size_t(3)}) {
    Mesh mesh = mesh_of<Mesh>(wavy_sheet());
    const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh, target);
    const SMS::Edge_length_cost<Mesh> cost;
    const SMS::Midpoint_placement<Mesh> placement;
    SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(cost).get_placement(placement));
    const std::size_t faces = reference_copy(mesh).number_of_faces();
    EXPECT_LE(faces, target);
    EXPECT_GE(faces + 2, target);  // a collapse removes two faces at most
    EXPECT_EQ(stop.reason(), cgal_policies::Stop_reason::target_reached);
  }
}

TYPED_TEST(MeshTypes, BorderPairContraction) {
  // The sheet cut in two along x = 0.5, the right half with copies of the cut's points a hair
  // above: the contraction stitches them back into the sheet.
  Soup soup = wavy_sheet();
  std::map<std::size_t, std::size_t> copy_of;
  for (std::size_t k = 0; k < soup.points.size(); ++k)
    if (std::abs(soup.points[k].x() - 0.5) < 1e-12) {
      const std::size_t copy = soup.points.size() + copy_of.size();
      copy_of.emplace(k, copy);
    }
  for (const auto& [k, copy] : copy_of)
    soup.points.push_back(soup.points[k] + Epick::Vector_3(0, 0, 1e-7));
  for (auto& triangle : soup.triangles) {
    double x = 0;
    for (const std::size_t k : triangle) x += soup.points[k].x() / 3;
    if (x > 0.5)
      for (std::size_t& k : triangle)
        if (copy_of.count(k)) k = copy_of[k];
  }
  ASSERT_EQ(copy_of.size(), std::size_t(kSide + 1));
  using Mesh = typename TypeParam::Mesh;
  Mesh mesh = mesh_of<Mesh>(soup);
  const cgal_policies::Border_pair_contraction_report report =
      cgal_policies::Border_pair_contraction(1e-5)(mesh);
  EXPECT_EQ(report.merged_pairs, std::size_t(kSide + 1));
  EXPECT_EQ(report.stitched_edges, std::size_t(kSide));
  const test_meshes::Mesh stitched = reference_copy(mesh);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(stitched.number_of_faces(), kFaces);
  EXPECT_EQ(test_meshes::border_edge_count(stitched), std::size_t(4 * kSide));
}

TYPED_TEST(MeshTypes, SmallComponentsGoWhole) {
  Soup soup = wavy_sheet();
  const std::size_t first = soup.points.size();
  soup.points.insert(soup.points.end(), {{2, 0, 0}, {3, 0, 0}, {2, 1, 0}, {3, 1, 0}});
  soup.triangles.push_back({first, first + 1, first + 2});
  soup.triangles.push_back({first + 2, first + 1, first + 3});
  using Mesh = typename TypeParam::Mesh;
  Mesh mesh = mesh_of<Mesh>(soup);
  const cgal_policies::Dropped_components dropped =
      cgal_policies::drop_components_smaller_than(mesh, 10);
  EXPECT_EQ(dropped.components, 1u);
  EXPECT_EQ(dropped.faces, 2u);
  EXPECT_EQ(reference_copy(mesh).number_of_faces(), kFaces);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
}

// The pipeline is a Surface_mesh's, over any kernel; another type is refused at compile time
// (the static_assert of cgal_policies::simplify), which no test can run.
template <class Type>
class SurfaceMeshTypes : public MeshTypes<Type> {};
using Surface_mesh_types = testing::Types<Surface_mesh_epick, Surface_mesh_cartesian>;
TYPED_TEST_SUITE(SurfaceMeshTypes, Surface_mesh_types, Type_names);

TYPED_TEST(SurfaceMeshTypes, SimplificationPipeline) {
  using Mesh = typename TypeParam::Mesh;
  Mesh mesh = mesh_of<Mesh>(wavy_sheet());
  cgal_policies::Simplification_options options;
  options.target = cgal_policies::Face_target::faces(kTarget);
  options.fit_options.rounds = 2;
  options.fit_options.min_input_samples = 2000;
  const cgal_policies::Simplification_report report = cgal_policies::simplify(mesh, options);
  test_meshes::Mesh reference = mesh_of<test_meshes::Mesh>(wavy_sheet());
  cgal_policies::simplify(reference, options);
  EXPECT_EQ(report.output_faces, reference.number_of_faces());
  const Outcome got = outcome_of(mesh), expected = outcome_of(reference);
  EXPECT_TRUE(got.valid);
  EXPECT_LE(got.faces, kTarget);
  EXPECT_NEAR(got.mean_error, expected.mean_error, 0.05 * expected.mean_error);
  this->RecordProperty("faces", std::to_string(got.faces));
  this->RecordProperty("mean_error_vs_surface_mesh",
                       std::to_string(got.mean_error / expected.mean_error));
}

}  // namespace
