// mesh_error A B: Metro-style two-sided distances between two meshes (docs/evaluation.md), A being
// the reference, the validity figures of B and, with --attributes, the error of B's texture
// coordinates, normals and colours.
#include "cli/App_error.h"
#include "cli/Command_line.h"
#include "cli/Json_object.h"
#include "cli/app_main.h"
#include "cli/report_fields.h"
#include "cli/tuned_allocator.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace apps {
namespace {

void print_help() {
  std::cout << "usage: mesh_error A B [--samples N] [--attributes] [--asset-root DIR] [--json]\n"
               "Two-sided distances between the surfaces of A (the reference) and B: the\n"
               "Hausdorff distance, the mean distance in each direction and the RMS, absolute\n"
               "and relative to A's bounding-box diagonal; then the validity of B.\n\n"
               "  --samples N   random face samples per direction, fixed seed (default "
            << kDefaultErrorSamples
            << "); every vertex is sampled too\n"
               "  --attributes  also compare the corner attributes of B with A's (OBJ, PLY,\n"
               "                glTF): texture coordinates relative to A's texture extent,\n"
               "                normal angles, colour distances, seams and flipped texture\n"
               "                triangles;\n"
               "                each figure only when both files have what it compares\n"
               "                (docs/evaluation.md)\n"
               "  --asset-root DIR  let A and B name files anywhere in DIR, a folder\n"
               "                holding both; without it, each only in its own folder and below\n"
               "  --json        print one JSON object on stdout\n";
}

void print_attribute_error(const Attribute_error& e) {
  if (e.uv_mean_rel)
    std::printf("texture coordinates: mean %.5f%%, max %.5f%% of A's texture extent\n",
                100 * *e.uv_mean_rel, 100 * *e.uv_max_rel);
  else
    std::printf("texture coordinates: not in both meshes\n");
  if (e.flipped_uv_faces) std::printf("flipped texture triangles of B: %zu\n", *e.flipped_uv_faces);
  if (e.normal_angle_mean_deg)
    std::printf("normals: mean %.4f deg, max %.4f deg\n", *e.normal_angle_mean_deg,
                *e.normal_angle_max_deg);
  else
    std::printf("normals: not in both meshes\n");
  if (e.color_mean)
    std::printf("colours: mean %.5f, max %.5f (RGBA distance, channels from 0 to 1)\n",
                *e.color_mean, *e.color_max);
  else
    std::printf("colours: not in both meshes\n");
  if (e.seam_edges_a)
    std::printf("seam edges / connected seams: A %zu / %zu, B %zu / %zu\n", *e.seam_edges_a,
                *e.seam_loops_a, *e.seam_edges_b, *e.seam_loops_b);
}

int run(int argc, char** argv) {
  Command_line cli(argc, argv);
  if (cli.take_flag("help", "-h")) {
    print_help();
    return exit_success;
  }
  const double samples = cli.take_number("samples").value_or(double(kDefaultErrorSamples));
  const bool json = cli.take_flag("json");
  const bool attributes = cli.take_flag("attributes");
  const std::string asset_root = take_asset_root(cli);
  const std::vector<std::string> args = cli.positionals();
  if (args.size() != 2)
    throw App_error(
        exit_usage,
        "usage: mesh_error A B [--samples N] [--attributes] [--asset-root DIR] [--json]");
  if (!(samples >= 1 && samples == std::floor(samples)))
    throw App_error(exit_usage, "--samples must be a whole number of at least 1");

  const Corner_attribute_reading reading =
      attributes ? Corner_attribute_reading::keep : Corner_attribute_reading::drop;
  const Mesh a = read_triangle_mesh(args[0], {reading, 1, asset_root});
  const Mesh b = read_triangle_mesh(args[1], {reading, 1, asset_root});
  const Mesh_error error = measure_mesh_error(a, b, std::size_t(samples));
  const Mesh_validity validity = check_mesh_validity(b);
  const Attribute_error attribute_error =
      attributes ? measure_attribute_error(a, b, std::size_t(samples)) : Attribute_error();
  if (json) {
    Json_object report;
    add_fields(report, error);
    add_fields(report, validity);
    add_fields(report, attribute_error);
    std::cout << report.str() << '\n';
    return exit_success;
  }
  const double d = error.bbox_diagonal;
  std::printf("reference diagonal  %.6g (%zu face samples per direction)\n", d, error.samples);
  std::printf("%-20s %14s %12s\n", "", "absolute", "% diagonal");
  const std::pair<const char*, double> rows[] = {
      {"Hausdorff", error.hausdorff},       {"max A->B", error.hausdorff_a_to_b},
      {"max B->A", error.hausdorff_b_to_a}, {"mean A->B", error.mean_a_to_b},
      {"mean B->A", error.mean_b_to_a},     {"RMS", error.rms}};
  for (const auto& [name, value] : rows)
    std::printf("%-20s %14.6g %12.5f\n", name, value, 100 * value / d);
  std::printf(
      "B: %s, %s, %zu faces, %zu boundary edges, %zu non-manifold vertices, "
      "%zu degenerate faces, min angle %.2f deg\n",
      validity.valid ? "valid" : "INVALID", validity.closed ? "closed" : "open", validity.faces,
      validity.boundary_edges, validity.non_manifold_vertices, validity.degenerate_faces,
      validity.min_angle_deg);
  if (attributes) print_attribute_error(attribute_error);
  return exit_success;
}

}  // namespace
}  // namespace apps

int main(int argc, char** argv) {
  apps::restart_with_tuned_allocator(argv);
  return apps::guarded_main("mesh_error", [&] { return apps::run(argc, argv); });
}
