#include "bench_runner.h"

#include "Run_memory_probe.h"
#include "cli/Stopwatch.h"
#include "cli/report_fields.h"
#include "io/Streamed_mesh_file.h"
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

// A case's input: held whole, or out of core only its file.
struct Case_input {
  const Mesh* whole;  // nullptr out of core
  std::string path;
};

// Runs one row `repetitions` times on copies of the input; keeps the first result. A run cut
// short by the time limit is not repeated: the others would be cut short too.
Run_record run_row(const Case_input& input, const Bench_row& row, const Bench_plan& plan,
                   const Bench_settings& settings, Bench_progress& progress,
                   const std::string& case_name) {
  Run_record record;
  record.policy = row.name;
  record.threads = settings.threads;
  record.input_read = input.whole ? "whole" : "out of core";
  record.repetitions = plan.repetitions;
  if (input.whole) {
    record.input_faces = input.whole->number_of_faces();
    record.input_vertices = input.whole->number_of_vertices();
  }
  std::vector<double> seconds, fit_seconds;
  Mesh result;
  for (std::size_t rep = 0; rep < plan.repetitions; ++rep) {
    progress.start_run(
        case_name + ", " + row.name +
        (settings.threads ? ", " + std::to_string(settings.threads) + " thread(s)" : "") +
        ", repetition " + std::to_string(rep + 1) + "/" + std::to_string(plan.repetitions));
    Mesh mesh = input.whole ? *input.whole : Mesh();
    const Run_memory_probe memory;
    const Bench_run outcome =
        input.whole ? row.run(mesh, settings) : row.run_out_of_core(input.path, mesh, settings);
    record.peak_memory_mib = std::max(record.peak_memory_mib, memory.peak_mib());
    record.memory_added_mib = std::max(record.memory_added_mib, memory.added_mib());
    seconds.push_back(outcome.seconds);
    fit_seconds.push_back(outcome.fit_seconds);
    if (rep == 0) {
      record.stop_reason = to_string(outcome.stop_reason);
      record.fit_flips = outcome.fit_flips;
      if (!input.whole) {
        record.input_faces = outcome.input_faces;
        record.input_vertices = outcome.input_vertices;
      }
      if (plan.attributes && input.whole)
        record.attributes = corner_attributes_word(
            cgal_policies::Corner_attributes<Point>(*input.whole).any_corner_values(),
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
  if (input.whole) {
    record.error = measure_mesh_error(*input.whole, result, plan.samples);
    record.error_measured = true;
  }
  record.validity = check_mesh_validity(result);
  if (record.attributes == "carried")
    record.attribute_error = measure_attribute_error(*input.whole, result, plan.samples);
  return record;
}

// The thread counts a row runs on.
std::vector<std::size_t> thread_counts(const Bench_row& row, const Bench_plan& plan) {
  return row.uses_threads ? plan.threads : std::vector<std::size_t>{0};
}

// The faces of a mesh the bench reads in passes: a PLY's header declares them, and the target is
// taken of them.
std::size_t declared_faces(const std::string& path) {
  const std::size_t faces = Streamed_mesh_file(path).declared_faces();
  if (faces == 0)
    throw Io_error(Io_error::Kind::unreadable_input,
                   path +
                       ": out of core, the bench takes the target of the faces a PLY header "
                       "declares: give a binary PLY with faces");
  return faces;
}

}  // namespace

double mean_error_rel(const Run_record& r) {
  const double d = r.error.bbox_diagonal > 0 ? r.error.bbox_diagonal : 1;
  return r.error.mean() / d;
}

std::string run_label(const Run_record& r) {
  std::string label = r.policy;
  if (r.threads > 0)
    label += ", " + std::to_string(r.threads) + (r.threads == 1 ? " thread" : " threads");
  if (r.input_read == "out of core") label += ", out of core";
  return label;
}

double pipeline_seconds(const Run_record& r) { return r.seconds + r.fit_seconds; }

void add_scaling(std::vector<Run_record>& records) {
  for (Run_record& r : records) {
    if (r.threads < 2 || !(pipeline_seconds(r) > 0)) continue;
    const auto one = std::find_if(records.begin(), records.end(), [&r](const Run_record& o) {
      return o.threads == 1 && o.mesh == r.mesh && o.target == r.target && o.label == r.label &&
             o.policy == r.policy && o.input_read == r.input_read;
    });
    if (one != records.end()) r.scaling = pipeline_seconds(*one) / pipeline_seconds(r);
  }
}

std::vector<Run_record> run_bench(const Bench_plan& plan) {
  std::size_t total = 0;
  for (const Bench_mesh& m : plan.meshes)
    for (const Bench_row& row : plan.rows)
      if (mesh_runs_row(m, row.name))
        total += m.targets.size() * thread_counts(row, plan).size() * plan.repetitions;
  Bench_progress progress(total);

  std::vector<Run_record> records;
  for (const Bench_mesh& bench_mesh : plan.meshes) {
    Mesh original;
    std::size_t input_faces = 0;
    if (bench_mesh.out_of_core) {
      input_faces = declared_faces(bench_mesh.path);
    } else {
      Read_report read_report;
      original = read_triangle_mesh(
          bench_mesh.path, &read_report,
          plan.attributes ? Corner_attribute_reading::keep : Corner_attribute_reading::drop);
      input_faces = original.number_of_faces();
      for (const std::string& repair : read_report.repairs)
        std::fprintf(stderr, "simplify_bench: %s: %s\n", bench_mesh.path.c_str(), repair.c_str());
      for (const std::string& loss : read_report.left_out)
        std::fprintf(stderr, "simplify_bench: warning: %s\n", loss.c_str());
    }
    const Case_input input{bench_mesh.out_of_core ? nullptr : &original, bench_mesh.path};
    const std::string name = std::filesystem::path(bench_mesh.path).filename().string();

    for (const Bench_target& target : bench_mesh.targets) {
      const std::size_t target_faces = target_face_count(target, input_faces);
      const std::string case_name =
          name + " to " + std::to_string(target_faces) + " faces (" + describe_target(target) + ")";
      const std::size_t first = records.size();
      for (const Bench_row& row : plan.rows) {
        if (!mesh_runs_row(bench_mesh, row.name)) continue;
        for (const std::size_t threads : thread_counts(row, plan)) {
          const Bench_settings settings{target_faces, plan.time_limit_seconds, plan.options,
                                        threads, plan.prepass_factor};
          Run_record r = run_row(input, row, plan, settings, progress, case_name);
          r.mesh = name;
          r.target = describe_target(target);
          r.label = target.label;
          r.target_ratio = target.ratio;
          r.target_faces = target_faces;
          const std::size_t removed = r.input_faces - std::min(r.input_faces, r.output_faces);
          r.faces_removed_per_second = r.seconds > 0 ? double(removed) / r.seconds : 0.0;
          std::fprintf(stderr, "    %s: %zu faces in %.3f s", r.policy.c_str(), r.output_faces,
                       r.seconds);
          if (r.error_measured)
            std::fprintf(stderr, ", Hausdorff %.4f%%, mean %.4f%%",
                         100 * r.error.hausdorff / r.error.bbox_diagonal, 100 * mean_error_rel(r));
          std::fprintf(stderr, "%s\n", r.validity.valid ? "" : ", INVALID mesh");
          records.push_back(std::move(r));
        }
      }
      // Against gh on as many threads, else the first gh run: the peers run on one.
      for (auto it = records.begin() + long(first); it != records.end(); ++it) {
        const auto is_gh = [&](const Run_record& r, bool same_threads) {
          return r.policy == "gh" && (!same_threads || r.threads == it->threads);
        };
        auto gh = std::find_if(records.begin() + long(first), records.end(),
                               [&](const Run_record& r) { return is_gh(r, true); });
        if (gh == records.end())
          gh = std::find_if(records.begin() + long(first), records.end(),
                            [&](const Run_record& r) { return is_gh(r, false); });
        it->time_vs_gh = gh != records.end() && gh->seconds > 0
                             ? it->seconds / gh->seconds
                             : std::numeric_limits<double>::quiet_NaN();
      }
    }
    add_scaling(records);
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
