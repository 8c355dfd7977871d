// Exit codes shared by every app (README.md) and the one exception that carries them to main().
#ifndef CGAL_POLICIES_APPS_CLI_APP_ERROR_H
#define CGAL_POLICIES_APPS_CLI_APP_ERROR_H

#include <stdexcept>
#include <string>

namespace apps {

enum Exit_code : int {
  exit_success = 0,
  exit_not_done = 1,   // the work could not be done (e.g. an error bound could not be met)
  exit_usage = 2,      // bad command line
  exit_bad_input = 3,  // unreadable or invalid input
  exit_bad_output = 4  // the output could not be written
};

class App_error : public std::runtime_error {
 public:
  App_error(Exit_code code, const std::string& message)
      : std::runtime_error(message), m_code(code) {}
  Exit_code code() const { return m_code; }

 private:
  Exit_code m_code;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_APP_ERROR_H
