// Why a simplification run ended, recorded where it happens (the stop predicate, the end of the
// queue) rather than guessed from the result afterwards.
#ifndef CGAL_POLICIES_APPS_STOP_REASON_H
#define CGAL_POLICIES_APPS_STOP_REASON_H

namespace apps {

enum class Stop_reason {
  target_reached,       // the face target was met
  no_collapse_left,     // every remaining collapse was refused by topology or the policy
  error_bound_reached,  // as no_collapse_left, in a run bounded by --max-error or a tolerance
  time_limit            // stopped where it was after the time limit
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
  }
  return "unknown";
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_STOP_REASON_H
