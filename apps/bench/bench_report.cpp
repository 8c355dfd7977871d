#include "bench_report.h"

#include "Bench_row.h"
#include "cli/Json_object.h"

#include <CGAL/version.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <type_traits>

namespace apps {
namespace {

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

template <typename Value>
std::string csv_cell(const Value& value) {
  if constexpr (std::is_same_v<Value, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_floating_point_v<Value>) {
    return std::isfinite(value) ? Json_object::format_number(value) : "";
  } else {
    return std::to_string(value);
  }
}

template <typename Value>
std::string csv_cell(const std::optional<Value>& value) {
  return value ? csv_cell(*value) : "";
}

template <typename T>
struct is_optional : std::false_type {};
template <typename T>
struct is_optional<std::optional<T>> : std::true_type {};

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string percent(double fraction) { return format("%.3g", 100 * fraction); }

std::string seconds_cell(double s) { return format(s < 1 ? "%.4f" : "%.2f", s); }

std::string validity_cell(const Mesh_validity& v) {
  if (!v.valid) return "INVALID";
  std::string text = v.closed ? "closed" : std::to_string(v.boundary_edges) + " border edges";
  if (v.non_manifold_vertices)
    text += ", " + std::to_string(v.non_manifold_vertices) + " non-manifold vertices";
  if (v.degenerate_faces) text += ", " + std::to_string(v.degenerate_faces) + " degenerate";
  return text;
}

std::string target_cell(const Run_record& r) {
  return (r.label.empty() ? r.target : r.label + ", " + r.target) + " → " +
         std::to_string(r.target_faces);
}

std::string mean_error_cell(const Run_record& r, double d) {
  return r.error_measured
             ? percent(r.error.mean_a_to_b / d) + " / " + percent(r.error.mean_b_to_a / d)
             : "not measured";
}

bool reached(const Run_record& r) { return r.output_faces <= r.target_faces; }
bool timed_out(const Run_record& r) {
  return r.stop_reason == to_string(cgal_policies::Stop_reason::time_limit);
}

std::string faces_cell(const Run_record& r) {
  return std::to_string(r.output_faces) + (timed_out(r) ? "†" : reached(r) ? "" : "*");
}

// Consecutive runs of one mesh, in the order they ran.
std::vector<std::vector<const Run_record*>> group_by_mesh(const std::vector<Run_record>& records) {
  std::vector<std::vector<const Run_record*>> groups;
  for (const Run_record& r : records) {
    if (groups.empty() || groups.back().front()->mesh != r.mesh) groups.emplace_back();
    groups.back().push_back(&r);
  }
  return groups;
}

// The plan's mesh of a run, by file name.
const Bench_mesh* find_mesh(const Bench_plan& plan, const std::string& name) {
  const auto it = std::find_if(plan.meshes.begin(), plan.meshes.end(), [&](const Bench_mesh& m) {
    return std::filesystem::path(m.path).filename().string() == name;
  });
  return it == plan.meshes.end() ? nullptr : &*it;
}

std::string mesh_table(const std::vector<const Run_record*>& runs, const Bench_plan& plan) {
  const Run_record& first = *runs.front();
  std::string md = "## " + first.mesh + " (" + std::to_string(first.input_faces) + " faces, " +
                   std::to_string(first.input_vertices) + " vertices)\n\n";
  md +=
      "| target → faces | policy | faces | seconds | fit s | × gh | faces removed/s | peak MiB "
      "(+run) | Hausdorff % | mean % (→ / ←) | validity |\n";
  md += "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  bool short_of_target = false, out_of_time = false;
  for (const Run_record* r : runs) {
    short_of_target |= !reached(*r) && !timed_out(*r);
    out_of_time |= timed_out(*r);
    const double d = r->error.bbox_diagonal > 0 ? r->error.bbox_diagonal : 1;
    md += "| " + target_cell(*r) + " | " + run_label(*r) + " | " + faces_cell(*r) + " | " +
          seconds_cell(r->seconds) + " | " +
          (fitted_base(r->policy) ? seconds_cell(r->fit_seconds) : "–") + " | " +
          (std::isfinite(r->time_vs_gh) ? format("%.3g", r->time_vs_gh) : "–") + " | " +
          format("%.0f", r->faces_removed_per_second) + " | " + format("%.0f", r->peak_memory_mib) +
          " (+" + format("%.0f", r->memory_added_mib) + ") | " +
          (r->error_measured ? percent(r->error.hausdorff / d) : "–") + " | " +
          mean_error_cell(*r, d) + " | " + validity_cell(r->validity) + " |\n";
  }
  if (short_of_target) md += "\n\\* stopped short of the target: no collapse was left.\n";
  if (out_of_time)
    md += "\n† stopped at the time limit (`--time-limit`), after one run; its time is the limit.\n";
  const Bench_mesh* mesh = find_mesh(plan, first.mesh);
  if (mesh && !mesh->left_out.empty()) md += "\nLeft out: " + mesh->left_out + ".\n";
  return md + "\n";
}

// Per mesh, among the runs (policy, threads) that reached every target: the lowest mean error
// (both directions averaged, then averaged over the mesh's targets; measured runs only) and the
// lowest geometric mean of the time relative to gh (ratios average geometrically), or of the
// seconds on a mesh without gh.
std::string summary(const std::vector<std::vector<const Run_record*>>& groups) {
  std::string md =
      "## Summary\n\nPer mesh, among the runs that reached every target: the mean error "
      "averaged over the mesh's targets, the time ratio to gh (without gh: the seconds) averaged "
      "geometrically.\n\n";
  for (const auto& runs : groups) {
    const bool with_gh = std::all_of(
        runs.begin(), runs.end(), [](const Run_record* r) { return std::isfinite(r->time_vs_gh); });
    std::vector<std::string> labels;
    for (const Run_record* r : runs)
      if (std::find(labels.begin(), labels.end(), run_label(*r)) == labels.end())
        labels.push_back(run_label(*r));
    std::string most_accurate, fastest;
    double best_error = INFINITY, best_time = INFINITY;
    for (const std::string& label : labels) {
      double error_sum = 0, log_time = 0;
      std::size_t n = 0;
      bool eligible = true, measured = true;
      for (const Run_record* r : runs) {
        if (run_label(*r) != label) continue;
        eligible &= reached(*r);
        measured &= r->error_measured;
        error_sum += mean_error_rel(*r);
        log_time += std::log(std::max(with_gh ? r->time_vs_gh : r->seconds, 1e-12));
        ++n;
      }
      if (!eligible) continue;
      const double error = error_sum / double(n), time = std::exp(log_time / double(n));
      if (measured && error < best_error) {
        best_error = error;
        most_accurate = label;
      }
      if (time < best_time) {
        best_time = time;
        fastest = label;
      }
    }
    md += "- " + runs.front()->mesh + ": ";
    if (fastest.empty()) {
      md += "no policy reached every target.\n";
      continue;
    }
    if (!most_accurate.empty())
      md += "lowest mean error: " + most_accurate + " (" + percent(best_error) +
            "% of the diagonal); ";
    md += "fastest: " + fastest + " (" + format("%.3g", best_time) + (with_gh ? " × gh" : " s") +
          ").\n";
  }
  return md;
}

// Per run on more than one thread beside the same row's run on one: the time of the policy's
// pass and the fit (pipeline_seconds) on one thread over its own (add_scaling).
std::string scaling_table(const std::vector<Run_record>& records) {
  std::string rows;
  for (const Run_record& r : records) {
    if (!r.scaling) continue;
    rows += "| " + r.mesh + " | " + target_cell(r) + " | " + run_label(r) + " | " +
            seconds_cell(*r.scaling * pipeline_seconds(r)) + " | " +
            seconds_cell(pipeline_seconds(r)) + " | " + format("%.2f", *r.scaling) + " |\n";
  }
  if (rows.empty()) return "";
  return "## Threads\n\nThe policy's pass and the fit, in seconds, on one thread and on the "
         "run's; the scaling is the first over the second.\n\n"
         "| mesh | target → faces | run | s on 1 thread | s | scaling |\n"
         "|---|---|---|--:|--:|--:|\n" +
         rows + "\n";
}

// With --attributes: what each run did with the corner attributes and, when it carried them, their
// error (docs/evaluation.md).
std::string attribute_table(const std::vector<Run_record>& records) {
  const auto cell = [](const auto& value, double scale, const char* pattern) {
    return value ? format(pattern, scale * double(*value)) : std::string("–");
  };
  std::string rows;
  for (const Run_record& r : records) {
    if (r.attributes.empty()) continue;
    const Attribute_error& e = r.attribute_error;
    rows += "| " + r.mesh + " | " + target_cell(r) + " | " + r.policy + " | " + r.attributes +
            " | " + cell(e.uv_mean_rel, 100, "%.3g") + " | " + cell(e.uv_max_rel, 100, "%.3g") +
            " | " + cell(e.normal_angle_mean_deg, 1, "%.3g") + " | " +
            cell(e.color_mean, 100, "%.3g") + " | " + cell(e.seam_loops_a, 1, "%.0f") + " / " +
            cell(e.seam_loops_b, 1, "%.0f") + " | " + cell(e.flipped_uv_faces, 1, "%.0f") + " | " +
            percent(mean_error_rel(r)) + " |\n";
  }
  if (rows.empty()) return "";
  return "## Corner attributes\n\nTexture distance at corresponding points in % of the input's "
         "texture extent, normal angle in degrees, colour distance in % of full intensity, seam "
         "loops in / out, texture triangles turned over, and the geometric mean error (both "
         "directions, % of the diagonal).\n\n"
         "| mesh | target → faces | policy | attributes | uv mean % | uv max % | normal mean ° | "
         "colour mean % | seam loops | flipped | mean % |\n"
         "|---|---|---|---|--:|--:|--:|--:|--:|--:|--:|\n" +
         rows + "\n";
}

// Per fitted run "P+fit": its mean error and Hausdorff distance against P's and lt's on the same
// mesh and target, and its fitting pass's time against lt's simplification (docs/fitting.md).
std::string fitting_table(const std::vector<Run_record>& records) {
  const auto find = [&](const Run_record& like, const std::string& policy) -> const Run_record* {
    for (const Run_record& r : records)
      if (r.mesh == like.mesh && r.target == like.target && r.label == like.label &&
          r.threads == like.threads && r.input_read == like.input_read && r.policy == policy)
        return &r;
    return nullptr;
  };
  const auto ratio = [](double a, double b) { return b > 0 ? format("%.3f", a / b) : "–"; };
  std::string rows;
  for (const Run_record& r : records) {
    const std::optional<std::string> fitted = fitted_base(r.policy);
    if (!fitted) continue;
    const Run_record* base = find(r, *fitted);
    const Run_record* lt = find(r, "lt");
    rows += "| " + r.mesh + " | " + target_cell(r) + " | " + run_label(r) + " | " + faces_cell(r) +
            " | " + seconds_cell(r.fit_seconds) + " | " + std::to_string(r.fit_flips) + " | " +
            (base ? ratio(mean_error_rel(r), mean_error_rel(*base)) : "–") + " | " +
            (lt ? ratio(mean_error_rel(r), mean_error_rel(*lt)) : "–") + " | " +
            (lt ? ratio(r.error.hausdorff, lt->error.hausdorff) : "–") + " | " +
            (lt ? ratio(r.fit_seconds, lt->seconds) : "–") + " | " + validity_cell(r.validity) +
            " |\n";
  }
  if (rows.empty()) return "";
  return "## Fitting pass\n\nP+fit: P, then the two-sided fit (docs/fitting.md). Mean: both "
         "directions averaged, over P's and over lt's at the same target; Hausdorff over lt's; "
         "fit time over lt's simplification time.\n\n"
         "| mesh | target → faces | run | faces | fit s | flips | mean / P | mean / lt | "
         "Hausdorff / lt | fit s / lt s | output |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n" +
         rows + "\n";
}

}  // namespace

std::string runs_csv(const std::vector<Run_record>& records) {
  std::string header, body;
  if (!records.empty())
    for_each_field(records.front(), [&](const char* name, const auto&) {
      header += (header.empty() ? "" : ",") + std::string(name);
    });
  for (const Run_record& r : records) {
    std::string line;
    bool first = true;
    for_each_field(r, [&](const char*, const auto& value) {
      line += (first ? "" : ",") + csv_cell(value);
      first = false;
    });
    body += line + "\n";
  }
  return header + "\n" + body;
}

std::string runs_json(const std::vector<Run_record>& records, const std::string& command) {
  Json_object head;
  head.add("command", command);
  std::string text = head.str();
  text.pop_back();  // the closing brace: the runs follow
  text += ", \"runs\": [";
  for (std::size_t i = 0; i < records.size(); ++i) {
    Json_object run;
    for_each_field(records[i], [&](const char* name, const auto& value) {
      if constexpr (is_optional<std::decay_t<decltype(value)>>::value) {
        if (value) run.add(name, *value);
      } else {
        run.add(name, value);
      }
    });
    text += (i ? ",\n  " : "\n  ") + run.str();
  }
  return text + "\n]}\n";
}

std::string markdown_report(const std::vector<Run_record>& records, const std::string& command,
                            const Bench_plan& plan) {
  std::string md = "# simplify_bench\n\n`" + command + "`\n\nBuilt with CGAL " +
                   std::string(CGAL_VERSION_STR) +
                   ": gh, gh-prob and lt are its policies, and every row of this suite but fast "
                   "and flat-lt runs in its edge collapse.\n\n";
  md += "Seconds: the simplification alone, the fastest of " + std::to_string(plan.repetitions) +
        " repetition(s); × gh: that time over gh's on the same mesh and target. Errors: "
        "two-sided, " +
        std::to_string(plan.samples) +
        " face samples per direction, in % of the input's bounding-box diagonal; mean → is "
        "input to result, ← result to input. Peak MiB: the process's resident peak during the "
        "run (+ what the run added).\n\n";
  if (plan.prepass_factor > 0)
    md += "Every pipeline row without a bound ran fast first, down to " +
          Json_object::format_number(plan.prepass_factor) + " times its target (--prepass).\n\n";
  if (std::any_of(records.begin(), records.end(),
                  [](const Run_record& r) { return !r.error_measured; }))
    md +=
        "Out of core, the seconds include the reading, and the error is not measured: the "
        "measure holds the input whole.\n\n";
  const auto groups = group_by_mesh(records);
  for (const auto& runs : groups) md += mesh_table(runs, plan);
  return md + fitting_table(records) + scaling_table(records) + attribute_table(records) +
         summary(groups);
}

}  // namespace apps
