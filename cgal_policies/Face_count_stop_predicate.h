// Face_count_stop_predicate: a StopPredicate for CGAL's SMS::edge_collapse that stops once a
// triangle mesh has no more than a target number of faces (CGAL 5.5's own predicates count
// edges), once a deadline has passed, or once the caller's interruption callback says so, and
// records which of them stopped the run. Any mesh type edge_collapse takes: the faces are counted
// exactly, once at the first call and again only when the edges removed since leave the answer
// open (a collapse removes one or two faces and one edge more), so a type whose count walks every
// face (Polyhedron_3, OpenMesh) is counted O(log n) times, not at every call.
//   target              faces, >= 0
//   time_limit_seconds  >= 0; 0: no deadline
//   interrupted         polled every kInterruptionPeriod calls; may be empty
// Usage:
//   cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh, num_faces(mesh) / 10);
//   SMS::edge_collapse(mesh, stop, ...);
//   // stop.reason(): Stop_reason::target_reached, time_limit or interrupted; empty when the
//   // queue ran dry first
#ifndef CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H
#define CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H

#include <cgal_policies/Stop_reason.h>
#include <cgal_policies/internal/face_count.h>

#include <CGAL/assertions.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

namespace cgal_policies {

template <typename TriangleMesh>
class Face_count_stop_predicate {
 public:
  using Clock = std::chrono::steady_clock;
  // Interruption callbacks may cost a lock or a call into an interpreter: not at every edge.
  static constexpr std::size_t kInterruptionPeriod = 256;

  Face_count_stop_predicate(const TriangleMesh& mesh, std::size_t target,
                            double time_limit_seconds = 0, std::function<bool()> interrupted = {})
      : m_mesh(&mesh),
        m_target(target),
        m_has_deadline(time_limit_seconds > 0),
        m_interrupted(std::move(interrupted)),
        m_state(std::make_shared<State>()) {
    CGAL_precondition(time_limit_seconds >= 0);
    if (m_has_deadline)
      m_deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(time_limit_seconds));
  }

  template <typename FT, typename Profile>
  bool operator()(const FT&, const Profile&, std::size_t initial_edges,
                  std::size_t current_edges) const {
    if (m_state->reason) return true;
    if (at_most_target_faces(initial_edges, current_edges))
      m_state->reason = Stop_reason::target_reached;
    else if (m_has_deadline && Clock::now() >= m_deadline)
      m_state->reason = Stop_reason::time_limit;
    else if (m_interrupted && ++m_state->calls % kInterruptionPeriod == 0 && m_interrupted())
      m_state->reason = Stop_reason::interrupted;
    return bool(m_state->reason);
  }

  // What stopped the run; empty while nothing has (or when the queue ran dry first). Copies
  // share it: SMS::edge_collapse takes the predicate by value in some versions.
  const std::optional<Stop_reason>& reason() const { return m_state->reason; }

 private:
  struct State {
    std::optional<Stop_reason> reason;
    std::size_t calls = 0;
    // The faces counted when the mesh had `counted_edges` edges, in the run that started with
    // `run_edges`; none before the first call.
    std::optional<std::size_t> counted_faces;
    std::size_t counted_edges = 0, run_edges = 0;
  };

  // Whether the mesh, now of `edges` edges in a run that started with `initial_edges`, has at
  // most m_target faces. Since the last count, each collapse removed f faces and f + 1 edges,
  // f in {1, 2}: with r edges removed, between r/2 and 2r/3 faces went. Another run (a predicate
  // used twice) counts again.
  bool at_most_target_faces(std::size_t initial_edges, std::size_t edges) const {
    State& s = *m_state;
    if (!s.counted_faces || initial_edges != s.run_edges || edges > s.counted_edges)
      return recount(initial_edges, edges);
    const std::size_t removed = s.counted_edges - edges;
    const std::size_t fewest_gone = (removed + 1) / 2, most_gone = 2 * removed / 3;
    if (*s.counted_faces <= m_target + fewest_gone) return true;
    if (*s.counted_faces > m_target + most_gone) return false;
    return recount(initial_edges, edges);
  }

  bool recount(std::size_t initial_edges, std::size_t edges) const {
    m_state->counted_faces = internal::face_count(*m_mesh);
    m_state->counted_edges = edges;
    m_state->run_edges = initial_edges;
    return *m_state->counted_faces <= m_target;
  }

  const TriangleMesh* m_mesh;
  std::size_t m_target;
  bool m_has_deadline;
  Clock::time_point m_deadline;
  std::function<bool()> m_interrupted;
  std::shared_ptr<State> m_state;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H
