#include "collapse_recorder.h"

#include "cli/Stopwatch.h"
#include "pipeline/Pipeline.h"

#include <stdexcept>

namespace apps {

Collapse_history record_collapses(const Mesh& input,
                                  cgal_policies::Simplification_options options) {
  if (input.has_garbage()) throw std::invalid_argument("record_collapses: collect garbage first");
  Mesh mesh = input;
  Collapse_history history;
  history.input_faces = mesh.number_of_faces();
  const Stopwatch watch;
  options.on_collapse = [&](Mesh::Vertex_index removed, Mesh::Vertex_index kept) {
    history.collapses.push_back({removed, kept, mesh.point(kept), watch.seconds()});
  };
  history.report = Pipeline(options).run(mesh);
  history.final_faces = mesh.number_of_faces();
  return history;
}

}  // namespace apps
