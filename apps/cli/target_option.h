// The face target of a command line, RATIO or --ratio R or --faces N, checked when given.
#ifndef CGAL_POLICIES_APPS_CLI_TARGET_OPTION_H
#define CGAL_POLICIES_APPS_CLI_TARGET_OPTION_H

#include <cgal_policies/Face_target.h>

#include <optional>

namespace apps {

// App_error(exit_usage) unless exactly one of the two is given and in range.
cgal_policies::Face_target face_target(std::optional<double> ratio, std::optional<double> faces);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_TARGET_OPTION_H
