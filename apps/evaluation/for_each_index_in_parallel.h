// The evaluator's measures run on every core: each index belongs to one thread.
#ifndef CGAL_POLICIES_APPS_EVALUATION_FOR_EACH_INDEX_IN_PARALLEL_H
#define CGAL_POLICIES_APPS_EVALUATION_FOR_EACH_INDEX_IN_PARALLEL_H

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace apps {

// Runs body(i) for every i < n on every core. Each i belongs to one thread, so a body that writes
// slot i alone gives a result that does not depend on the schedule.
template <class Body>
void for_each_index_in_parallel(std::size_t n, const Body& body) {
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = (n + threads - 1) / threads;
  std::vector<std::thread> workers;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = t * chunk, end = std::min(n, begin + chunk);
    if (begin >= end) break;
    workers.emplace_back([&body, begin, end] {
      for (std::size_t i = begin; i < end; ++i) body(i);
    });
  }
  for (std::thread& w : workers) w.join();
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_EVALUATION_FOR_EACH_INDEX_IN_PARALLEL_H
