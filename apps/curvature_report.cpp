// curvature_report INPUT A B: where two simplifications of INPUT put their faces
// (docs/curvature.md: "measure where the faces go, curved vs flat"). Prints one JSON object.
//
// - The curved quarter: INPUT's faces ranked by the approximate curvature of Zhang et al. (eq.
//   9-10; a face takes the mean K of its corners, lower is more curved), most curved first, until
//   they cover a quarter of INPUT's area.
// - curved_face_share: the share of a simplification's faces whose centroid lies nearest to the
//   curved quarter. Faces spread evenly over the area would give 0.25; keeping curved detail means
//   more.
// - mean_normal_angle_deg: at points sampled on INPUT (fixed seed), the mean angle between INPUT's
//   face normal and the normal of the nearest face of the simplification; also over the samples of
//   the curved quarter and of the rest.
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/Json_object.h"
#include "cli/app_main.h"
#include "cli/tuned_allocator.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cgal_policies/internal/approximate_curvature.h>
#include <cgal_policies/internal/mesh_geometry.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <numeric>
#include <vector>

namespace apps {
namespace {

constexpr std::size_t kDefaultSamples = 100000;
constexpr double kCurvedShare = 0.25;  // of the input's area

const char* const kUsage = "usage: curvature_report INPUT A B [--samples N] [--asset-root DIR]";

// True for the faces of `input` in its most curved quarter by area.
std::vector<bool> curved_quarter(Mesh& input) {
  auto normals = input
                     .add_property_map<Mesh::Vertex_index, cgal_policies::internal::Stored_normal>(
                         "v:report_normal")
                     .first;
  auto curvatures = input.add_property_map<Mesh::Vertex_index, double>("v:report_k").first;
  cgal_policies::internal::compute_approximate_curvatures(input, input.points(), normals,
                                                          curvatures);
  std::vector<double> face_k(input.number_of_faces()), area(input.number_of_faces());
  for (auto f : faces(input)) {
    double k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, input), input)) k += curvatures[v];
    face_k[f] = k / 3;
    area[f] = 0.5 * cgal_policies::internal::face_area_normal(f, input, input.points()).norm();
  }
  std::vector<std::size_t> order(face_k.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return face_k[a] < face_k[b]; });
  const double quota = kCurvedShare * std::accumulate(area.begin(), area.end(), 0.0);
  std::vector<bool> curved(face_k.size(), false);
  double covered = 0;
  for (std::size_t i = 0; i < order.size() && covered < quota; ++i) {
    curved[order[i]] = true;
    covered += area[order[i]];
  }
  input.remove_property_map(normals);
  input.remove_property_map(curvatures);
  return curved;
}

Eigen::Vector3d unit_normal(Mesh::Face_index f, const Mesh& mesh) {
  return cgal_policies::internal::unit_or_zero(
      cgal_policies::internal::face_area_normal(f, mesh, mesh.points()));
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
}

void report_simplification(const std::string& prefix, const Mesh& input,
                           const Face_tree& input_tree, const std::vector<bool>& curved,
                           const std::vector<Point>& samples, const Mesh& simplified,
                           Json_object& json) {
  std::size_t curved_faces = 0;
  for (auto f : faces(simplified)) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (auto v : CGAL::vertices_around_face(halfedge(f, simplified), simplified))
      centroid += cgal_policies::internal::to_eigen(simplified.point(v)) / 3;
    const auto nearest =
        input_tree.closest_point_and_primitive(cgal_policies::internal::to_point<Point>(centroid));
    curved_faces += curved[nearest.second];
  }

  Face_tree tree(faces(simplified).first, faces(simplified).second, simplified);
  tree.accelerate_distance_queries();
  double sum[2] = {0, 0};  // flat, curved
  std::size_t count[2] = {0, 0};
  for (const Point& p : samples) {
    const Mesh::Face_index from = input_tree.closest_point_and_primitive(p).second;
    const Mesh::Face_index to = tree.closest_point_and_primitive(p).second;
    const int k = curved[from] ? 1 : 0;
    sum[k] += angle_deg(unit_normal(from, input), unit_normal(to, simplified));
    ++count[k];
  }
  auto mean = [](double s, std::size_t n) { return n ? s / double(n) : 0.0; };
  json.add(prefix + "faces", simplified.number_of_faces());
  json.add(prefix + "curved_face_share", mean(double(curved_faces), simplified.number_of_faces()));
  json.add(prefix + "mean_normal_angle_deg", mean(sum[0] + sum[1], count[0] + count[1]));
  json.add(prefix + "mean_normal_angle_curved_deg", mean(sum[1], count[1]));
  json.add(prefix + "mean_normal_angle_flat_deg", mean(sum[0], count[0]));
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    std::cout << kUsage
              << "\nWhere two simplifications A and B of INPUT put their faces: the share of their "
                 "faces\nin INPUT's most curved quarter (by area, by approximate curvature), and "
                 "the mean angle\nbetween INPUT's normals and theirs at N points sampled on INPUT "
                 "(default "
              << kDefaultSamples << "). Prints JSON.\n";
    return exit_success;
  }
  const double samples = cli.take_number("samples").value_or(double(kDefaultSamples));
  const std::string asset_root = take_asset_root(cli);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 3 || !(samples >= 1)) throw App_error(exit_usage, kUsage);

  const Read_options reading{Corner_attribute_reading::drop, 1, asset_root};
  Mesh input = read_triangle_mesh(args[0], reading);
  const std::vector<bool> curved = curved_quarter(input);
  Face_tree input_tree(faces(input).first, faces(input).second, input);
  input_tree.accelerate_distance_queries();
  const std::vector<Point> points = sample_faces(input, std::size_t(samples));

  Json_object json;
  json.add("input", args[0]);
  json.add("input_faces", input.number_of_faces());
  json.add("samples", points.size());
  json.add("a", args[1]);
  json.add("b", args[2]);
  report_simplification("a_", input, input_tree, curved, points,
                        read_triangle_mesh(args[1], reading), json);
  report_simplification("b_", input, input_tree, curved, points,
                        read_triangle_mesh(args[2], reading), json);
  std::cout << json.str() << '\n';
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("curvature_report", [&] { return apps::run(argc, argv); });
}
