#include "bench_peers.h"

namespace apps {

std::vector<Policy_entry> bench_peers() {
  std::vector<Policy_entry> all = envelope_peers();
  const auto append = [&all](const std::vector<Policy_entry>& group) {
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
