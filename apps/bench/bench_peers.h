// The peers simplify_bench measures beside the registry's policies: methods a user would pick
// instead of ours, run as rows of the same tables (Bench_row.h). Each peer lives in its own source
// file, compiled only when its library was found (apps/CMakeLists.txt).
#ifndef CGAL_POLICIES_APPS_BENCH_BENCH_PEERS_H
#define CGAL_POLICIES_APPS_BENCH_BENCH_PEERS_H

#include "Bench_row.h"

#include <vector>

namespace apps {

// Every peer this build has, in a fixed order.
std::vector<Bench_row> bench_peers();

// One function per peer source file.
std::vector<Bench_row> envelope_peers();       // peer_envelope.cpp: gh-envelope (CGAL)
std::vector<Bench_row> meshoptimizer_peers();  // peer_meshoptimizer.cpp: meshopt
std::vector<Bench_row> openmesh_peers();       // peer_openmesh.cpp: openmesh

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_BENCH_BENCH_PEERS_H
