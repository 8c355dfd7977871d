#include "collapse_recorder.h"
#include "common/Stopwatch.h"

#include <stdexcept>

namespace apps {

Collapse_history record_collapses(const Mesh& input, const Policy_entry& policy,
                                  Simplify_settings settings) {
  if (input.has_garbage()) throw std::invalid_argument("record_collapses: collect garbage first");
  Mesh mesh = input;
  Collapse_history history;
  history.input_faces = mesh.number_of_faces();
  const Stopwatch watch;
  settings.on_collapse = [&](Mesh::Vertex_index removed, Mesh::Vertex_index kept) {
    history.collapses.push_back({removed, kept, mesh.point(kept), watch.seconds()});
  };
  history.outcome = policy.run(mesh, settings);
  history.final_faces = mesh.number_of_faces();
  return history;
}

}  // namespace apps
