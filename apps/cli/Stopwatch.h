// Wall time on the steady clock since construction: how the apps time a run, a read or a write.
#ifndef CGAL_POLICIES_APPS_CLI_STOPWATCH_H
#define CGAL_POLICIES_APPS_CLI_STOPWATCH_H

#include <chrono>

namespace apps {

class Stopwatch {
 public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - m_start).count(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point m_start = Clock::now();
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_STOPWATCH_H
