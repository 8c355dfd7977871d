// Fuzzes the library's pipeline as simplify runs it (apps/pipeline/Pipeline.h): every policy of the
// registry on small meshes built from the bytes (fuzz_soup.h, repaired by the reader's pipeline)
// with options drawn from the bytes, each within its documented range, and the passes around the
// run (small components, dropped pieces, smoothing, fitting). After each pass the mesh must be a
// valid triangle mesh with finite points, manifold when the input is; the run meets the face target
// or says why not; and when the run has a two-sided bound, the evaluator finds no sample farther
// than it. The mesh may carry texture coordinates and normals, cut into charts
// (so with seams); a run that carries them keeps them finite, keeps every seam corner where it
// was, and turns no texture triangle over.
#include "fuzz_checks.h"
#include "fuzz_soup.h"

#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"
#include "pipeline/Pipeline.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/internal/seam_collapse_rule.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace {

using fuzz::require;

// The settings come from this many bytes at the front (they need fewer; the last one chooses the
// corner attributes); the mesh from the rest.
constexpr int kSettingsBytes = 64;

using Attributes = cgal_policies::Corner_attributes<apps::Point>;
using Carrier = cgal_policies::Corner_attribute_carrier<apps::Point>;

// With bit 0 of `mode`: texture coordinates, a projection of the points on two axes shifted by a
// chart number drawn per face (so seams where charts meet), constant normals, and colours in
// [0, 1] that vary with the point and the chart.
void paint_corner_attributes(apps::Mesh& mesh, std::uint8_t mode) {
  if (!(mode & 1)) return;
  const Attributes attributes = Attributes::add(mesh, {true, true, true, true, false, false});
  const int axis = (mode >> 1) % 3, charts = 1 + (mode >> 3) % 4;
  for (const auto f : mesh.faces()) {
    // A label that every policy keeps on the face, fast's rebuilt ones too.
    (*attributes.materials)[f] = std::uint32_t(f);
    const int chart = int((std::size_t(f) * 2654435761u >> (mode >> 5)) % std::size_t(charts));
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const apps::Point& p = mesh.point(mesh.target(h));
      (*attributes.uvs)[h] = {p[axis] + 4.0 * chart, p[(axis + 1) % 3]};
      (*attributes.normals)[h] = apps::Kernel::Vector_3(0, 0, 1);
      const auto unit = [](double x) { return std::isfinite(x) ? x - std::floor(x) : 0.5; };
      (*attributes.colors)[h] = {unit(p.x()), unit(p.y()), chart / 4.0, 1};
    }
  }
}

// The texture orientation of every face (by its label) and the points of the seam corners, before a
// run.
struct Seam_record {
  std::map<std::uint32_t, double> uv_areas;  // by the face's label (its material)
  std::vector<apps::Point> seam_corners;
};

Seam_record record_seams(apps::Mesh& mesh) {
  Seam_record record;
  const Attributes attributes(mesh);
  if (!attributes.uvs) return record;
  for (const auto f : mesh.faces())
    record.uv_areas[(*attributes.materials)[f]] = attributes.face_uv_area(mesh, f);
  const Carrier carrier(mesh);
  for (const auto v : mesh.vertices())
    if (cgal_policies::internal::is_seam_corner(carrier.seam_edges_at(v)))
      record.seam_corners.push_back(mesh.point(v));
  return record;
}

// After a run that carried the attributes.
void require_seams_kept(const apps::Mesh& mesh, const Seam_record& record, const std::string& run) {
  const Attributes attributes(mesh);
  for (const auto f : mesh.faces()) {
    for (const auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      require(std::isfinite((*attributes.uvs)[h][0]) && std::isfinite((*attributes.uvs)[h][1]),
              run + ": finite texture coordinates");
      for (const double c : (*attributes.colors)[h])
        require(c >= 0 && c <= 1, run + ": colours within [0, 1]");
    }
    const double before = record.uv_areas.at((*attributes.materials)[f]),
                 after = attributes.face_uv_area(mesh, f);
    require(before == 0 || before * after > 0, run + ": no texture triangle turned over");
  }
  std::set<apps::Point> points;
  for (const auto v : mesh.vertices()) points.insert(mesh.point(v));
  for (const apps::Point& p : record.seam_corners)
    require(points.count(p) == 1, run + ": every seam corner kept where it was");
}

// A value of `option` from the bytes, within its range; whole numbers and open ranges are kept
// small so that one input runs in well under a second.
double option_value(const apps::Policy_option& option, fuzz::Byte_reader& bytes) {
  if (option.is_flag) return 1;
  const double low = std::isfinite(option.min) ? option.min : 0;
  const double high = std::min(std::isfinite(option.max) ? option.max : low + 1,
                               option.is_whole ? low + 20 : low + 1e9);
  double value = low + bytes.unit() * (high - low);
  if (option.is_whole) value = std::floor(value);
  if (option.min_is_excluded && value <= option.min) value = option.default_value;
  return value;
}

// The policy's options and the angle from the bytes; max_error for a policy that takes it.
void read_settings(const apps::Policy_entry& policy, fuzz::Byte_reader& bytes,
                   cgal_policies::Simplification_options& options) {
  options.policy = policy.policy;
  if (bytes.u8() >= 128) options.max_normal_angle_deg = bytes.unit() * 180;
  apps::Option_values values;
  for (const apps::Policy_option& option : policy.options)
    if (bytes.u8() >= 128) values[option.name] = option_value(option, bytes);
  apply_policy_options(policy, values, options);
  if (cgal_policies::runs_edge_collapse(policy.policy) && bytes.u8() >= 128)
    options.max_error = 1e-4 + bytes.unit() * 0.2;
}

// The evaluator's two-sided Hausdorff distance of `mesh` to `original` is within `bound` (a
// fraction of the original's diagonal); it samples, so it never sees more than the true distance.
void require_within(const apps::Mesh& original, const apps::Mesh& mesh, double bound,
                    const std::string& after) {
  const apps::Mesh_error error = apps::measure_mesh_error(original, mesh, 500);
  require(error.hausdorff <= bound * error.bbox_diagonal * (1 + 1e-9),
          after + ": two-sided Hausdorff " + std::to_string(error.hausdorff / error.bbox_diagonal) +
              " of the diagonal, above the bound " + std::to_string(bound));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using cgal_policies::Simplification_pass;
  fuzz::Byte_reader bytes(data, size);
  const auto& registry = apps::policy_registry();
  const apps::Policy_entry& policy = registry[bytes.u8() % registry.size()];
  const std::uint8_t passes = bytes.u8();  // which passes run around the policy, one bit each
  const std::size_t min_component = passes & 1 ? bytes.u8() % 8 : 0;
  fuzz::Byte_reader settings_bytes = bytes;  // the settings are read once the face count is known
  for (int i = 0; i + 1 < kSettingsBytes; ++i) bytes.u8();
  const std::uint8_t attribute_mode = bytes.u8();
  fuzz::Soup soup = fuzz::read_soup(bytes);
  apps::Mesh mesh;
  try {
    mesh = apps::triangle_mesh_from_soup("soup", soup.points, soup.polygons);
  } catch (const cgal_policies::io::Io_error&) {
    return 0;  // the repair fuzzer covers what the reader refuses
  }
  cgal_policies::Simplification_options options;
  options.fit = false;
  options.target = cgal_policies::Face_target::faces(std::max<std::size_t>(
      1, std::size_t(std::llround(settings_bytes.unit() * mesh.number_of_faces()))));
  read_settings(policy, settings_bytes, options);
  options.min_component = min_component;
  options.drop_small_pieces = passes & 2;
  const double bound = options.two_sided_bound();
  if (passes & 4) {
    options.smoothing.iterations = 1 + (passes >> 5) % 3;
    options.smoothing.bounded = bound > 0;
  }
  if (passes & 8) {
    options.fit = true;
    options.fit_options.rounds = 1 + (passes >> 4) % 2;
    options.fit_options.min_input_samples = 2000;  // the default's are slow in the sanitized build
  }
  const std::string run =
      policy.name + " to " + std::to_string(options.target.face_count()) + " faces";

  paint_corner_attributes(mesh, attribute_mode);
  const apps::Mesh original = mesh;
  Seam_record seams = record_seams(mesh);
  const bool manifold_input =
      fuzz::require_finite_triangle_mesh(original, "the input").non_manifold_vertices == 0;
  // Components dropped whole are gone from the output by the user's choice: no bound holds after.
  double kept_bound = bound;
  const bool carried = cgal_policies::Corner_attributes<apps::Point>(mesh).any_corner_values();
  // Valid, finite, manifold when the input is, and within the run's bound when it has one.
  options.pass_done = [&](Simplification_pass pass) {
    const std::string after = run + ", " + to_string(pass);
    if (pass == Simplification_pass::components) seams = record_seams(mesh);
    if (pass == Simplification_pass::simplification && carried)
      require_seams_kept(mesh, seams, after);
    const bool dropping =
        pass == Simplification_pass::components || pass == Simplification_pass::pieces;
    if (dropping && mesh.number_of_faces() < original.number_of_faces()) kept_bound = 0;
    const apps::Mesh_validity validity = fuzz::require_finite_triangle_mesh(mesh, after);
    require(!manifold_input || validity.non_manifold_vertices == 0, after + ": manifold");
    if (kept_bound > 0) require_within(original, mesh, kept_bound, after);
  };
  const cgal_policies::Simplification_report report = apps::Pipeline(options).run(mesh, original);
  require(!carried || report.attributes_carried, run + ": the corner attributes carried");
  require(report.stop_reason != cgal_policies::Stop_reason::target_reached ||
              report.output_faces <= report.target_faces,
          run + ": the target is met when the run says so");
  require(mesh.number_of_faces() <= original.number_of_faces(), run + ": no face added");
  return 0;
}
