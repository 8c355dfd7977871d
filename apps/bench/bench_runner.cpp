#include "bench_runner.h"

#include "Run_memory_probe.h"
#include "cli/Stopwatch.h"
#include "cli/report_fields.h"
#include "io/mesh_io.h"

#include <cgal_policies/Corner_attributes.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace apps {
namespace {

// Progress lines on stderr: which case, how many runs are left, the time elapsed.
class Bench_progress {
 public:
  explicit Bench_progress(std::size_t total_runs) : m_total(total_runs) {}

  void start_run(const std::string& what) {
    ++m_done;
    const long elapsed = long(elapsed_seconds());
    std::fprintf(stderr, "[%zu/%zu, %zu left, %ld:%02ld elapsed] %s\n", m_done, m_total,
                 m_total - m_done, elapsed / 60, elapsed % 60, what.c_str());
  }

  double elapsed_seconds() const { return m_watch.seconds(); }

 private:
  std::size_t m_total, m_done = 0;
  Stopwatch m_watch;
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// Runs one row `repetitions` times on copies of `original`; keeps the first result. A run cut
// short by the time limit is not repeated: the others would be cut short too.
Run_record run_row(const Mesh& original, const Bench_row& row, const Bench_plan& plan,
                   const Bench_settings& settings, Bench_progress& progress,
                   const std::string& case_name) {
  Run_record record;
  record.policy = row.name;
  record.repetitions = plan.repetitions;
  std::vector<double> seconds, fit_seconds;
  Mesh result;
  for (std::size_t rep = 0; rep < plan.repetitions; ++rep) {
    progress.start_run(case_name + ", " + row.name + ", repetition " + std::to_string(rep + 1) +
                       "/" + std::to_string(plan.repetitions));
    Mesh mesh = original;
    const Run_memory_probe memory;
    const Bench_run outcome = row.run(mesh, settings);
    record.peak_memory_mib = std::max(record.peak_memory_mib, memory.peak_mib());
    record.memory_added_mib = std::max(record.memory_added_mib, memory.added_mib());
    seconds.push_back(outcome.seconds);
    fit_seconds.push_back(outcome.fit_seconds);
    if (rep == 0) {
      record.stop_reason = to_string(outcome.stop_reason);
      record.fit_flips = outcome.fit_flips;
      if (plan.attributes)
        record.attributes = corner_attributes_word(
            cgal_policies::Corner_attributes<Point>(original).any_corner_values(),
            outcome.attributes_carried);
      result = std::move(mesh);
    } else if (mesh.number_of_faces() != result.number_of_faces()) {
      std::fprintf(stderr, "simplify_bench: %s: %s is not deterministic (%zu then %zu faces)\n",
                   case_name.c_str(), row.name.c_str(), std::size_t(result.number_of_faces()),
                   std::size_t(mesh.number_of_faces()));
    }
    if (outcome.stop_reason == cgal_policies::Stop_reason::time_limit) {
      record.repetitions = rep + 1;
      break;
    }
  }
  // The same steps as simplify --measure, so that both measure the very same mesh.
  result.collect_garbage();
  record.output_faces = result.number_of_faces();
  record.output_vertices = result.number_of_vertices();
  record.seconds = *std::min_element(seconds.begin(), seconds.end());
  record.seconds_median = median(seconds);
  record.fit_seconds = *std::min_element(fit_seconds.begin(), fit_seconds.end());
  record.error = measure_mesh_error(original, result, plan.samples);
  record.validity = check_mesh_validity(result);
  if (record.attributes == "carried")
    record.attribute_error = measure_attribute_error(original, result, plan.samples);
  return record;
}

}  // namespace

double mean_error_rel(const Run_record& r) {
  const double d = r.error.bbox_diagonal > 0 ? r.error.bbox_diagonal : 1;
  return (r.error.mean_a_to_b + r.error.mean_b_to_a) / (2 * d);
}

std::vector<Run_record> run_bench(const Bench_plan& plan) {
  std::size_t total = 0;
  for (const Bench_mesh& m : plan.meshes)
    total += m.targets.size() * plan.rows.size() * plan.repetitions;
  Bench_progress progress(total);

  std::vector<Run_record> records;
  for (const Bench_mesh& bench_mesh : plan.meshes) {
    Read_report read_report;
    const Mesh original = read_triangle_mesh(
        bench_mesh.path, &read_report,
        plan.attributes ? Corner_attribute_reading::keep : Corner_attribute_reading::drop);
    const std::string name = std::filesystem::path(bench_mesh.path).filename().string();
    for (const std::string& repair : read_report.repairs)
      std::fprintf(stderr, "simplify_bench: %s: %s\n", bench_mesh.path.c_str(), repair.c_str());

    for (const Bench_target& target : bench_mesh.targets) {
      const std::size_t target_faces = target_face_count(target, original.number_of_faces());
      const std::string case_name =
          name + " to " + std::to_string(target_faces) + " faces (" + describe_target(target) + ")";
      const std::size_t first = records.size();
      for (const Bench_row& row : plan.rows) {
        const Bench_settings settings{target_faces, plan.time_limit_seconds, plan.options};
        Run_record r = run_row(original, row, plan, settings, progress, case_name);
        r.mesh = name;
        r.input_faces = original.number_of_faces();
        r.input_vertices = original.number_of_vertices();
        r.target = describe_target(target);
        r.label = target.label;
        r.target_ratio = target.ratio;
        r.target_faces = target_faces;
        const std::size_t removed = r.input_faces - std::min(r.input_faces, r.output_faces);
        r.faces_removed_per_second = r.seconds > 0 ? double(removed) / r.seconds : 0.0;
        std::fprintf(stderr, "    %s: %zu faces in %.3f s, Hausdorff %.4f%%, mean %.4f%%%s\n",
                     r.policy.c_str(), r.output_faces, r.seconds,
                     100 * r.error.hausdorff / r.error.bbox_diagonal, 100 * mean_error_rel(r),
                     r.validity.valid ? "" : ", INVALID mesh");
        records.push_back(std::move(r));
      }
      const auto gh = std::find_if(records.begin() + long(first), records.end(),
                                   [](const Run_record& r) { return r.policy == "gh"; });
      for (auto it = records.begin() + long(first); it != records.end(); ++it)
        it->time_vs_gh = gh != records.end() && gh->seconds > 0
                             ? it->seconds / gh->seconds
                             : std::numeric_limits<double>::quiet_NaN();
    }
    if (plan.on_mesh_done) plan.on_mesh_done(records);
  }
  if (!Run_memory_probe().resets())
    std::fprintf(stderr,
                 "simplify_bench: the kernel refused to reset the peak memory: the memory figures "
                 "are the process's peaks so far\n");
  std::fprintf(stderr, "simplify_bench: %zu runs in %.1f s\n", total, progress.elapsed_seconds());
  return records;
}

}  // namespace apps
