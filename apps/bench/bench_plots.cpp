#include "bench_plots.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace apps {
namespace {

// For a file name: "bunny.obj" -> "bunny_obj".
std::string file_stem(const std::string& mesh) {
  std::string stem = mesh;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  return stem;
}

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// gnuplot strings in single quotes double their single quotes.
std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

// The data of one mesh: one block per run label (gnuplot's "index"), rows sorted by face count.
std::vector<std::string> write_mesh_data(const std::vector<const Run_record*>& runs,
                                         const std::string& path) {
  std::vector<std::string> policies;
  for (const Run_record* r : runs)
    if (std::find(policies.begin(), policies.end(), run_label(*r)) == policies.end())
      policies.push_back(run_label(*r));
  std::ofstream out(path);
  for (const std::string& policy : policies) {
    std::vector<const Run_record*> rows;
    for (const Run_record* r : runs)
      if (run_label(*r) == policy) rows.push_back(r);
    std::sort(rows.begin(), rows.end(), [](const Run_record* a, const Run_record* b) {
      return a->output_faces < b->output_faces;
    });
    out << "# " << policy << "\n# faces mean_rel_percent hausdorff_rel_percent time_vs_gh\n";
    for (const Run_record* r : rows)
      out << r->output_faces << ' ' << 100 * mean_error_rel(*r) << ' '
          << 100 * r->error.hausdorff / r->error.bbox_diagonal << ' ' << r->time_vs_gh << '\n';
    out << "\n\n";
  }
  return policies;
}

std::string plot_command(const std::string& data, const std::vector<std::string>& policies,
                         int column) {
  std::string command = "plot";
  for (std::size_t i = 0; i < policies.size(); ++i)
    command += std::string(i ? "," : "") + " \\\n  " + gnuplot_quote(data) + " index " +
               std::to_string(i) + " using 1:" + std::to_string(column) +
               " with linespoints title " + gnuplot_quote(policies[i]);
  return command + "\n";
}

}  // namespace

bool draw_plots(const std::vector<Run_record>& records, const std::string& folder) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    std::fprintf(stderr, "simplify_bench: gnuplot is not installed: no plots\n");
    return false;
  }
  std::string script =
      "set terminal pngcairo noenhanced size 1200,520 font ',10'\n"
      "set key outside right\nset grid\nset logscale xy\nset xlabel 'faces'\n";
  std::vector<std::string> meshes;
  for (const Run_record& r : records)
    if (std::find(meshes.begin(), meshes.end(), r.mesh) == meshes.end()) meshes.push_back(r.mesh);
  bool any = false;
  for (const std::string& mesh : meshes) {
    std::vector<const Run_record*> runs;
    for (const Run_record& r : records)
      if (r.mesh == mesh) runs.push_back(&r);
    // The plots are the error and the time over gh's.
    if (std::any_of(runs.begin(), runs.end(), [](const Run_record* r) {
          return !r->error_measured || !std::isfinite(r->time_vs_gh);
        })) {
      std::fprintf(stderr, "simplify_bench: no plots of %s: without gh or the error\n",
                   mesh.c_str());
      continue;
    }
    any = true;
    const std::string stem = file_stem(mesh), data = stem + ".dat";
    const std::vector<std::string> policies = write_mesh_data(runs, folder + "/" + data);
    script += "set output " + gnuplot_quote(stem + "_error.png") + "\n" +
              "set multiplot layout 1,2 title " + gnuplot_quote(mesh + ": two-sided error") +
              "\nset ylabel 'mean error, % of the diagonal'\n" + plot_command(data, policies, 2) +
              "set ylabel 'Hausdorff error, % of the diagonal'\n" +
              plot_command(data, policies, 3) + "unset multiplot\n";
    script += "set output " + gnuplot_quote(stem + "_time.png") + "\nset title " +
              gnuplot_quote(mesh + ": simplification time relative to gh") +
              "\nset ylabel 'time / time of gh'\n" + plot_command(data, policies, 4) +
              "unset title\n";
  }
  if (!any) return false;
  std::ofstream(folder + "/plots.gp") << script;
  const std::string command =
      "cd " + shell_quote(folder) + " && gnuplot plots.gp 2> gnuplot_errors.txt";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "simplify_bench: gnuplot failed: see %s/gnuplot_errors.txt\n",
                 folder.c_str());
    return false;
  }
  return true;
}

}  // namespace apps
