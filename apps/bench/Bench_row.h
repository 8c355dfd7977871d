// One row of simplify_bench's tables: a pipeline of this suite (a policy, and "P+fit" when it is
// followed by the fitting pass) or a peer a user would pick instead (bench_peers.h), each run the
// same way on a copy of the mesh.
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_ROW_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_ROW_H

#include "app_types.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Stop_reason.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace apps {

// What a row asks of a run.
struct Bench_settings {
  std::size_t target_faces = 0;
  double time_limit_seconds = 0;  // the edge-collapse runs stop where they are after it; 0: none
  Option_values options;          // the option values given on the command line, by name
  std::size_t threads = 0;        // cores of a pipeline row's cells, 0: all (the peers use one)
  double prepass_factor = 0;      // Simplification_options::prepass_factor of the rows that can
};

// What one run did.
struct Bench_run {
  double seconds = 0;      // the simplification alone
  double fit_seconds = 0;  // the fitting pass of a "P+fit" row, else 0
  std::size_t fit_flips = 0;
  cgal_policies::Stop_reason stop_reason = cgal_policies::Stop_reason::no_collapse_left;
  bool attributes_carried = false;
  // Out of core, the input as the run counted it: its faces and its points once equal ones are
  // joined; the bench never holds it whole to count them.
  std::size_t input_faces = 0, input_vertices = 0;
};

struct Bench_row {
  std::string name;
  std::string summary;
  std::vector<Policy_option> options;  // what it reads of Bench_settings::options
  std::function<Bench_run(Mesh&, const Bench_settings&)> run;
  // The run on a file read in passes (binary PLY or OBJ) into the result, never whole; empty for
  // a row that needs the whole input (the peers, a bound).
  std::function<Bench_run(const std::string& input, Mesh& result, const Bench_settings&)>
      run_out_of_core = {};
  bool uses_threads = false;  // runs once per thread count of the plan; else once
};

// The row of this suite's pipeline with `policy` alone, or followed by the fitting pass.
Bench_row pipeline_row(const Policy_entry& policy, bool fit);

// P for a "P+fit" name; nothing for any other name.
std::optional<std::string> fitted_base(const std::string& name);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_ROW_H
