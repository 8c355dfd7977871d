// The progress of a partitioned run while its parts run: the whole's face count is the input's
// less what the parts have removed so far, so that a progress bar moves from the start, and not
// only in the last pass over the stitched whole. The parts report from their own threads; the
// caller's callback is called one call at a time.
#ifndef CGAL_POLICIES_INTERNAL_PART_PROGRESS_H
#define CGAL_POLICIES_INTERNAL_PART_PROGRESS_H

#include <cgal_policies/Simplification_pass.h>
#include <cgal_policies/internal/Pipeline_visitor.h>

#include <cstddef>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

class Part_progress {
 public:
  using Callback = std::function<void(Simplification_pass pass, double done, std::size_t faces)>;

  // `progress`, the run's callback (may be empty), for a run of `whole_faces` faces to `target`.
  Part_progress(Callback progress, std::size_t whole_faces, std::size_t target)
      : m_progress(std::move(progress)), m_whole_faces(whole_faces), m_target(target) {}

  // The callback for a part of `part_faces` faces: its face counts as the whole's progress. Empty
  // when the run has none. This object must outlive the part's run.
  Callback of_part(std::size_t part_faces) {
    if (!m_progress) return {};
    const std::lock_guard<std::mutex> adding(m_mutex);
    const std::size_t part = m_reported.size();
    m_reported.push_back(0);
    return [this, part, part_faces](Simplification_pass pass, double, std::size_t faces) {
      if (pass != Simplification_pass::simplification || faces > part_faces) return;
      const std::lock_guard<std::mutex> one_at_a_time(m_mutex);
      const std::size_t removed = part_faces - faces;
      m_removed = m_removed + removed - m_reported[part];
      m_reported[part] = removed;
      const std::size_t whole = m_whole_faces - m_removed;
      m_progress(pass, simplification_done(m_whole_faces, m_target, whole), whole);
    };
  }

  // The callback for the last pass, over the stitched parts: its face counts, and how far the
  // whole run is at them.
  Callback of_last_pass() const {
    if (!m_progress) return {};
    return [this](Simplification_pass pass, double done, std::size_t faces) {
      if (pass == Simplification_pass::simplification)
        done = simplification_done(m_whole_faces, m_target, faces);
      m_progress(pass, done, faces);
    };
  }

 private:
  Callback m_progress;
  std::size_t m_whole_faces, m_target;
  std::mutex m_mutex;
  std::vector<std::size_t> m_reported;  // the faces each part had removed when it last reported
  std::size_t m_removed = 0;            // their sum
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_PART_PROGRESS_H
