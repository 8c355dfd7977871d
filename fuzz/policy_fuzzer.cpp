// Fuzzes every policy of the registry as simplify runs it, on small meshes built from the bytes
// (fuzz_soup.h, repaired by the reader's pipeline) with options drawn from the bytes, each within
// its documented range, and the passes around the run (small components, smoothing, fitting). The
// output must be a valid triangle mesh with finite points, manifold when the input is; it meets
// the face target or says why not; and when the run has a two-sided bound, the evaluator finds
// no sample farther than it. The mesh may carry texture coordinates and normals, cut into charts
// (so with seams); a run that carries them keeps them finite, keeps every seam corner where it
// was, and turns no texture triangle over.
#include "fuzz_checks.h"
#include "fuzz_soup.h"

#include "common/App_error.h"
#include "common/fitting.h"
#include "common/mesh_io.h"
#include "common/mesh_measures.h"
#include "common/policy_registry.h"
#include "common/small_components.h"
#include "common/smoothing.h"

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Two_sided_fitter.h>

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
  const Attributes attributes = Attributes::add(mesh, {true, true, true, true});
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
  for (const auto v : mesh.vertices()) {
    const std::size_t seams = carrier.seam_edges_at(v);
    if (seams != 0 && seams != 2) record.seam_corners.push_back(mesh.point(v));
  }
  return record;
}

// After a run that carried the attributes, before its garbage is collected.
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

apps::Simplify_settings read_settings(const apps::Policy_entry& policy, std::size_t faces,
                                      fuzz::Byte_reader& bytes) {
  apps::Simplify_settings settings = apps::default_settings(policy, 0);
  settings.target_faces = std::max<std::size_t>(1, std::size_t(std::llround(bytes.unit() * faces)));
  if (bytes.u8() >= 128) settings.max_normal_angle_deg = bytes.unit() * 180;
  for (const apps::Policy_option& option : policy.options)
    if (bytes.u8() >= 128) settings.options[option.name] = option_value(option, bytes);
  apps::check_policy_options(policy, settings.options);
  if (policy.takes_error_bound && bytes.u8() >= 128) settings.max_error = 1e-4 + bytes.unit() * 0.2;
  return settings;
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
  } catch (const apps::App_error&) {
    return 0;  // the repair fuzzer covers what the reader refuses
  }
  apps::Simplify_settings settings = read_settings(policy, mesh.number_of_faces(), settings_bytes);
  const std::string run = policy.name + " to " + std::to_string(settings.target_faces) + " faces";

  apps::drop_components_smaller_than(mesh, min_component);
  paint_corner_attributes(mesh, attribute_mode);
  const apps::Mesh original = mesh;
  const Seam_record seams = record_seams(mesh);
  const bool manifold_input =
      fuzz::require_finite_triangle_mesh(original, "the input").non_manifold_vertices == 0;
  // Valid, finite, manifold when the input is, and within the run's bound when it has one.
  const auto require_sound = [&](double bound, const std::string& after) {
    const apps::Mesh_validity validity = fuzz::require_finite_triangle_mesh(mesh, after);
    require(!manifold_input || validity.non_manifold_vertices == 0, after + ": manifold");
    if (bound > 0) require_within(original, mesh, bound, after);
  };
  const apps::Simplify_outcome outcome = policy.run(mesh, settings);
  if (outcome.attributes_carried) require_seams_kept(mesh, seams, run);
  mesh.collect_garbage();
  double bound = apps::two_sided_bound(policy, settings);
  require_sound(bound, run);
  require(outcome.stop_reason != apps::Stop_reason::target_reached ||
              mesh.number_of_faces() <= settings.target_faces,
          run + ": the target is met when the run says so");
  require(mesh.number_of_faces() <= original.number_of_faces(), run + ": no face added");
  // Pieces dropped whole are gone from the output by the user's choice: no bound holds after it.
  if ((passes & 2) && apps::drop_smallest_components_until(mesh, settings.target_faces).faces > 0) {
    bound = 0;
    require_sound(bound, run + ", pieces dropped");
  }

  if (passes & 4) {
    apps::Smoothing_request smoothing;
    smoothing.iterations = 1 + (passes >> 5) % 3;
    smoothing.bounded = bound > 0;
    apps::smooth_mesh(mesh, original, smoothing, bound);
    require_sound(bound, run + ", smoothed");
  }
  if (passes & 8) {
    cgal_policies::Two_sided_fit_options options;
    options.rounds = 1 + (passes >> 4) % 2;
    options.min_input_samples = 2000;  // the default's 100,000 are slow in the sanitized build
    options.max_normal_angle_deg = settings.max_normal_angle_deg;
    options.tolerance = bound;
    cgal_policies::Two_sided_fitter<apps::Mesh>(original, options).fit(mesh);
    require_sound(bound, run + ", fitted");
  }
  return 0;
}
