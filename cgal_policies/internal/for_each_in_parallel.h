// Runs body(i) for every i < n, each on its own, on up to `threads` cores (0: all of them): with
// TBB when the build links it (CGAL_POLICIES_WITH_TBB), else on std::threads that take the next i
// in turn. A body writes only what belongs to its i, so the result does not depend on the schedule.
// The first exception a body throws is thrown again once every thread has stopped.
#ifndef CGAL_POLICIES_INTERNAL_FOR_EACH_IN_PARALLEL_H
#define CGAL_POLICIES_INTERNAL_FOR_EACH_IN_PARALLEL_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <numeric>
#include <thread>
#include <vector>

#ifdef CGAL_POLICIES_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#else
#include <exception>
#include <mutex>
#endif

namespace cgal_policies {
namespace internal {

// The cores a run of `threads` (0: all of them) uses.
inline std::size_t thread_count(std::size_t threads) {
  return threads > 0 ? threads : (std::max)(1u, std::thread::hardware_concurrency());
}

#ifdef CGAL_POLICIES_WITH_TBB
// Marks this thread, while it lives, as running a body of for_each_in_parallel.
class Inside_parallel_body {
 public:
  Inside_parallel_body() : m_outer(flag()) { flag() = true; }
  ~Inside_parallel_body() { flag() = m_outer; }
  Inside_parallel_body(const Inside_parallel_body&) = delete;
  Inside_parallel_body& operator=(const Inside_parallel_body&) = delete;

  static bool now() { return flag(); }

 private:
  static bool& flag() {
    static thread_local bool inside = false;
    return inside;
  }

  bool m_outer;
};
#endif

template <class Body>
void for_each_in_parallel(std::size_t n, std::size_t threads, const Body& body) {
  if (threads == 1 || n <= 1) {  // in place: no arena or thread for the calls made on one core
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
#ifdef CGAL_POLICIES_WITH_TBB
  const auto run = [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        const Inside_parallel_body inside;
                        for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                      });
  };
  // A call from a body runs in that body's arena, whose cores are already counted: a core whose
  // own bodies are done then takes part of the nested work rather than wait.
  if (Inside_parallel_body::now()) return run();
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : int(threads));
  arena.execute(run);
#else
  threads = thread_count(threads);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t i; (i = next++) < n;) try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = n;
      }
  };
  std::vector<std::thread> workers;
  for (std::size_t t = 1; t < (std::min)(threads, n); ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (failure) std::rethrow_exception(failure);
#endif
}

// The same for a few heavy items of known relative `costs`: each core takes the costliest item
// left, so that a large item does not start last while the other cores wait (a list schedule,
// largest first). The cells of a fit's second half are of unequal sizes.
template <class Body>
void for_each_costliest_first(const std::vector<std::size_t>& costs, std::size_t threads,
                              const Body& body) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  std::atomic<std::size_t> next{0};
  for_each_in_parallel((std::min)(thread_count(threads), order.size()), threads, [&](std::size_t) {
    for (std::size_t k; (k = next++) < order.size();) try {
        body(order[k]);
      } catch (...) {
        next = order.size();
        throw;
      }
  });
}

// body(begin, end) for the ranges of `block` consecutive i < n, as for_each_in_parallel runs them:
// for bodies so cheap that a task each would cost more than they do, or that carry a hint from
// one i to the next.
template <class Body>
void for_each_block(std::size_t n, std::size_t block, std::size_t threads, const Body& body) {
  for_each_in_parallel((n + block - 1) / block, threads,
                       [&](std::size_t b) { body(b * block, (std::min)(n, (b + 1) * block)); });
}

// body(i) for every i < n, `block` consecutive i to a task (for_each_block).
template <class Body>
void for_each_in_blocks(std::size_t n, std::size_t block, std::size_t threads, const Body& body) {
  for_each_block(n, block, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FOR_EACH_IN_PARALLEL_H
