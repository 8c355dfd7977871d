// Corner attributes (cgal_policies/Corner_attributes.h) carried through the collapses of every
// policy (Corner_attribute_carrier.h, Attribute_carrying_visitor.h, the seam rules of
// Seam_keeping_placement.h and Seam_keeping_filter.h), on tiny meshes with exact expectations and
// on spot, and the carrier's refusal to run without its visitor.
#include "pipeline_runs.h"
#include "test_meshes.h"

#include "evaluation/attribute_error.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cgal_policies/Attribute_carrying_visitor.h>
#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Face_count_stop_predicate.h>
#include <cgal_policies/Seam_keeping_filter.h>
#include <cgal_policies/Seam_keeping_placement.h>
#include <cgal_policies/internal/resolve_free_uvs.h>

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace test_meshes;
using pipeline_runs::mean_error;
using pipeline_runs::simplify;

// (cgal_policies/Corner_attribute_carrier.h).
using Attributes = cgal_policies::Corner_attributes<Point>;

const std::vector<std::string> kCarryingPolicies = {"gh",        "gh-prob",   "lt",   "classic",
                                                    "curvature", "fusion",    "fast", "flat-lt",
                                                    "hausdorff", "attributes"};

TEST(CarriedAttributes, ALinearFieldOnAFlatMeshIsReproducedExactly) {
  const auto field = [](Mesh::Face_index, const Point& p) {
    return std::array<double, 2>{0.3 * p.x() + 0.1 * p.y(), -0.2 * p.x() + 0.5 * p.y() + 0.25};
  };
  // Within [0, 1] on the grid, so that no solved colour is clamped.
  const auto color_field = [](Mesh::Face_index, const Point& p) {
    return std::array<double, 4>{0.05 * p.x() + 0.02 * p.y(), 0.9 - 0.04 * p.y(), 0.5, 1};
  };
  // The second set (a lightmap's): carried as the first is, though no quadric weighs it.
  const auto second_field = [](Mesh::Face_index, const Point& p) {
    return std::array<double, 2>{0.5 - 0.04 * p.y(), 0.07 * p.x() + 0.125};
  };
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = flat_grid(10);
    paint_corners(mesh, field, true);
    paint_colors(mesh, color_field);
    paint_second_uvs(mesh, second_field);
    const cgal_policies::Simplification_report outcome = simplify(mesh, policy, 20);
    EXPECT_TRUE(outcome.attributes_carried) << policy;
    EXPECT_LT(mesh.number_of_faces(), 200u) << policy;
    const Attributes attributes(mesh);
    ASSERT_TRUE(attributes.uvs && attributes.normals && attributes.colors && attributes.second_uvs)
        << policy;
    for (auto h : halfedges(mesh)) {
      if (mesh.is_border(h)) continue;
      const auto expected = field(face(h, mesh), mesh.point(target(h, mesh)));
      EXPECT_NEAR((*attributes.uvs)[h][0], expected[0], 1e-12) << policy;
      EXPECT_NEAR((*attributes.uvs)[h][1], expected[1], 1e-12) << policy;
      const auto expected_color = color_field(face(h, mesh), mesh.point(target(h, mesh)));
      for (int d = 0; d < 4; ++d)
        EXPECT_NEAR((*attributes.colors)[h][d], expected_color[d], 1e-12) << policy;
      EXPECT_EQ((*attributes.normals)[h], Kernel::Vector_3(0, 0, 1)) << policy;
      const auto expected_second = second_field(face(h, mesh), mesh.point(target(h, mesh)));
      EXPECT_NEAR((*attributes.second_uvs)[h][0], expected_second[0], 1e-12) << policy;
      EXPECT_NEAR((*attributes.second_uvs)[h][1], expected_second[1], 1e-12) << policy;
    }
    for (auto f : faces(mesh)) EXPECT_GT(uv_area(mesh, f), 0) << policy;
  }
}

// A seam of the second set alone, where the first set and the normals agree: the corners of
// x = 5 disagree only in their second coordinates, which jump by 1 across it. Every policy keeps
// the seam, so that each face's corners still read the field of their side, exactly.
TEST(CarriedAttributes, ASeamOfTheSecondUvSetAloneIsKept) {
  const auto side = [](const Mesh& mesh, Mesh::Face_index f) {
    double x = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) x += mesh.point(v).x();
    return x < 15 ? 0.0 : 1.0;  // the centroid's x, times 3, against the seam's
  };
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = textured_grid(10, true);
    paint_second_uvs(mesh, [&](Mesh::Face_index f, const Point& p) {
      return std::array<double, 2>{p.x() / 10 + side(mesh, f), p.y() / 10};
    });
    const cgal_policies::Corner_attribute_carrier<Point> before(mesh);
    for (auto v : vertices(mesh))
      EXPECT_EQ(before.seam_edges_at(v) > 0, mesh.point(v).x() == 5 || mesh.is_border(v)) << policy;
    simplify(mesh, policy, 20);
    const Attributes attributes(mesh);
    ASSERT_TRUE(attributes.second_uvs) << policy;
    for (auto h : halfedges(mesh)) {
      if (mesh.is_border(h)) continue;
      const Point& p = mesh.point(target(h, mesh));
      const double shift = side(mesh, face(h, mesh));
      EXPECT_NEAR((*attributes.second_uvs)[h][0], p.x() / 10 + shift, 1e-12) << policy;
      EXPECT_NEAR((*attributes.second_uvs)[h][1], p.y() / 10, 1e-12) << policy;
    }
  }
}

// Blending influences: each joint weighs the barycentric sum of its weights at the corners, the
// four heaviest are kept (ties: the lower joints) and renormalised; a corner without influences
// makes the blend none. Unused slots are joint 0 with weight 0.
TEST(SkinInfluences, BlendingKeepsTheFourHeaviestJointsRenormalised) {
  using Skin = Attributes::Skin_influences;
  const Skin a{{0, 1, 0, 0}, {0.75, 0.25, 0, 0}}, b{{1, 0, 0, 0}, {1, 0, 0, 0}};
  const Skin half = Attributes::blend_skins({a, b, b}, {0.5, 0.5, 0});
  EXPECT_EQ(half.joints, (std::array<std::uint16_t, 4>{1, 0, 0, 0}));
  EXPECT_EQ(half.weights, (std::array<double, 4>{0.625, 0.375, 0, 0}));
  // Six joints of equal weight: the four lowest are kept, a quarter each.
  const Skin c{{5, 1, 0, 0}, {0.5, 0.5, 0, 0}}, d{{4, 2, 0, 0}, {0.5, 0.5, 0, 0}},
      e{{3, 0, 0, 0}, {0.5, 0.5, 0, 0}};
  const Skin ties = Attributes::blend_skins({c, d, e}, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  EXPECT_EQ(ties.joints, (std::array<std::uint16_t, 4>{0, 1, 2, 3}));
  for (double w : ties.weights) EXPECT_DOUBLE_EQ(w, 0.25);
  // Five joints: the lightest is dropped and the others renormalised.
  const Skin f{{0, 1, 2, 3}, {0.4, 0.3, 0.2, 0.1}}, g{{4, 0, 0, 0}, {1, 0, 0, 0}};
  const Skin five = Attributes::blend_skins({f, g, g}, {0.5, 0.25, 0.25});
  EXPECT_EQ(five.joints, (std::array<std::uint16_t, 4>{4, 0, 1, 2}));
  const std::array<double, 4> renormalised = {0.5 / 0.95, 0.2 / 0.95, 0.15 / 0.95, 0.1 / 0.95};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(five.weights[i], renormalised[i]);
  const Skin none = Attributes::no_values().skin;
  EXPECT_TRUE(std::isnan(Attributes::blend_skins({a, b, none}, {0.5, 0.5, 0}).weights[0]));
  // Equal influences are equal values; different ones make a seam as other values do.
  Attributes::Values x = Attributes::no_values(), y = x;
  x.skin = y.skin = half;
  EXPECT_TRUE(Attributes::same_values(x, y));
  y.skin = a;
  EXPECT_FALSE(Attributes::same_values(x, y));
}

// The weight of `joint` in `skin`: 0 when it has none.
double weight_of(const Attributes::Skin_influences& skin, std::uint16_t joint) {
  double weight = 0;
  for (int i = 0; i < 4; ++i)
    if (skin.joints[i] == joint) weight += skin.weights[i];
  return weight;
}

// Skin weights of three joints, 2, 3 and 7, that are linear in the position, with texture
// coordinates and normals: every policy keeps them linear (no quadric weighs them: they are
// interpolated), each corner's weights summing to 1 over those joints alone, unused slots joint 0
// with weight 0.
TEST(CarriedAttributes, LinearSkinWeightsAreReproducedAndStayNormalised) {
  const auto weights = [](const Point& p) {
    return std::array<double, 3>{0.4 - 0.02 * p.y(), 0.6 - 0.05 * p.x(),
                                 0.05 * p.x() + 0.02 * p.y()};
  };
  const std::array<std::uint16_t, 3> joints = {2, 3, 7};
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = textured_grid(10, true);
    paint_skins(mesh, [&](Mesh::Face_index, const Point& p) {
      const std::array<double, 3> w = weights(p);
      return Attributes::normalized_skin({{joints[0], w[0]}, {joints[1], w[1]}, {joints[2], w[2]}});
    });
    const cgal_policies::Simplification_report outcome = simplify(mesh, policy, 20);
    EXPECT_TRUE(outcome.attributes_carried) << policy;
    EXPECT_LT(mesh.number_of_faces(), 200u) << policy;
    const Attributes attributes(mesh);
    ASSERT_TRUE(attributes.skins) << policy;
    for (auto h : halfedges(mesh)) {
      if (mesh.is_border(h)) continue;
      const Attributes::Skin_influences& skin = (*attributes.skins)[h];
      double sum = 0;
      for (int i = 0; i < 4; ++i) {
        sum += skin.weights[i];
        if (skin.weights[i] > 0)
          EXPECT_TRUE(std::count(joints.begin(), joints.end(), skin.joints[i])) << policy;
        else
          EXPECT_EQ(skin.joints[i], 0) << policy;
      }
      EXPECT_NEAR(sum, 1, 1e-12) << policy;
      const std::array<double, 3> expected = weights(mesh.point(target(h, mesh)));
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(weight_of(skin, joints[std::size_t(k)]), expected[std::size_t(k)], 1e-12)
            << policy;
    }
  }
}

// Influences that jump across x = 5 (joint 0 alone on the left, joint 1 alone on the right) where
// every other value agrees: a seam of the skin alone, which every policy keeps, each face's corners
// the influences of their side.
TEST(CarriedAttributes, ASeamOfTheSkinAloneIsKept) {
  const auto side = [](const Mesh& mesh, Mesh::Face_index f) {
    double x = 0;
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) x += mesh.point(v).x();
    return x < 15 ? 0 : 1;  // the centroid's x, times 3, against the seam's
  };
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = textured_grid(10, true);
    paint_skins(mesh, [&](Mesh::Face_index f, const Point&) {
      return Attributes::Skin_influences{{std::uint16_t(side(mesh, f)), 0, 0, 0}, {1, 0, 0, 0}};
    });
    const cgal_policies::Corner_attribute_carrier<Point> before(mesh);
    for (auto v : vertices(mesh))
      EXPECT_EQ(before.seam_edges_at(v) > 0, mesh.point(v).x() == 5 || mesh.is_border(v)) << policy;
    simplify(mesh, policy, 20);
    const Attributes attributes(mesh);
    ASSERT_TRUE(attributes.skins) << policy;
    for (auto h : halfedges(mesh)) {
      if (mesh.is_border(h)) continue;
      const Attributes::Skin_influences& skin = (*attributes.skins)[h];
      EXPECT_EQ(skin.joints[0], side(mesh, face(h, mesh))) << policy;
      EXPECT_EQ(skin.weights, (std::array<double, 4>{1, 0, 0, 0})) << policy;
    }
  }
}

// CGAL collapses every edge of zero length first, with no placement, filter or OnCollapsing; such a
// collapse moves no point, and every face around it keeps the values it had at each vertex
// (Corner_attribute_carrier::started). The textured plane's vertex (1, 1) is moved onto (2, 1), its
// coordinates painted where it was.
TEST(CarriedAttributes, AZeroLengthEdgeCollapsesWithEveryFaceKeepingItsValues) {
  for (const std::string& policy : kCarryingPolicies) {
    // Not CGAL's loop: the flat-array engines take an edge of zero length as any other.
    if (policy == "fast" || policy == "flat-lt") continue;
    Mesh mesh = textured_plane(false);
    mesh.point(Mesh::Vertex_index(6)) = Point(2, 1, 0);
    const auto corner_uvs = [&](Mesh::Face_index f) {
      const Attributes attributes(mesh);  // fast's maps are new ones
      std::multiset<std::array<double, 2>> uvs;
      for (auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        uvs.insert((*attributes.uvs)[h]);
      return uvs;
    };
    // By their values, not their indices: fast rebuilds the mesh.
    std::multiset<std::multiset<std::array<double, 2>>> before;
    for (auto f : faces(mesh)) before.insert(corner_uvs(f));
    const cgal_policies::Simplification_report outcome = simplify(mesh, policy, 30);
    EXPECT_TRUE(outcome.attributes_carried) << policy;
    EXPECT_EQ(mesh.number_of_faces(), 30u) << policy;  // the two faces of the edge
    for (auto f : faces(mesh)) {
      const auto found = before.find(corner_uvs(f));
      ASSERT_NE(found, before.end()) << policy;
      before.erase(found);
    }
  }
}

TEST(CarriedAttributes, ATexturedPlaneToTwoTrianglesKeepsItsCornerUvsExactly) {
  const auto field = [](Mesh::Face_index, const Point& p) {
    return std::array<double, 2>{p.x() / 8, p.y() / 8};
  };
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = flat_grid(8);
    paint_corners(mesh, field, false);
    simplify(mesh, policy, 2);
    ASSERT_EQ(mesh.number_of_faces(), 2u) << policy;
    const Attributes attributes(mesh);
    for (auto h : halfedges(mesh)) {
      if (mesh.is_border(h)) continue;
      const Point& p = mesh.point(target(h, mesh));
      EXPECT_TRUE((p.x() == 0 || p.x() == 8) && (p.y() == 0 || p.y() == 8)) << policy << ": " << p;
      EXPECT_EQ((*attributes.uvs)[h], field(face(h, mesh), p)) << policy;
    }
  }
}

// The cube of test_meshes::six_sided_cube(): every cube edge is a seam and every cube corner a
// seam corner.
TEST(CarriedAttributes, ACubeWithSixChartsKeepsEveryChartWhole) {
  const Mesh cube = six_sided_cube();
  ASSERT_EQ(cube.number_of_faces(), 192u);
  ASSERT_TRUE(CGAL::is_closed(cube));
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = cube;
    paint_corners(
        mesh, [&](Mesh::Face_index f, const Point& p) { return cube_chart(cube_side(mesh, f), p); },
        false);
    simplify(mesh, policy, 12);
    EXPECT_EQ(mesh.number_of_faces(), 12u) << policy;
    EXPECT_TRUE(CGAL::is_closed(mesh)) << policy;
    const Attributes attributes(mesh);
    for (auto f : faces(mesh)) {
      const int k = cube_side(mesh, f);
      EXPECT_GT(uv_area(mesh, f), 0) << policy;
      for (auto h : halfedges_around_face(halfedge(f, mesh), mesh))
        EXPECT_EQ((*attributes.uvs)[h], cube_chart(k, mesh.point(target(h, mesh)))) << policy;
    }
  }
}

// The fitting pass on a textured mesh (docs/fitting.md): the seam vertices stay, no edge flips,
// and each moved vertex takes the values where it went, so no texture triangle turns over and the
// texture error stays near the simplification's while the geometric error drops.
TEST(CarriedAttributes, FittingSpotKeepsItsSeamsAndItsTexture) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Mesh input = apps::read_triangle_mesh(data_file("spot.obj"), nullptr,
                                              apps::Corner_attribute_reading::keep);
  // lt alone, then lt and the fitting pass.
  const std::size_t target = input.number_of_faces() / 10;
  Mesh simplified = input;
  simplify(simplified, "lt", target);
  Mesh mesh = input;
  cgal_policies::Simplification_options options = pipeline_runs::policy_alone("lt", target);
  options.fit = true;
  const cgal_policies::Simplification_report fit = apps::Pipeline(options).run(mesh);
  EXPECT_GT(fit.fit.moves, 0u);
  EXPECT_EQ(fit.fit.flips, 0u);
  Mesh seams_of = simplified;
  const cgal_policies::Corner_attribute_carrier<Point> seams(seams_of);
  const Attributes before(simplified), after(mesh);
  ASSERT_TRUE(after.uvs);
  std::size_t moved = 0;
  for (const auto v : vertices(mesh)) {
    if (seams.seam_edges_at(v) > 0) {
      EXPECT_EQ(mesh.point(v), simplified.point(v)) << "seam vertex " << v << " moved";
    }
    moved += mesh.point(v) != simplified.point(v);
  }
  EXPECT_GT(moved, 0u);
  for (const auto f : faces(mesh)) {
    const double was = before.face_uv_area(simplified, f), now = after.face_uv_area(mesh, f);
    EXPECT_TRUE(was == 0 || was * now > 0) << "face " << f << " turned over in the texture";
  }
  const auto uv_error = [&](const Mesh& m) {
    return *apps::measure_attribute_error(input, m, 50000).uv_mean_rel;
  };
  EXPECT_LT(uv_error(mesh), 1.1 * uv_error(simplified));
  EXPECT_LT(mean_error(input, mesh), mean_error(input, simplified));
}

// The fitting pass's last step (internal/resolve_free_uvs.h): texture coordinates that drifted off
// the input's field at the vertices on no seam are solved back onto it, but for the hold to the
// drifted values (1e-6 of a vertex's weight); the border's stay.
TEST(CarriedAttributes, SolvingTheFreeTextureCoordinatesAgainRestoresTheInputsField) {
  const auto field = [](Mesh::Face_index, const Point& p) {
    return std::array<double, 2>{0.3 * p.x() + 0.1 * p.y(), -0.2 * p.x() + 0.5 * p.y() + 0.25};
  };
  Mesh input = flat_grid(10);
  paint_corners(input, field, true);
  Mesh mesh = input;
  const cgal_policies::Corner_attribute_carrier<Point> seams(mesh);
  const Attributes attributes(mesh);
  std::size_t drifted = 0;
  for (const auto v : vertices(mesh)) {
    if (seams.seam_edges_at(v) > 0) continue;
    for (const auto h : halfedges_around_target(v, mesh)) {
      (*attributes.uvs)[h][0] += 0.004 * double(std::size_t(v) % 3);
      (*attributes.uvs)[h][1] -= 0.003;
    }
    ++drifted;
  }
  ASSERT_GT(drifted, 0u);
  cgal_policies::internal::resolve_free_uvs(
      mesh, input, [&](Mesh::Vertex_index v) { return seams.seam_edges_at(v) == 0; });
  for (const auto h : halfedges(mesh)) {
    if (mesh.is_border(h)) continue;
    const auto expected = field(face(h, mesh), mesh.point(target(h, mesh)));
    EXPECT_NEAR((*attributes.uvs)[h][0], expected[0], 1e-7);
    EXPECT_NEAR((*attributes.uvs)[h][1], expected[1], 1e-7);
  }
}

TEST(CarriedAttributes, SpotKeepsItsSeamCornersAndTurnsNoTextureTriangleOver) {
  SKIP_IF_REAL_MESHES_ARE_OFF();
  const Mesh input = apps::read_triangle_mesh(data_file("spot.obj"), nullptr,
                                              apps::Corner_attribute_reading::keep);
  const Attributes input_attributes(input);
  ASSERT_TRUE(input_attributes.uvs);
  Mesh seams_of = input;
  const cgal_policies::Corner_attribute_carrier<Point> seams(seams_of);
  std::vector<Point> seam_corners;
  for (auto v : vertices(input)) {
    const std::size_t count = seams.seam_edges_at(v);
    if (count != 0 && count != 2) seam_corners.push_back(input.point(v));
  }
  ASSERT_FALSE(seam_corners.empty());
  const auto not_positive = [](const Mesh& mesh) {
    std::size_t count = 0;
    for (auto f : faces(mesh)) count += uv_area(mesh, f) > 0 ? 0 : 1;
    return count;
  };
  for (const std::string& policy : kCarryingPolicies) {
    Mesh mesh = input;
    const std::size_t target = input.number_of_faces() / 10;
    cgal_policies::Simplification_options options = pipeline_runs::policy_alone(policy, target);
    // hausdorff's default bound, with the seams held, stops it short of this target
    // (docs/attributes.md).
    options.hausdorff.beta = 0.01;
    apps::Pipeline(options).run(mesh);
    EXPECT_LE(mesh.number_of_faces(), target) << policy;
    std::set<std::array<double, 3>> kept;
    for (auto v : vertices(mesh))
      kept.insert({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    for (const Point& p : seam_corners)
      EXPECT_TRUE(kept.count({p.x(), p.y(), p.z()})) << policy << ": seam corner " << p << " gone";
    // Each surviving face keeps its orientation in the texture, and none becomes flat there.
    EXPECT_LE(not_positive(mesh), not_positive(input)) << policy;
  }
}

namespace SMS = CGAL::Surface_mesh_simplification;
using Carrier = cgal_policies::Corner_attribute_carrier<Point>;

// The seam rules of a textured plane collapsed by CGAL's Lindstrom-Turk policy, with or without the
// visitor that feeds the carrier.
void collapse_textured_plane(Mesh& mesh, bool with_visitor) {
  Carrier carrier(mesh);
  using Placement =
      cgal_policies::Seam_keeping_placement<Point, SMS::LindstromTurk_placement<Mesh>>;
  using Filter = cgal_policies::Seam_keeping_filter<Point, SMS::internal::Dummy_filter>;
  const auto parameters = CGAL::parameters::get_cost(SMS::LindstromTurk_cost<Mesh>())
                              .get_placement(Placement({}, &carrier))
                              .filter(Filter({}, &carrier));
  const cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh, 8);
  if (with_visitor)
    SMS::edge_collapse(
        mesh, stop, parameters.visitor(cgal_policies::Attribute_carrying_visitor<Point>(&carrier)));
  else
    SMS::edge_collapse(mesh, stop, parameters);
}

TEST(AttributeCarryingVisitor, ACarrierWithoutItsVisitorRefusesToRun) {
  Mesh mesh = textured_plane(false);
  EXPECT_THROW(collapse_textured_plane(mesh, false), std::logic_error);
}

// With the visitor, the plane's linear texture field follows every collapse exactly.
TEST(AttributeCarryingVisitor, WithItsVisitorTheValuesFollowTheCollapses) {
  Mesh mesh = textured_plane(false);
  collapse_textured_plane(mesh, true);
  mesh.collect_garbage();
  EXPECT_EQ(mesh.number_of_faces(), 8u);
  const Attributes attributes(mesh);
  for (auto h : halfedges(mesh)) {
    if (mesh.is_border(h)) continue;
    const Point& p = mesh.point(target(h, mesh));
    EXPECT_NEAR((*attributes.uvs)[h][0], p.x() / 4, 1e-12);
    EXPECT_NEAR((*attributes.uvs)[h][1], p.y() / 4, 1e-12);
  }
}

}  // namespace
