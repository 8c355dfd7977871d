// Simplification_pipeline: the whole pass order of this suite on a CGAL::Surface_mesh, the one
// place that orders the passes (docs/pipeline.md). A Surface_mesh only, by design: the passes keep
// their state and the corner attributes in its property maps and cut, spill and rebuild it; the
// policies and passes it runs, but those that carry corner attributes, take any mesh type on
// their own (docs/compatibility.md), and simplify() refuses another type at compile time. Each
// pass runs only when its options ask for it:
//   1. merge           Border_pair_contraction stitches border pairs closer than merge_distance
//   2. components      components of fewer than min_component faces go, but the largest
//   3. simplification  the policy down to the target, carrying the corner attributes
//                      (Corner_attributes.h) with their seams, within max_error and the time limit;
//                      with prepass_factor, fast first takes the mesh most of the way
//   4. pieces          when no collapse is left short of the target, whole components go
//   5. smoothing       Laplacian_smoother, within the run's bound when asked
//   6. fit             Two_sided_fitter against the input, within the run's bound; on a
//                      textured mesh fitted whole, the texture coordinates off the seams then
//                      solved again against the input's
// The mesh is left compact (garbage collected). Options: Simplification_options (every default in
// the library); the report: Simplification_report. Deterministic: the same mesh and options give
// the same bytes, for any thread count. A large mesh is cut into cells (Simplification_options::
// parts; docs/scale.md): the policy runs on each at once, cut vertices locked, then on the
// stitched whole; the fit likewise, but under a bound. A bound holds as in a whole run: each part
// is certified against itself as cut, the last pass against the mesh the parts were cut from. The
// interruption callback stops the run between collapses or between passes, the mesh valid and
// simplified as far as it got. Usage:
//   cgal_policies::Simplification_options options;  // the library's default pipeline
//   options.target = cgal_policies::Face_target::ratio(0.1);
//   const cgal_policies::Simplification_report report =
//       cgal_policies::Simplification_pipeline<Point>(options).run(mesh);
#ifndef CGAL_POLICIES_SIMPLIFICATION_PIPELINE_H
#define CGAL_POLICIES_SIMPLIFICATION_PIPELINE_H

#include <cgal_policies/Border_pair_contraction.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Hausdorff_move_guard.h>
#include <cgal_policies/Laplacian_smoother.h>
#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/Simplification_report.h>
#include <cgal_policies/internal/Is_surface_mesh.h>
#include <cgal_policies/internal/Part_progress.h>
#include <cgal_policies/internal/Partitioned_job_files.h>
#include <cgal_policies/internal/Spilled_input.h>
#include <cgal_policies/internal/fit_carrying_corner_values.h>
#include <cgal_policies/internal/raw_mesh_file.h>
#include <cgal_policies/internal/run_cgal_policies.h>
#include <cgal_policies/internal/run_flat_array_policies.h>
#include <cgal_policies/internal/run_hausdorff_policy.h>
#include <cgal_policies/internal/run_partitioned.h>
#include <cgal_policies/internal/run_quadric_policies.h>
#include <cgal_policies/small_components.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <system_error>

namespace cgal_policies {

template <class Point>
class Simplification_pipeline {
 public:
  using Mesh = CGAL::Surface_mesh<Point>;

  explicit Simplification_pipeline(const Simplification_options& options = {})
      : m_options(options) {
    CGAL_precondition(options.max_normal_angle_deg >= 0 && options.max_normal_angle_deg <= 180);
    CGAL_precondition(options.max_error >= 0 && options.time_limit_seconds >= 0);
    CGAL_precondition(runs_edge_collapse(options.policy) ||
                      (options.max_error == 0 && options.time_limit_seconds == 0));
    CGAL_precondition(options.merge_distance >= 0);
    CGAL_precondition(options.smoothing.iterations >= 0);
    CGAL_precondition(!options.smoothing.bounded || options.two_sided_bound() > 0);
    CGAL_precondition(options.prepass_factor == 0 || options.prepass_factor >= 1);
    CGAL_precondition(options.prepass_factor == 0 ||
                      (options.two_sided_bound() == 0 && options.time_limit_seconds == 0 &&
                       !options.on_collapse));
  }

  // Runs every pass on `mesh`. The passes that measure against the input (fit, bounded smoothing)
  // keep a copy of it; a partitioned run under a bound keeps another, of the mesh it cuts (after
  // the repairs), for its last pass.
  Simplification_report run(Mesh& mesh) const {
    return needs_input() ? run(mesh, Mesh(mesh)) : run(mesh, Mesh());
  }

  // The same, with the caller's copy of the input (`mesh` as it was), for a caller that keeps one
  // anyway; it may be empty when neither the fit nor bounded smoothing runs.
  Simplification_report run(Mesh& mesh, const Mesh& input) const {
    Simplification_report report = run_repairs(mesh);
    const std::optional<internal::Spatial_cells> cells = cells_of(mesh);
    report.parts = cells ? cells->size() : 1;
    // 3: the policy; its seconds exclude the garbage collection after it.
    timed(report, Simplification_pass::simplification, [&] {
      const std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
      std::optional<internal::Policy_outcome> outcome;
      if (cells) {
        const bool flat_parts = internal::runs_on_flat_parts(mesh, m_options);
        // CGAL's edge collapse takes edges of zero length unasked, locked ends or not. The flat
        // engines never collapse a locked end: their runs leave those edges to them, and spare a
        // garbage collection of the whole mesh on one core.
        if (!flat_parts) internal::collapse_zero_length_edges(mesh);
        const double diagonal = diagonal_of(mesh);
        const std::optional<Mesh> input_as_cut =
            keeps_input_as_cut() ? std::optional<Mesh>(mesh) : std::nullopt;
        internal::Part_progress progress(m_options.progress, mesh.number_of_faces(),
                                         report.target_faces);
        const auto run_policy =
            part_or_stitched_runner(mesh, input_as_cut, diagonal, progress, started);
        if (flat_parts)
          outcome = internal::run_flat_partitioned(
              mesh, report.target_faces, *cells, m_options.threads,
              [&](internal::Flat_part& part, std::size_t target) {
                Simplification_options options = m_options;
                options.progress = progress.of_part(part.triangles.size());
                return internal::run_on_flat_part(part, target, options);
              },
              run_policy);
        else
          outcome = internal::run_partitioned(mesh, report.target_faces, *cells, m_options.threads,
                                              run_policy);
      }
      if (!outcome) {
        report.parts = 1;
        outcome = run_policy_in_time(mesh, report.target_faces, m_options, nullptr, started);
      }
      report.stop_reason = outcome->stop_reason;
      report.attributes_carried = outcome->attributes_carried;
    });
    finish(report, mesh, input, [&](const Two_sided_fit_options& fit) {
      return report.parts > 1 && fits_by_cells()
                 ? internal::fit_by_cells(mesh, input, *cells, m_options.threads, fit)
                 : internal::fit_carrying_corner_values(mesh, input, fit);
    });
    return report;
  }

  // A mesh too large to hold whole, read from `source` in passes (the concept is in
  // internal/Streamed_cut.h) into `mesh`, which it replaces: equal points joined, cut into cells
  // with the triangles spilled to temporary files, each cell's part simplified as in a partitioned
  // run, the parts stitched and finished, then the fit by cells against the spilled input. Peak
  // memory: the points, the parts in flight and the output. The corner values and materials the
  // source carries are carried as in memory. Without the passes that need the whole input (merge,
  // components, a bound, bounded smoothing): those options are preconditions. The simplification
  // pass's seconds include the reading.
  template <class Source>
  Simplification_report run_streamed(const Source& source, Mesh& mesh) const {
    check_streamed_options();
    mesh.clear();
    const auto start = std::chrono::steady_clock::now();
    const internal::Spilled_input<Point> input(source, m_options);
    Simplification_report report = streamed_report(input);
    internal::Part_progress progress(m_options.progress, input.faces(), report.target_faces);
    const std::optional<Mesh> input_as_cut;  // none: no bound out of core
    const std::optional<internal::Policy_outcome> outcome = internal::run_parts(
        report.parts, input.faces(), input.vertices(), report.target_faces, m_options.threads,
        parts_of(input, input.spills()),
        part_or_stitched_runner(mesh, input_as_cut, input.diagonal(), progress, start), mesh);
    if (!outcome) throw std::logic_error("a part lost a vertex of its cut");
    report.stop_reason = outcome->stop_reason;
    report.attributes_carried = outcome->attributes_carried;
    report.pass_seconds[std::size_t(Simplification_pass::simplification)] = seconds_since(start);
    finish(report, mesh, Mesh(), [&](const Two_sided_fit_options& fit) {
      // One cell is the whole input: fitted whole, as run() fits a mesh it did not cut.
      if (report.parts == 1)
        return internal::fit_carrying_corner_values(mesh, input.part(input.spills(), 0), fit);
      const internal::Spatial_cells shifted = input.shifted_cells(m_options.threads);
      std::optional<internal::Spill_files> shifted_spills;
      const auto input_parts = [&](const internal::Spatial_cells& by) {
        const bool first_half = &by == &input.cells();
        if (!first_half) input.spill_shifted(shifted, shifted_spills);
        return [parts = parts_of(input, first_half ? input.spills() : *shifted_spills)](
                   std::size_t c) { return internal::near_triangles(parts(c)); };
      };
      return internal::fit_by_cells(mesh, input.cells(), shifted, m_options.threads, fit,
                                    input_parts);
    });
    return report;
  }

  // A partitioned run as tasks that hand their work on through files in `folder` (empty, and seen
  // by every task), so that a task scheduler (Dask, Ray) may run them in other processes or on
  // other machines (docs/scale.md). The job runs in stages, each a task per part and a stitch:
  //   const std::size_t parts = pipeline.cut(mesh, folder);  // or cut_streamed(source, folder)
  //   for (int stage = 0;; ++stage) {
  //     for (std::size_t c = 0; c < parts; ++c) pipeline.run_part(folder, stage, c);  // anywhere
  //     if (!pipeline.stitch(folder, stage)) break;
  //   }
  //   const Simplification_report report = pipeline.result(folder, mesh);
  // Stage 0 simplifies the parts; stages 1 and 2 run the halves of the fit by cells. Every task is
  // given the same options, and the result is run(mesh)'s, byte for byte; but where a part lost a
  // vertex of its cut, the run over the whole starts from the parts put back together, in their
  // vertex order. A mesh that run() would not cut is one part, run whole.

  // Runs the repairs (passes 1-2) on `mesh` and cuts it into the parts of each stage; returns
  // their number. Keeps a copy of the input while it cuts when a pass measures against it; under a
  // bound, writes the mesh it cuts too, for the last pass.
  std::size_t cut(Mesh& mesh, const std::filesystem::path& folder) const {
    CGAL_precondition(!m_options.on_collapse);
    const auto start = std::chrono::steady_clock::now();
    std::optional<Mesh> input;
    if (needs_input()) input.emplace(mesh);
    internal::Job_header job;
    job.report = run_repairs(mesh);
    const std::optional<internal::Spatial_cells> cells = cells_of(mesh);
    job.partitioned = cells.has_value();
    job.report.parts = cells ? cells->size() : 1;
    if (cells) {
      internal::collapse_zero_length_edges(mesh);
      const std::vector<std::uint32_t> cell = internal::face_cells(mesh, *cells, m_options.threads);
      for (std::size_t c = 0; c < cells->size(); ++c)
        internal::write_raw_mesh(internal::mesh_part(mesh, cell, std::uint32_t(c)),
                                 internal::part_file(folder, 0, c));
      job.cells = cells->splits();
      job.whole_diagonal = diagonal_of(mesh);
      if (keeps_input_as_cut())
        internal::write_raw_mesh(mesh, internal::job_input_as_cut_file(folder));
    } else {
      internal::write_raw_mesh(mesh, internal::part_file(folder, 0, 0));
    }
    job.whole_faces = mesh.number_of_faces();
    job.whole_vertices = mesh.number_of_vertices();
    if (input && (!cells || !fits_by_cells()))
      internal::write_raw_mesh(*input, internal::job_input_file(folder));
    if (input && cells && m_options.fit && fits_by_cells()) {
      // The input's part of each cell, for the fit's stages: the same cells, then shifted ones.
      const std::vector<Eigen::Vector3d> centroids =
          internal::face_centroids(*input, m_options.threads);
      const internal::Spatial_cells shifted =
          internal::shifted_cells(centroids, *cells, m_options.threads);
      job.shifted_cells = shifted.splits();
      for (const int stage : {1, 2}) {
        const std::vector<std::uint32_t> cell =
            internal::face_cells(centroids, stage == 1 ? *cells : shifted, m_options.threads);
        for (std::size_t c = 0; c < cells->size(); ++c)
          internal::write_raw_mesh(internal::mesh_part(*input, cell, std::uint32_t(c), false),
                                   internal::near_part_file(folder, stage, c));
      }
    }
    job.report.pass_seconds[std::size_t(Simplification_pass::simplification)] =
        seconds_since(start) - job.report.total_seconds();
    internal::write_job_header(folder, job);
    return job.report.parts;
  }

  // cut() for a mesh too large to hold whole, read from `source` in passes as run_streamed reads
  // it: the parts of every stage are written from the triangles spilled by cell, one part per
  // thread at a time, never from the whole. run_streamed's preconditions; the job's result is
  // run_streamed's, byte for byte. Returns the number of parts: 0, nothing written, for a source
  // without a face.
  template <class Source>
  std::size_t cut_streamed(const Source& source, const std::filesystem::path& folder) const {
    check_streamed_options();
    const auto start = std::chrono::steady_clock::now();
    const internal::Spilled_input<Point> input(source, m_options);
    if (input.faces() == 0) return 0;
    internal::Job_header job;
    job.report = streamed_report(input);
    job.partitioned = true;
    job.cells = input.cells().splits();
    job.whole_diagonal = input.diagonal();
    job.whole_faces = input.faces();
    job.whole_vertices = input.vertices();
    // Each cell's part, for stage 0 and, as the input near the cell, for the fit's first half:
    // the same file twice, linked where the folder's file system allows it.
    internal::for_each_in_parallel(job.report.parts, m_options.threads, [&](std::size_t c) {
      const Mesh part = input.part(input.spills(), c);
      internal::write_raw_mesh(part, internal::part_file(folder, 0, c));
      if (!m_options.fit) return;
      std::error_code not_linked;
      std::filesystem::create_hard_link(internal::part_file(folder, 0, c),
                                        internal::near_part_file(folder, 1, c), not_linked);
      if (not_linked) internal::write_raw_mesh(part, internal::near_part_file(folder, 1, c));
    });
    if (m_options.fit) {
      const internal::Spatial_cells shifted = input.shifted_cells(m_options.threads);
      job.shifted_cells = shifted.splits();
      std::optional<internal::Spill_files> shifted_spills;
      input.spill_shifted(shifted, shifted_spills);
      internal::for_each_in_parallel(shifted.size(), m_options.threads, [&](std::size_t c) {
        internal::write_raw_mesh(input.part(*shifted_spills, c),
                                 internal::near_part_file(folder, 2, c));
      });
    }
    job.report.pass_seconds[std::size_t(Simplification_pass::simplification)] =
        seconds_since(start);
    internal::write_job_header(folder, job);
    return job.report.parts;
  }

  // Runs part c of `stage`: the policy on it, or a half of the fit.
  void run_part(const std::filesystem::path& folder, int stage, std::size_t c) const {
    const auto start = std::chrono::steady_clock::now();
    const internal::Job_header job = internal::read_job_header(folder);
    Mesh part = internal::read_raw_mesh<Point>(internal::part_file(folder, stage, c));
    internal::Part_result result;
    if (stage > 0) {
      result.fit = internal::fit_part(part,
                                      internal::near_triangles(internal::read_raw_mesh<Point>(
                                          internal::near_part_file(folder, stage, c))),
                                      fit_stage_options(job.report, stage));
    } else if (job.partitioned) {
      result.kept_locks = internal::simplify_part(
          part, job.report.target_faces, job.whole_faces, [&](Mesh& m, std::size_t target) {
            return run_on_part(m, target, job.whole_diagonal, nullptr,
                               std::chrono::steady_clock::now());
          });
    } else {
      result.outcome = run_policy(part, job.report.target_faces, m_options, nullptr);
      part.collect_garbage();
    }
    internal::write_raw_mesh(part, internal::done_part_file(folder, stage, c));
    result.seconds = seconds_since(start);
    internal::write_part_result(folder, stage, c, result);
  }

  // Stitches the parts of `stage` that run_part left; true when another stage follows. Each
  // pass's seconds add those of its stitches and of the slowest part of each stage: the job's
  // time when every part has a core of its own.
  bool stitch(const std::filesystem::path& folder, int stage) const {
    const auto start = std::chrono::steady_clock::now();
    internal::Job_header job = internal::read_job_header(folder);
    Simplification_report& report = job.report;
    const std::size_t parts = report.parts;
    std::vector<internal::Part_result> results;
    for (std::size_t c = 0; c < parts; ++c)
      results.push_back(internal::read_part_result(folder, stage, c));
    double slowest = 0;
    for (const internal::Part_result& r : results) slowest = std::max(slowest, r.seconds);
    // The parts file_of(folder, of_stage, c) of a mesh of `whole_vertices` vertices, stitched.
    const auto stitched = [&](const auto& file_of, int of_stage, std::size_t whole_vertices) {
      std::vector<Mesh> meshes(parts);
      for (std::size_t c = 0; c < parts; ++c)
        meshes[c] = internal::read_raw_mesh<Point>(file_of(folder, of_stage, c));
      return internal::stitch_parts(meshes, whole_vertices);
    };
    Mesh mesh;
    int next = 0;  // the stage that follows, 0 for none
    if (stage == 0) {
      internal::Policy_outcome outcome = results.front().outcome;  // of a part run whole
      if (!job.partitioned) {
        mesh = internal::read_raw_mesh<Point>(internal::done_part_file(folder, 0, 0));
      } else {
        const bool kept_locks =
            std::all_of(results.begin(), results.end(), [](const auto& r) { return r.kept_locks; });
        mesh = stitched(kept_locks ? internal::done_part_file : internal::part_file, 0,
                        job.whole_vertices);
        if (kept_locks) {
          outcome = run_over_stitched(
              mesh, report.target_faces,
              keeps_input_as_cut() ? std::optional<Mesh>(internal::read_raw_mesh<Point>(
                                         internal::job_input_as_cut_file(folder)))
                                   : std::nullopt,
              job.whole_diagonal, nullptr, std::chrono::steady_clock::now());
        } else {
          report.parts = 1;
          outcome = run_policy(mesh, report.target_faces, m_options, nullptr);
        }
      }
      report.stop_reason = outcome.stop_reason;
      report.attributes_carried = outcome.attributes_carried;
      report.pass_seconds[std::size_t(Simplification_pass::simplification)] +=
          slowest + seconds_since(start);
      // The input, written whole when the run was not cut or is bounded; when a part lost a vertex
      // of its cut, put back together from its parts for the fit.
      const bool whole_input = needs_input() && (!job.partitioned || !fits_by_cells());
      const Mesh input = whole_input
                             ? internal::read_raw_mesh<Point>(internal::job_input_file(folder))
                         : report.parts == 1 && m_options.fit
                             ? stitched(internal::near_part_file, 1, report.input_vertices)
                             : Mesh();
      finish(report, mesh, input, [&](const Two_sided_fit_options& fit) {
        if (report.parts == 1 || !fits_by_cells())
          return internal::fit_carrying_corner_values(mesh, input, fit);
        next = 1;
        return Two_sided_fit_report();
      });
    } else {
      const auto fit_start = std::chrono::steady_clock::now();
      mesh = stitched(internal::done_part_file, stage, job.stage_vertices);
      std::vector<Two_sided_fit_report> fits;
      for (const internal::Part_result& r : results) fits.push_back(r.fit);
      const Two_sided_fit_report half = internal::add_cell_fit_reports(fits);
      report.fit.rounds += half.rounds;
      internal::add_fit_counts(report.fit, half);
      if (stage == 1 && fit_stage_options(report, 2).rounds > 0) next = 2;
      report.pass_seconds[std::size_t(Simplification_pass::fit)] +=
          slowest + seconds_since(fit_start);
      report.output_faces = mesh.number_of_faces();
      report.output_vertices = mesh.number_of_vertices();
    }
    if (next > 0) {
      const internal::Spatial_cells by(next == 1 ? job.cells : job.shifted_cells);
      const std::vector<std::uint32_t> cell = internal::face_cells(mesh, by, m_options.threads);
      for (std::size_t c = 0; c < parts; ++c)
        internal::write_raw_mesh(internal::mesh_part(mesh, cell, std::uint32_t(c)),
                                 internal::part_file(folder, next, c));
      job.stage_vertices = mesh.number_of_vertices();
    } else {
      internal::write_raw_mesh(mesh, internal::job_output_file(folder));
    }
    internal::write_job_header(folder, job);
    return next > 0;
  }

  // The result of a job whose last stage is stitched: `mesh` becomes its output.
  Simplification_report result(const std::filesystem::path& folder, Mesh& mesh) const {
    mesh = internal::read_raw_mesh<Point>(internal::job_output_file(folder));
    return internal::read_job_header(folder).report;
  }

  const Simplification_options& options() const { return m_options; }

 private:
  // Whether a pass after the policy measures against the input.
  bool needs_input() const { return m_options.fit || m_options.smoothing.bounded; }

  // What a run that never holds the input whole cannot do.
  void check_streamed_options() const {
    CGAL_precondition(m_options.two_sided_bound() == 0 && !m_options.on_collapse);
    CGAL_precondition(m_options.merge_distance == 0 && m_options.min_component <= 1);
    CGAL_precondition(!m_options.smoothing.bounded);
  }

  Simplification_report streamed_report(const internal::Spilled_input<Point>& input) const {
    Simplification_report report;
    report.input_faces = input.faces();
    report.input_vertices = input.vertices();
    report.target_faces = m_options.target.of(report.input_faces);
    report.parts = input.cells().size();
    return report;
  }

  // The input parts of the cells spilled in `spills`, by cell.
  static auto parts_of(const internal::Spilled_input<Point>& input,
                       const internal::Spill_files& spills) {
    return [&input, &spills](std::size_t c) { return input.part(spills, c); };
  }

  // Whether a partitioned run keeps the mesh it cuts for its last pass: a two-sided bound is
  // certified against it, not against the stitched parts, which are within the bound of it
  // already (the errors would add up).
  bool keeps_input_as_cut() const { return m_options.two_sided_bound() > 0; }

  // Whether the fit of a partitioned run runs by cells: not under a bound, since a cell's fit
  // certifies against the input's cell alone, and a piece of the input near a cut, covered by a
  // face of the next cell, could lose its cover to a move there. A bounded fit runs whole.
  bool fits_by_cells() const { return m_options.two_sided_bound() == 0; }

  // The diagonal of the mesh's bounding box, which the bounds are fractions of.
  static double diagonal_of(const Mesh& mesh) {
    return internal::diagonal_length(CGAL::Polygon_mesh_processing::bbox(mesh));
  }

  // `options` with their bounds, fractions of the diagonal of the mesh that their certifier
  // measures (Hausdorff_input_surface), rescaled from `diagonal`, the one of the mesh cut, to
  // that of `measured`: the tolerances stay the whole run's in length.
  static Simplification_options in_lengths_of(Simplification_options options, const Mesh& measured,
                                              double diagonal) {
    const double measured_diagonal = diagonal_of(measured);
    if (!(measured_diagonal > 0)) return options;
    const double scale = diagonal / measured_diagonal;
    options.max_error *= scale;
    options.hausdorff.beta *= scale;
    return options;
  }

  // A part of a partitioned run of a mesh of that diagonal, its cut vertices locked; a bound is
  // certified against the part as cut, in the whole's lengths. The parts then keep it together:
  // a point of the input lies in some part's input, within tau of that part's output, and a point
  // of the output in some part's output, within tau of that part's input. Its progress goes to
  // `progress`, the whole run's (none in a job's task, which runs alone). A time limit counts
  // from `started`.
  internal::Policy_outcome run_on_part(Mesh& part, std::size_t target, double diagonal,
                                       internal::Part_progress* progress,
                                       std::chrono::steady_clock::time_point started) const {
    Simplification_options options = in_lengths_of(m_options, part, diagonal);
    options.progress = progress ? progress->of_part(part.number_of_faces()) : nullptr;
    return run_policy_in_time(part, target, options, nullptr, started);
  }

  // The last pass of a partitioned run, over the stitched `whole`: under a bound, certified
  // against `input_as_cut` (keeps_input_as_cut), of that diagonal. Its progress goes to
  // `progress`, the whole run's, when there is one (none in a job's task). A time limit counts
  // from `started`.
  internal::Policy_outcome run_over_stitched(Mesh& whole, std::size_t target,
                                             const std::optional<Mesh>& input_as_cut,
                                             double diagonal,
                                             const internal::Part_progress* progress,
                                             std::chrono::steady_clock::time_point started) const {
    const Mesh* input = input_as_cut ? &*input_as_cut : nullptr;
    Simplification_options options = in_lengths_of(m_options, input ? *input : whole, diagonal);
    if (progress) options.progress = progress->of_last_pass();
    return run_policy_in_time(whole, target, options, input, started);
  }

  // The policy of a partitioned run whose stitched parts become `whole` (run_parts' run_policy):
  // run_on_part on each part, then run_over_stitched, both with the whole run's progress and
  // its time limit, counted from `started`.
  auto part_or_stitched_runner(const Mesh& whole, const std::optional<Mesh>& input_as_cut,
                               double diagonal, internal::Part_progress& progress,
                               std::chrono::steady_clock::time_point started) const {
    return [this, &whole, &input_as_cut, diagonal, &progress, started](Mesh& m,
                                                                       std::size_t target) {
      return &m == &whole ? run_over_stitched(m, target, input_as_cut, diagonal, &progress, started)
                          : run_on_part(m, target, diagonal, &progress, started);
    };
  }

  static double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // The report's counts of the input and passes 1-2 run on `mesh`: the repairs before the run;
  // the target stays the one asked of the input.
  Simplification_report run_repairs(Mesh& mesh) const {
    Simplification_report report;
    report.input_faces = mesh.number_of_faces();
    report.input_vertices = mesh.number_of_vertices();
    report.target_faces = m_options.target.of(report.input_faces);
    report.bound = m_options.two_sided_bound();
    if (m_options.merge_distance > 0)
      timed(report, Simplification_pass::merge, [&] {
        report.merged = Border_pair_contraction(m_options.merge_distance)(mesh);
        if (report.merged.stitched_edges > 0) mesh.collect_garbage();
      });
    if (m_options.min_component > 1)
      timed(report, Simplification_pass::components, [&] {
        report.dropped_before = drop_components_smaller_than(mesh, m_options.min_component);
      });
    return report;
  }

  // A large mesh is cut into cells, for the policy and the fit to run on every core; none when
  // it runs whole.
  std::optional<internal::Spatial_cells> cells_of(const Mesh& mesh) const {
    const std::size_t count = m_options.cell_count(mesh.number_of_faces());
    if (count <= 1) return std::nullopt;
    return internal::Spatial_cells(internal::face_centroids(mesh, m_options.threads), count,
                                   m_options.threads);
  }

  template <class Pass>
  void timed(Simplification_report& report, Simplification_pass pass, const Pass& run) const {
    const auto start = std::chrono::steady_clock::now();
    run();
    report.pass_seconds[std::size_t(pass)] = seconds_since(start);
    if (pass != Simplification_pass::simplification && m_options.pass_done)
      m_options.pass_done(pass);
  }

  // After the policy's pass: the garbage collected, then passes 4-6 unless the run was
  // interrupted, fit_by(options) running the fit, and the output's counts.
  template <class Fit>
  void finish(Simplification_report& report, Mesh& mesh, const Mesh& input,
              const Fit& fit_by) const {
    mesh.collect_garbage();
    if (m_options.pass_done) m_options.pass_done(Simplification_pass::simplification);
    if (m_options.drop_small_pieces && report.stop_reason == Stop_reason::no_collapse_left)
      timed(report, Simplification_pass::pieces, [&] {
        report.dropped_after = drop_smallest_components_until(mesh, report.target_faces);
      });
    if (m_options.smoothing.iterations > 0 && !interrupted(report))
      timed(report, Simplification_pass::smoothing,
            [&] { report.smoothing_refused_moves = smooth(mesh, input, report.bound); });
    if (m_options.fit && !interrupted(report))
      timed(report, Simplification_pass::fit, [&] {
        report.fit = fit_by(fit_options(report));
        report.fitted = true;
      });
    report.output_faces = mesh.number_of_faces();
    report.output_vertices = mesh.number_of_vertices();
  }

  Two_sided_fit_options fit_options(const Simplification_report& report) const {
    Two_sided_fit_options fit = m_options.fit_options;
    fit.max_normal_angle_deg = m_options.max_normal_angle_deg;
    fit.tolerance = report.bound;
    fit.threads = m_options.threads;
    return fit;
  }

  // Those of fit stage 1 or 2 of a job: a half of the fit by cells.
  Two_sided_fit_options fit_stage_options(const Simplification_report& report, int stage) const {
    Two_sided_fit_options fit = fit_options(report);
    fit.rounds = internal::fit_half_rounds(fit.rounds, stage - 1);
    return fit;
  }

  // Asks the callback between passes; an interrupted run reports it and skips the rest.
  bool interrupted(Simplification_report& report) const {
    if (report.stop_reason == Stop_reason::interrupted) return true;
    if (!m_options.interrupted || !m_options.interrupted()) return false;
    report.stop_reason = Stop_reason::interrupted;
    return true;
  }

  // run_policy with what is left of options' time limit, which counts from `started`: the
  // parts and the last pass of a partitioned run share one deadline. When none is left, `mesh`
  // stays as it is: even a run stopped at once would first cost every edge.
  static internal::Policy_outcome run_policy_in_time(
      Mesh& mesh, std::size_t target, Simplification_options options, const Mesh* reference,
      std::chrono::steady_clock::time_point started) {
    if (options.time_limit_seconds > 0) {
      options.time_limit_seconds -= seconds_since(started);
      if (!(options.time_limit_seconds > 0))
        return {mesh.number_of_faces() <= target ? Stop_reason::target_reached
                                                 : Stop_reason::time_limit,
                Corner_attributes<Point>(mesh).any_corner_values()};
    }
    return run_policy(mesh, target, options, reference);
  }

  // `reference`: the input a bound is certified against, when it is not `mesh` as it is now.
  // With a prepass, fast first takes `mesh` down to options.prepass_faces(target) faces; the
  // progress of both is then measured from where `mesh` started.
  static internal::Policy_outcome run_policy(Mesh& mesh, std::size_t target,
                                             const Simplification_options& options,
                                             const Mesh* reference) {
    const std::size_t coarse = options.prepass_faces(target);
    if (coarse == 0 || mesh.number_of_faces() <= coarse)
      return run_policy_alone(mesh, target, options, reference);
    Simplification_options from_start = options;
    if (options.progress)
      from_start.progress = [&options, start = mesh.number_of_faces(), target](
                                Simplification_pass pass, double done, std::size_t faces) {
        if (pass == Simplification_pass::simplification)
          done = internal::simplification_done(start, target, faces);
        options.progress(pass, done, faces);
      };
    internal::run_fast<Point>(mesh, coarse, from_start, nullptr);
    if (options.interrupted && options.interrupted())
      return internal::flat_array_outcome(mesh, false, true);
    return run_policy_alone(mesh, target, from_start, reference);
  }

  static internal::Policy_outcome run_policy_alone(Mesh& mesh, std::size_t target,
                                                   const Simplification_options& options,
                                                   const Mesh* reference) {
    switch (options.policy) {
      case Simplification_policy::gh:
        return internal::run_gh(mesh, target, options, reference);
      case Simplification_policy::gh_probabilistic:
        return internal::run_gh_probabilistic(mesh, target, options, reference);
      case Simplification_policy::lt:
        return internal::run_lt(mesh, target, options, reference);
      case Simplification_policy::classic:
        return internal::run_classic(mesh, target, options, reference);
      case Simplification_policy::curvature:
        return internal::run_curvature(mesh, target, options, reference);
      case Simplification_policy::fusion:
        return internal::run_fusion(mesh, target, options, reference);
      case Simplification_policy::fast:
        return internal::run_fast(mesh, target, options, reference);
      case Simplification_policy::flat_lt:
        return internal::run_flat_lt(mesh, target, options, reference);
      case Simplification_policy::hausdorff:
        return internal::run_hausdorff(mesh, target, options, reference);
      case Simplification_policy::attributes:
        return internal::run_attributes(mesh, target, options, reference);
    }
    CGAL_error_msg("unknown Simplification_policy");
    return {};
  }

  // Returns the moves a bounded smoothing refused.
  std::size_t smooth(Mesh& mesh, const Mesh& input, double bound) const {
    const Smoothing_options& s = m_options.smoothing;
    const Laplacian_smoother<Mesh> smoother(s.rate, s.weights, s.method);
    if (!s.bounded) {
      smoother.smooth(mesh, s.iterations);
      return 0;
    }
    const Hausdorff_move_guard<Mesh> guard(input, mesh, bound);
    return smoother.smooth(mesh, s.iterations, guard);
  }

  Simplification_options m_options;
};

// Simplification_pipeline<Point>(options).run(mesh).
template <class Point>
Simplification_report simplify(CGAL::Surface_mesh<Point>& mesh,
                               const Simplification_options& options = {}) {
  return Simplification_pipeline<Point>(options).run(mesh);
}

// Any other mesh type is refused here, at compile time: the pipeline keeps its state in a
// Surface_mesh's property maps and rebuilds the mesh between passes.
template <class TriangleMesh>
Simplification_report simplify(TriangleMesh&, const Simplification_options& = {}) {
  static_assert(internal::Is_surface_mesh<TriangleMesh>::value,
                "cgal_policies::simplify runs on a CGAL::Surface_mesh only: copy the mesh into "
                "one (CGAL::copy_face_graph), or run a policy of the library in "
                "SMS::edge_collapse, which takes any mesh type");
  return {};
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_SIMPLIFICATION_PIPELINE_H
