// The cases simplify_bench runs: meshes with their targets, as named presets (docs/evaluation.md
// and the papers' experiments) or given on the command line.
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_PRESETS_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_PRESETS_H

#include <cstddef>
#include <string>
#include <vector>

namespace apps {

// A target is a fraction of the input's faces or a face count (exactly one of the two is set).
struct Bench_target {
  double ratio = 0;
  std::size_t faces = 0;
  std::string label;  // where the case comes from, e.g. "[Zhang09]: 4940 faces"; may be empty
};

struct Bench_mesh {
  std::string path;
  std::vector<Bench_target> targets;
  // The rows run on this mesh, by name; empty: every row of the plan.
  std::vector<std::string> rows = {};
  // Never read whole: the rows run on the file read in passes, and the error is not measured.
  bool out_of_core = false;
  // The rows left out and why, for the report; may be empty.
  std::string left_out = {};
};

struct Bench_preset {
  std::string name;
  std::string description;
  std::vector<Bench_mesh> meshes;  // paths relative to the data folder
  std::size_t repetitions;
  std::size_t samples;  // face samples per direction for the error measure
  // Per run, so that a policy far slower than the others cannot hold the whole matrix up.
  double time_limit_seconds;
  // Policies whose output the preset also fits to the input ("P+fit" rows, docs/fitting.md).
  std::vector<std::string> fitted = {};
  // Each of this suite's rows runs once per thread count (0: every core); the peers run once.
  std::vector<std::size_t> threads = {0};
  // For meshes made, not shipped: the script that makes them into a folder (its argument), which
  // is the preset's data folder. Empty: the meshes are in data/.
  std::string made_by = {};
};

// The presets by name: "standard", "papers", "quick", "scale".
const std::vector<Bench_preset>& bench_presets();

// The preset of that name, or nullptr.
const Bench_preset* find_bench_preset(const std::string& name);

// Whether `mesh` runs the row of that name (Bench_mesh::rows).
bool mesh_runs_row(const Bench_mesh& mesh, const std::string& row);

// The face count a target asks of a mesh with `input_faces` faces, rounded as simplify rounds it.
std::size_t target_face_count(const Bench_target& target, std::size_t input_faces);

// "10%" or "4940 faces", for tables and progress lines.
std::string describe_target(const Bench_target& target);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_PRESETS_H
