// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#ifndef CGAL_POLICIES_APPS_CLI_PROGRESS_BAR_H
#define CGAL_POLICIES_APPS_CLI_PROGRESS_BAR_H

#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>

namespace apps {

class Progress_bar {
 public:
  // Progress runs from `start` faces down to `target` faces.
  Progress_bar(std::size_t start, std::size_t target, bool enabled)
      : m_start(start), m_target(target), m_enabled(enabled && ::isatty(STDERR_FILENO)) {}
  ~Progress_bar() {
    if (m_drawn) std::fputc('\n', stderr);
  }
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  void update(std::size_t faces) {
    if (!m_enabled || m_start <= m_target) return;
    const double done = std::clamp(
        double(m_start - std::min(faces, m_start)) / double(m_start - m_target), 0.0, 1.0);
    const int width = 40, filled = int(done * width);
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%  %zu faces", filled,
                 "========================================", width - filled, "", int(done * 100),
                 faces);
    std::fflush(stderr);
    m_drawn = true;
  }

 private:
  std::size_t m_start, m_target;
  bool m_enabled;
  bool m_drawn = false;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_PROGRESS_BAR_H
