// Where an app may write its mesh, checked before any input is read.
#ifndef CGAL_POLICIES_APPS_CLI_OUTPUT_PATH_H
#define CGAL_POLICIES_APPS_CLI_OUTPUT_PATH_H

#include <string>

namespace apps {

// Throws App_error(exit_usage) when `output` cannot be a mesh file or would overwrite `input`
// (unless `force`), App_error(exit_bad_output) when its folder does not exist.
void check_output_path(const std::string& input, const std::string& output, bool force);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_OUTPUT_PATH_H
