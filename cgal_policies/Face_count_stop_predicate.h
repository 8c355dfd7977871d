// Face_count_stop_predicate: a StopPredicate for CGAL's SMS::edge_collapse that stops once a
// CGAL::Surface_mesh has no more than a target number of faces (CGAL 5.5's own predicates count
// edges), once a deadline has passed, or once the caller's interruption callback says so, and
// records which of them stopped the run.
//   target              faces, >= 0
//   time_limit_seconds  >= 0; 0: no deadline
//   interrupted         polled every kInterruptionPeriod calls; may be empty
// Usage:
//   cgal_policies::Face_count_stop_predicate<Mesh> stop(mesh, mesh.number_of_faces() / 10);
//   SMS::edge_collapse(mesh, stop, ...);
//   // stop.reason(): Stop_reason::target_reached, time_limit or interrupted; empty when the
//   // queue ran dry first
#ifndef CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H
#define CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H

#include <cgal_policies/Stop_reason.h>

#include <CGAL/assertions.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

namespace cgal_policies {

template <typename SurfaceMesh>
class Face_count_stop_predicate {
 public:
  using Clock = std::chrono::steady_clock;
  // Interruption callbacks may cost a lock or a call into an interpreter: not at every edge.
  static constexpr std::size_t kInterruptionPeriod = 256;

  Face_count_stop_predicate(const SurfaceMesh& mesh, std::size_t target,
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
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    if (m_state->reason) return true;
    if (m_mesh->number_of_faces() <= m_target)
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
  };

  const SurfaceMesh* m_mesh;
  std::size_t m_target;
  bool m_has_deadline;
  Clock::time_point m_deadline;
  std::function<bool()> m_interrupted;
  std::shared_ptr<State> m_state;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FACE_COUNT_STOP_PREDICATE_H
