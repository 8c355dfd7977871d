// The files through which the steps of a partitioned job (Simplification_pipeline::cut,
// run_part, stitch, result; docs/scale.md) hand their work on, in a folder that every step sees.
// The job runs in stages, each a task per part and a stitch: stage 0 simplifies the parts, stages
// 1 and 2 run the halves of the fit by cells.
//   job              what the steps leave to the next: the cells, the counts, the report so far
//   input            the input whole, for the passes that measure against it when it runs whole
//                    or under a bound (the fit, bounded smoothing)
//   input_as_cut     the mesh the parts were cut from, under a bound: the last pass certifies
//                    against it
//   part_S_C         part C of stage S (raw_mesh_file.h), done_S_C once its task ran, and
//   outcome_S_C      what that task reported
//   near_S_C         the input's part C of fit stage S, which part_S_C is fitted to
//   output           the stitched mesh: the result once the last stage is stitched
#ifndef CGAL_POLICIES_INTERNAL_PARTITIONED_JOB_FILES_H
#define CGAL_POLICIES_INTERNAL_PARTITIONED_JOB_FILES_H

#include <cgal_policies/Simplification_report.h>
#include <cgal_policies/internal/Binary_file.h>
#include <cgal_policies/internal/Policy_outcome.h>
#include <cgal_policies/internal/Spatial_cells.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cgal_policies {
namespace internal {

constexpr std::uint64_t kJobMagic = 0x3242'4f4a'5452'4150;  // "PARTJOB2"

struct Job_header {
  bool partitioned = false;  // false: the only part is the whole mesh, run as it is
  std::vector<Spatial_cells::Split> cells, shifted_cells;  // of stages 0-1 and of stage 2
  std::size_t whole_faces = 0, whole_vertices = 0;         // of the mesh that stage 0 cut
  double whole_diagonal = 0;       // of that mesh's bounding box, which the bounds are fractions of
  std::size_t stage_vertices = 0;  // of the mesh that the current fit stage cut
  Simplification_report report;    // of the stages stitched so far
};

struct Part_result {
  bool kept_locks = true;
  Policy_outcome outcome;    // of a part run whole
  Two_sided_fit_report fit;  // of a fit stage's part
  double seconds = 0;
};

inline std::filesystem::path job_file(const std::filesystem::path& folder) {
  return folder / "job";
}
inline std::filesystem::path job_input_file(const std::filesystem::path& folder) {
  return folder / "input";
}
inline std::filesystem::path job_input_as_cut_file(const std::filesystem::path& folder) {
  return folder / "input_as_cut";
}
inline std::filesystem::path job_output_file(const std::filesystem::path& folder) {
  return folder / "output";
}
inline std::filesystem::path stage_file(const std::filesystem::path& folder, const char* kind,
                                        int stage, std::size_t c) {
  return folder / (std::string(kind) + "_" + std::to_string(stage) + "_" + std::to_string(c));
}
inline std::filesystem::path part_file(const std::filesystem::path& folder, int stage,
                                       std::size_t c) {
  return stage_file(folder, "part", stage, c);
}
inline std::filesystem::path done_part_file(const std::filesystem::path& folder, int stage,
                                            std::size_t c) {
  return stage_file(folder, "done", stage, c);
}
inline std::filesystem::path near_part_file(const std::filesystem::path& folder, int stage,
                                            std::size_t c) {
  return stage_file(folder, "near", stage, c);
}

inline void write_report(Binary_file& file, const Simplification_report& r) {
  file.put(r.stop_reason);
  file.put(std::array<std::size_t, 6>{r.input_faces, r.input_vertices, r.target_faces,
                                      r.output_faces, r.output_vertices, r.parts});
  file.put(r.bound);
  file.put(std::array<std::size_t, 3>{r.merged.merged_pairs, r.merged.stitched_edges,
                                      r.merged.refused_pairs});
  file.put(r.merged.refused_by_reason.size());
  for (const auto& [reason, count] : r.merged.refused_by_reason) {
    file.put_string(reason);
    file.put(count);
  }
  file.put(r.dropped_before);
  file.put(r.dropped_after);
  file.put(r.smoothing_refused_moves);
  file.put(r.fitted);
  file.put(r.fit);
  file.put(r.attributes_carried);
  file.put(r.pass_seconds);
}

inline Simplification_report read_report(Binary_file& file) {
  Simplification_report r;
  r.stop_reason = file.get<Stop_reason>();
  const auto counts = file.get<std::array<std::size_t, 6>>();
  r.input_faces = counts[0];
  r.input_vertices = counts[1];
  r.target_faces = counts[2];
  r.output_faces = counts[3];
  r.output_vertices = counts[4];
  r.parts = counts[5];
  r.bound = file.get<double>();
  const auto merged = file.get<std::array<std::size_t, 3>>();
  r.merged.merged_pairs = merged[0];
  r.merged.stitched_edges = merged[1];
  r.merged.refused_pairs = merged[2];
  for (std::size_t i = 0, reasons = file.get<std::size_t>(); i < reasons; ++i) {
    std::string reason = file.get_string();
    r.merged.refused_by_reason[std::move(reason)] = file.get<std::size_t>();
  }
  r.dropped_before = file.get<Dropped_components>();
  r.dropped_after = file.get<Dropped_components>();
  r.smoothing_refused_moves = file.get<std::size_t>();
  r.fitted = file.get<bool>();
  r.fit = file.get<Two_sided_fit_report>();
  r.attributes_carried = file.get<bool>();
  r.pass_seconds = file.get<decltype(r.pass_seconds)>();
  return r;
}

inline void write_job_header(const std::filesystem::path& folder, const Job_header& job) {
  Binary_file file(job_file(folder), Binary_file::Mode::write);
  file.put(kJobMagic);
  file.put(job.partitioned);
  file.put_vector(job.cells);
  file.put_vector(job.shifted_cells);
  file.put(std::array<std::size_t, 3>{job.whole_faces, job.whole_vertices, job.stage_vertices});
  file.put(job.whole_diagonal);
  write_report(file, job.report);
  file.close();
}

inline Job_header read_job_header(const std::filesystem::path& folder) {
  Binary_file file(job_file(folder), Binary_file::Mode::read);
  if (file.get<std::uint64_t>() != kJobMagic) file.fail("not a job in");
  Job_header job;
  job.partitioned = file.get<bool>();
  job.cells = file.get_vector<Spatial_cells::Split>();
  job.shifted_cells = file.get_vector<Spatial_cells::Split>();
  const auto counts = file.get<std::array<std::size_t, 3>>();
  job.whole_faces = counts[0];
  job.whole_vertices = counts[1];
  job.stage_vertices = counts[2];
  job.whole_diagonal = file.get<double>();
  job.report = read_report(file);
  return job;
}

inline void write_part_result(const std::filesystem::path& folder, int stage, std::size_t c,
                              const Part_result& result) {
  Binary_file file(stage_file(folder, "outcome", stage, c), Binary_file::Mode::write);
  file.put(result);
  file.close();
}

inline Part_result read_part_result(const std::filesystem::path& folder, int stage, std::size_t c) {
  Binary_file file(stage_file(folder, "outcome", stage, c), Binary_file::Mode::read);
  return file.get<Part_result>();
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PARTITIONED_JOB_FILES_H
