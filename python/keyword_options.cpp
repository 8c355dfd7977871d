#include "keyword_options.h"

#include "cli/Command_line.h"
#include "cli/target_option.h"

#include <string>
#include <vector>

namespace cgal_policies {
namespace python {
namespace {

// "--name=value", or "--name" for True; nothing for None and False.
std::vector<std::string> command_line_words(const py::dict& keywords) {
  std::vector<std::string> words{"cgal_policies.simplify"};
  for (const auto& [key, value] : keywords) {
    std::string option = "--" + py::cast<std::string>(key);
    for (char& c : option)
      if (c == '_') c = '-';
    if (value.is_none() || (py::isinstance<py::bool_>(value) && !value.cast<bool>())) continue;
    if (py::isinstance<py::bool_>(value))
      words.push_back(option);
    else if (py::isinstance<py::str>(value))
      words.push_back(option + "=" + value.cast<std::string>());
    else  // repr gives the shortest text that reads back as the same double
      words.push_back(
          option + "=" +
          py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>());
  }
  return words;
}

}  // namespace

apps::Pipeline_request pipeline_request(const py::dict& keywords, const py::object& fit) {
  std::vector<std::string> words = command_line_words(keywords);
  if (!fit.is_none() && fit.cast<bool>()) words.push_back("--fit");
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  apps::Command_line cli(int(argv.size()), argv.data());
  apps::Pipeline_request request = apps::take_pipeline_request(cli);
  cli.positionals();  // refuses the keywords no option took
  if (request.ratio || request.faces)
    request.options.target = apps::face_target(request.ratio, request.faces);
  if (!fit.is_none() && !fit.cast<bool>()) request.options.fit = false;
  return request;
}

apps::Pipeline_request simplify_request(const py::object& target_count,
                                        const py::object& target_reduction,
                                        const py::object& policy, const py::object& fit,
                                        const py::object& max_error, const py::object& threads,
                                        py::dict keywords) {
  const auto named = [&keywords](const char* key, const py::object& value) {
    if (value.is_none()) return;
    if (keywords.contains(key)) throw py::value_error(std::string("give ") + key + " once");
    keywords[key] = value;
  };
  named("faces", target_count);
  if (!target_reduction.is_none()) {
    const double reduction = target_reduction.cast<double>();
    if (!(reduction >= 0 && reduction < 1))
      throw py::value_error("target_reduction must be a number in [0, 1)");
    named("ratio", py::float_(1 - reduction));
  }
  named("policy", policy);
  named("max_error", max_error);
  named("threads", threads);
  return pipeline_request(keywords, fit);
}

}  // namespace python
}  // namespace cgal_policies
