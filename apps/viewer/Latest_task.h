// Runs jobs on one background thread where only the latest request matters: a job submitted while
// another runs replaces any job still waiting, and only the latest job's result is handed back.
// The viewer's window stays responsive while a policy records or an error is measured.
#ifndef CGAL_POLICIES_APPS_VIEWER_LATEST_TASK_H
#define CGAL_POLICIES_APPS_VIEWER_LATEST_TASK_H

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace apps {

template <typename Result>
class Latest_task {
 public:
  Latest_task() : m_thread([this] { work(); }) {}
  ~Latest_task() {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_quit = true;
      m_job = nullptr;
    }
    m_wake.notify_one();
    m_thread.join();  // a running job finishes first: policies cannot be interrupted
  }
  Latest_task(const Latest_task&) = delete;
  Latest_task& operator=(const Latest_task&) = delete;

  void submit(std::function<Result()> job) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_job = std::move(job);
      ++m_submitted;
      m_result.reset();
    }
    m_wake.notify_one();
  }

  // The latest job's result, once; rethrows what that job threw.
  std::optional<Result> take() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
    return std::exchange(m_result, std::nullopt);
  }

  // True until the latest job has finished.
  bool busy() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_finished != m_submitted;
  }

 private:
  void work() {
    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
      m_wake.wait(lock, [this] { return m_quit || m_job; });
      if (m_quit) return;
      std::function<Result()> job = std::exchange(m_job, nullptr);
      const unsigned long long ticket = m_submitted;
      lock.unlock();
      std::optional<Result> result;
      std::exception_ptr error;
      try {
        result = job();
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (ticket != m_submitted) continue;  // superseded while it ran
      m_finished = ticket;
      m_result = std::move(result);
      m_error = error;
    }
  }

  mutable std::mutex m_mutex;
  std::condition_variable m_wake;
  std::function<Result()> m_job;
  std::optional<Result> m_result;
  std::exception_ptr m_error;
  unsigned long long m_submitted = 0, m_finished = 0;
  bool m_quit = false;
  std::thread m_thread;  // last: starts once the members above exist
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_LATEST_TASK_H
