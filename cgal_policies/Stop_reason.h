// Stop_reason: why a simplification ended, recorded where it happens (the stop predicate, the end
// of the queue, the interruption callback) rather than guessed from the result afterwards.
#ifndef CGAL_POLICIES_STOP_REASON_H
#define CGAL_POLICIES_STOP_REASON_H

namespace cgal_policies {

enum class Stop_reason {
  target_reached,       // the face target was met
  no_collapse_left,     // every remaining collapse was refused by topology or the policy
  error_bound_reached,  // as no_collapse_left, in a run bounded by max_error or a tolerance
  time_limit,           // stopped where it was after the time limit
  interrupted           // the caller's interruption callback asked to stop
};

// The name the JSON reports and the tables print.
inline const char* to_string(Stop_reason reason) {
  switch (reason) {
    case Stop_reason::target_reached:
      return "target_reached";
    case Stop_reason::no_collapse_left:
      return "no_collapse_left";
    case Stop_reason::error_bound_reached:
      return "error_bound_reached";
    case Stop_reason::time_limit:
      return "time_limit";
    case Stop_reason::interrupted:
      return "interrupted";
  }
  return "unknown";
}

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_STOP_REASON_H
