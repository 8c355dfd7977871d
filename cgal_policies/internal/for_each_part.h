// Runs body(i) for every i < n, each on its own, on up to `threads` cores (0: all of them) with
// TBB when the build links it (CGAL_POLICIES_WITH_TBB), one after the other otherwise. Each i
// writes only what belongs to it, so the result does not depend on the schedule.
#ifndef CGAL_POLICIES_INTERNAL_FOR_EACH_PART_H
#define CGAL_POLICIES_INTERNAL_FOR_EACH_PART_H

#include <cstddef>

#ifdef CGAL_POLICIES_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace cgal_policies {
namespace internal {

template <class Body>
void for_each_part(std::size_t n, std::size_t threads, const Body& body) {
#ifdef CGAL_POLICIES_WITH_TBB
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : int(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
                      });
  });
#else
  static_cast<void>(threads);
  for (std::size_t i = 0; i < n; ++i) body(i);
#endif
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FOR_EACH_PART_H
