#include "Run_memory_probe.h"

#include <malloc.h>

#include <fstream>
#include <string>

namespace apps {
namespace {

// A "Vm...:  1234 kB" line of /proc/self/status, in MiB; 0 when absent.
double status_mib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1)) / 1024.0;
  return 0;
}

}  // namespace

Run_memory_probe::Run_memory_probe() {
  malloc_trim(0);
  m_start_mib = status_mib("VmRSS");
  std::ofstream clear_refs("/proc/self/clear_refs");
  m_reset = bool(clear_refs << "5" << std::flush);  // 5: reset the peak resident size (Linux 4.0)
}

double Run_memory_probe::peak_mib() const { return status_mib("VmHWM"); }

}  // namespace apps
