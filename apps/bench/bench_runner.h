// Runs the benchmark matrix (meshes x targets x policies x repetitions) in one process: times each
// simplification alone, measures each result with the evaluator of mesh_error, and reports
// progress.
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_RUNNER_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_RUNNER_H

#include "Bench_row.h"
#include "bench_presets.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"

#include <CGAL/version.h>

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace apps {

struct Run_record;

struct Bench_plan {
  std::vector<Bench_mesh> meshes;  // paths as given to the reader
  std::vector<Bench_row> rows;     // "gh" among them: the reference of every time ratio
  Option_values options;           // option values given on the command line
  std::size_t repetitions = 1;
  // Each row that uses_threads runs once per count (0: every core), the others once.
  std::vector<std::size_t> threads = {0};
  std::size_t samples = kDefaultErrorSamples;
  // A run still going after this many seconds stops where it is (0: no limit); see run_row.
  double time_limit_seconds = 0;
  // Fast first, down to this many times the target, in every pipeline row without a bound (0:
  // none; not with a time limit).
  double prepass_factor = 0;
  // Read the meshes' corner attributes (OBJ), carry them, and measure them (Run_record).
  bool attributes = false;
  // Called after each mesh with every record so far, to keep partial results of long runs.
  std::function<void(const std::vector<Run_record>&)> on_mesh_done;
};

// One row on one mesh and target: the result of the first repetition, the times of all.
struct Run_record {
  std::string mesh;  // file name
  std::size_t input_faces = 0, input_vertices = 0;
  std::string target;  // describe_target()
  std::string label;
  double target_ratio = 0;  // 0 when the target is a face count
  std::size_t target_faces = 0;
  std::string policy;
  // The CGAL the bench was built with: gh, gh-prob and lt are its policies, and every pipeline
  // row but fast and flat-lt runs in its edge collapse.
  std::string cgal = CGAL_VERSION_STR;
  std::size_t threads = 0;  // Bench_settings::threads: 0 is a row's default
  std::string input_read;   // "whole", or "out of core" (Bench_mesh::out_of_core)
  std::size_t repetitions = 0;
  std::size_t output_faces = 0, output_vertices = 0;
  std::string stop_reason;
  double seconds = 0;  // the fastest repetition
  double seconds_median = 0;
  double time_vs_gh = 0;  // seconds / gh's seconds on the same mesh and target
  double faces_removed_per_second = 0;
  double peak_memory_mib = 0;   // during the simplification (the largest over the repetitions)
  double memory_added_mib = 0;  // that peak minus the resident size just before the run
  double fit_seconds = 0;       // the fitting pass of a "P+fit" run (fastest repetition), else 0
  std::size_t fit_flips = 0;
  // On more than one thread: the same row's time on one thread over this run's (add_scaling).
  std::optional<double> scaling;
  bool error_measured = false;  // out of core, the error is not measured
  Mesh_error error;
  Mesh_validity validity;
  // With Bench_plan::attributes: "carried" or "none" (corner_attributes_word), and the
  // error of the carried attributes.
  std::string attributes;
  Attribute_error attribute_error;
};

// Calls visit(name, value) for every field of a record, in the order of the CSV columns; the
// error and validity fields carry the names of mesh_error --json.
template <typename Visitor>
void for_each_field(const Run_record& r, Visitor&& visit) {
  const double d = r.error.bbox_diagonal > 0 ? r.error.bbox_diagonal : 1;
  // An error not measured is missing, not zero.
  const auto error = [&r](auto value) {
    return r.error_measured ? std::optional<decltype(value)>(value) : std::nullopt;
  };
  visit("mesh", r.mesh);
  visit("input_faces", r.input_faces);
  visit("input_vertices", r.input_vertices);
  visit("target", r.target);
  visit("label", r.label);
  visit("target_ratio", r.target_ratio);
  visit("target_faces", r.target_faces);
  visit("policy", r.policy);
  visit("cgal", r.cgal);
  visit("threads", r.threads);
  visit("input_read", r.input_read);
  visit("repetitions", r.repetitions);
  visit("output_faces", r.output_faces);
  visit("output_vertices", r.output_vertices);
  visit("stop_reason", r.stop_reason);
  visit("seconds", r.seconds);
  visit("seconds_median", r.seconds_median);
  visit("time_vs_gh", r.time_vs_gh);
  visit("faces_removed_per_second", r.faces_removed_per_second);
  visit("peak_memory_mib", r.peak_memory_mib);
  visit("memory_added_mib", r.memory_added_mib);
  visit("bbox_diagonal", error(r.error.bbox_diagonal));
  visit("hausdorff", error(r.error.hausdorff));
  visit("hausdorff_a_to_b", error(r.error.hausdorff_a_to_b));
  visit("hausdorff_b_to_a", error(r.error.hausdorff_b_to_a));
  visit("mean_a_to_b", error(r.error.mean_a_to_b));
  visit("mean_b_to_a", error(r.error.mean_b_to_a));
  visit("rms", error(r.error.rms));
  visit("hausdorff_rel", error(r.error.hausdorff / d));
  visit("mean_a_to_b_rel", error(r.error.mean_a_to_b / d));
  visit("mean_b_to_a_rel", error(r.error.mean_b_to_a / d));
  visit("rms_rel", error(r.error.rms / d));
  visit("samples", error(r.error.samples));
  visit("valid", r.validity.valid);
  visit("closed", r.validity.closed);
  visit("boundary_edges", r.validity.boundary_edges);
  visit("non_manifold_vertices", r.validity.non_manifold_vertices);
  visit("degenerate_faces", r.validity.degenerate_faces);
  visit("min_angle_deg", r.validity.min_angle_deg);
  visit("euler_characteristic", r.validity.euler_characteristic);
  visit("fit_seconds", r.fit_seconds);
  visit("fit_flips", r.fit_flips);
  visit("scaling", r.scaling);
  visit("attributes", r.attributes);
  for_each_field(r.attribute_error, visit);
}

// The mean error of a record in both directions, averaged, relative to the diagonal: the figure the
// tables and the summary rank policies by.
double mean_error_rel(const Run_record& r);

// The row's name, with the threads it was given and "out of core" when they were set: what the
// tables and plots tell runs apart by.
std::string run_label(const Run_record& r);

// The time a run spent in the policy's pass and the fitting pass: the figure of the scaling.
double pipeline_seconds(const Run_record& r);

// Sets the scaling of every run on more than one thread that has a run of the same row (policy)
// on one thread on the same mesh and target: that run's pipeline_seconds over its own.
void add_scaling(std::vector<Run_record>& records);

// Runs the plan, printing progress on stderr. Meshes that cannot be read throw App_error.
std::vector<Run_record> run_bench(const Bench_plan& plan);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_RUNNER_H
