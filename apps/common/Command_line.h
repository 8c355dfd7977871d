// A small command-line reader: options are taken by name, what is left are the positionals.
// Any malformed or unknown option is an App_error(exit_usage) naming it.
#ifndef CGAL_POLICIES_APPS_COMMAND_LINE_H
#define CGAL_POLICIES_APPS_COMMAND_LINE_H

#include <optional>
#include <string>
#include <vector>

namespace apps {

class Command_line {
 public:
  Command_line(int argc, char** argv);

  // True when --name (or one of its spellings, e.g. "-h") was given; removes it.
  bool take_flag(const std::string& name, const std::string& short_name = "");
  // The value after --name (or --name=value); removes both.
  std::optional<std::string> take_value(const std::string& name);
  // As take_value, read as a finite number.
  std::optional<double> take_number(const std::string& name);

  // The arguments left once every option was taken; an option left over is unknown.
  std::vector<std::string> positionals() const;

 private:
  std::vector<std::string> m_args;
};

// Parses a finite number; App_error(exit_usage) naming `what` otherwise.
double parse_number(const std::string& text, const std::string& what);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_COMMAND_LINE_H
