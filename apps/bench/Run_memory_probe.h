// The peak resident memory of one run inside a long benchmark process: the kernel's peak (VmHWM)
// is reset before the run, so runs do not inherit the peaks of earlier, larger ones.
#ifndef CGAL_POLICIES_APPS_BENCH_RUN_MEMORY_PROBE_H
#define CGAL_POLICIES_APPS_BENCH_RUN_MEMORY_PROBE_H

namespace apps {

class Run_memory_probe {
 public:
  // Returns freed heap memory to the system, notes the resident size and resets the peak.
  Run_memory_probe();

  // The peak resident size since construction (since the process started when the kernel refused
  // the reset; see resets()).
  double peak_mib() const;
  // The peak minus the resident size at construction: what the run added.
  double added_mib() const { return peak_mib() - m_start_mib; }
  bool resets() const { return m_reset; }

 private:
  double m_start_mib;
  bool m_reset;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_RUN_MEMORY_PROBE_H
