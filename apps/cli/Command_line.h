// A small command-line reader: options are taken by name, what is left are the positionals.
// Any malformed or unknown option is an App_error(exit_usage) naming it.
#ifndef CGAL_POLICIES_APPS_CLI_COMMAND_LINE_H
#define CGAL_POLICIES_APPS_CLI_COMMAND_LINE_H

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
  // As take_number, a whole number in [min, max]; App_error(exit_usage) naming the option and the
  // range otherwise. The bounds keep every value within what the caller's integer type holds.
  std::optional<double> take_whole_number(const std::string& name, double min, double max);

  // The arguments left once every option was taken; an option left over is unknown.
  std::vector<std::string> positionals() const;

 private:
  std::vector<std::string> m_args;
};

// --asset-root DIR, which every tool that reads meshes takes: the folder the files an input names
// may come from (mesh_io.h's Read_options); empty when not given. App_error(exit_usage) when DIR
// is not a folder.
std::string take_asset_root(Command_line& cli);
// Its line of a tool's --help.
extern const char* const kAssetRootHelp;

// Parses a finite number; App_error(exit_usage) naming `what` otherwise.
double parse_number(const std::string& text, const std::string& what);

// `value` when it is a whole number in [min, max]; App_error(exit_usage) naming `what` otherwise.
double check_whole_number(double value, double min, double max, const std::string& what);

// The largest count the apps take (--faces, --samples, --min-component): far beyond any mesh, and
// exactly representable both as a double and as a size_t.
constexpr double kMaxCount = 1e15;
// The largest --time-limit (31 years): a larger one would overflow the steady clock's deadline.
constexpr double kMaxTimeLimitSeconds = 1e9;

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_COMMAND_LINE_H
