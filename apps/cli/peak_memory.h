// The process's peak resident memory, for the reports of docs/evaluation.md.
#ifndef CGAL_POLICIES_APPS_CLI_PEAK_MEMORY_H
#define CGAL_POLICIES_APPS_CLI_PEAK_MEMORY_H

#include <sys/resource.h>

namespace apps {

inline double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_PEAK_MEMORY_H
