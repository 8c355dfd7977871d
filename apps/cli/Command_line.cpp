#include "Command_line.h"

#include "App_error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace apps {

Command_line::Command_line(int argc, char** argv) : m_args(argv + 1, argv + argc) {}

bool Command_line::take_flag(const std::string& name, const std::string& short_name) {
  const auto it = std::find_if(m_args.begin(), m_args.end(), [&](const std::string& a) {
    return a == "--" + name || (!short_name.empty() && a == short_name);
  });
  if (it == m_args.end()) return false;
  m_args.erase(it);
  return true;
}

std::optional<std::string> Command_line::take_value(const std::string& name) {
  const std::string option = "--" + name;
  for (auto it = m_args.begin(); it != m_args.end(); ++it) {
    if (it->rfind(option + "=", 0) == 0) {
      std::string value = it->substr(option.size() + 1);
      m_args.erase(it);
      return value;
    }
    if (*it != option) continue;
    if (it + 1 == m_args.end()) throw App_error(exit_usage, option + " needs a value");
    std::string value = *(it + 1);
    m_args.erase(it, it + 2);
    return value;
  }
  return std::nullopt;
}

std::optional<double> Command_line::take_number(const std::string& name) {
  const std::optional<std::string> text = take_value(name);
  if (!text) return std::nullopt;
  return parse_number(*text, "--" + name);
}

std::optional<double> Command_line::take_whole_number(const std::string& name, double min,
                                                      double max) {
  const std::optional<double> value = take_number(name);
  if (value) check_whole_number(*value, min, max, "--" + name);
  return value;
}

std::vector<std::string> Command_line::positionals() const {
  for (const std::string& a : m_args)
    if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1])) &&
        a[1] != '.')
      throw App_error(exit_usage, "unknown option " + a + " (see --help)");
  return m_args;
}

double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw App_error(exit_usage, what + ": '" + text + "' is not a finite number");
  return value;
}

double check_whole_number(double value, double min, double max, const std::string& what) {
  if (!(value >= min && value <= max && value == std::floor(value))) {
    std::ostringstream range;
    range << what << " must be a whole number in [" << min << ", " << max << "]";
    throw App_error(exit_usage, range.str());
  }
  return value;
}

const char* const kAssetRootHelp =
    "  --asset-root DIR      the input may name files (glTF buffers and images, OBJ\n"
    "                        material libraries and textures) anywhere in DIR, a\n"
    "                        folder holding it; without it, only in its own folder and\n"
    "                        below\n";

std::string take_asset_root(Command_line& cli) {
  const std::optional<std::string> root = cli.take_value("asset-root");
  if (!root) return {};
  std::error_code failed;
  if (!std::filesystem::is_directory(*root, failed))
    throw App_error(exit_usage, "--asset-root: '" + *root + "' is not a folder");
  return *root;
}

}  // namespace apps
