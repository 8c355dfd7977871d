#include "bench_peers.h"

namespace apps {

std::vector<Bench_row> bench_peers() {
  std::vector<Bench_row> all = envelope_peers();
  const auto append = [&all](const std::vector<Bench_row>& group) {
    all.insert(all.end(), group.begin(), group.end());
  };
#ifdef CGAL_POLICIES_WITH_MESHOPTIMIZER
  append(meshoptimizer_peers());
#endif
#ifdef CGAL_POLICIES_WITH_OPENMESH
  append(openmesh_peers());
#endif
  static_cast<void>(append);  // unused when no optional peer was found
  return all;
}

}  // namespace apps
