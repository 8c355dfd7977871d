// meshoptimizer's meshopt_simplify: quadric-driven collapses onto existing vertices on flat index
// arrays, as a game engine would run it. Only the meshopt_simplify call is timed; the conversions
// to and from its arrays are not part of the method.
#include "bench_peers.h"
#include "cli/Stopwatch.h"
#include "peer_mesh.h"

#include <meshoptimizer.h>

namespace apps {
namespace {

Bench_run run_meshoptimizer(Mesh& mesh, const Bench_settings& settings) {
  const Indexed_triangles input = to_indexed_triangles(mesh);
  std::vector<float> positions;
  positions.reserve(3 * input.points.size());
  for (const Point& p : input.points)
    for (int i = 0; i < 3; ++i) positions.push_back(float(p[i]));
  std::vector<unsigned int> indices;
  indices.reserve(3 * input.triangles.size());
  for (const auto& t : input.triangles) indices.insert(indices.end(), t.begin(), t.end());
  std::vector<unsigned int> output(indices.size());  // the worst case, as its contract asks

  // A relative target error of 1 is the whole extent of the mesh: only the face count stops it.
  const float kNoErrorLimit = 1.0f;
  const Stopwatch watch;
  const std::size_t count = meshopt_simplify(
      output.data(), indices.data(), indices.size(), positions.data(), input.points.size(),
      3 * sizeof(float), 3 * settings.target_faces, kNoErrorLimit, 0, nullptr);
  Bench_run outcome;
  outcome.seconds = watch.seconds();

  // meshopt keeps the input's vertices, so the result takes their exact (double) positions.
  Indexed_triangles result{input.points, {}};
  for (std::size_t i = 0; i + 2 < count; i += 3)
    result.triangles.push_back({output[i], output[i + 1], output[i + 2]});
  outcome.stop_reason = adopt_peer_result(result, settings.target_faces, mesh);
  return outcome;
}

}  // namespace

std::vector<Bench_row> meshoptimizer_peers() {
  return {{"meshopt",
           "meshoptimizer meshopt_simplify (collapses onto existing vertices)",
           {},
           run_meshoptimizer}};
}

}  // namespace apps
