// The benchmark's plots, drawn by gnuplot from a generated script: per mesh, the error against the
// face count with one curve per policy, and the time relative to gh against the face count.
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_PLOTS_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_PLOTS_H

#include "bench_runner.h"

#include <string>
#include <vector>

namespace apps {

// Writes the data and the script under `folder` and runs gnuplot there, giving
// <mesh>_error.png and <mesh>_time.png per mesh whose runs all have their error and a time over
// gh's (not out of core, not without gh). Returns false, having said why on stderr, when gnuplot
// is missing or fails or no mesh has plots; the benchmark goes on without plots.
bool draw_plots(const std::vector<Run_record>& records, const std::string& folder);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_PLOTS_H
