// What simplify_bench writes: a CSV and a JSON file of every run, and a Markdown report with one
// table per mesh and a summary naming, per mesh, the most accurate and the fastest policy.
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_REPORT_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_REPORT_H

#include "bench_runner.h"

#include <string>
#include <vector>

namespace apps {

std::string runs_csv(const std::vector<Run_record>& records);

// {"command": ..., "runs": [{...}, ...]}, one run per line.
std::string runs_json(const std::vector<Run_record>& records, const std::string& command);

// The Markdown report: the command, one table per mesh (in the order of the runs), the summary.
std::string markdown_report(const std::vector<Run_record>& records, const std::string& command,
                            const Bench_plan& plan);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_REPORT_H
