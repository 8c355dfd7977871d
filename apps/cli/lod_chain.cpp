#include "lod_chain.h"

#include "App_error.h"
#include "Command_line.h"

#include <cgal_policies/Face_target.h>

namespace apps {

std::vector<double> parse_lod_ratios(const std::string& text) {
  if (text.empty())
    throw App_error(exit_usage, "--lod needs the levels' ratios, e.g. --lod 0.5,0.25,0.1");
  std::vector<double> ratios;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma - start);
    const double ratio = parse_number(item, "--lod");
    if (!(ratio > 0 && ratio <= 1))
      throw App_error(exit_usage, "--lod: " + item + " is not a ratio in (0, 1]");
    if (!ratios.empty() && !(ratio < ratios.back()))
      throw App_error(exit_usage, "--lod: " + item +
                                      " does not keep fewer faces than the level before it; "
                                      "give the ratios finest first, each smaller");
    ratios.push_back(ratio);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (ratios.size() > kMaxLodLevels)
    throw App_error(exit_usage, "--lod: at most " + std::to_string(kMaxLodLevels) + " levels");
  return ratios;
}

std::vector<double> lod_screen_coverage(const std::vector<double>& ratios) {
  std::vector<double> coverage;
  for (std::size_t k = 1; k < ratios.size(); ++k) coverage.push_back(ratios[k] / ratios[0]);
  coverage.push_back(0);
  return coverage;
}

cgal_policies::Simplification_options lod_level_options(
    const cgal_policies::Simplification_options& options, const std::vector<double>& ratios,
    std::size_t level, std::size_t input_faces) {
  cgal_policies::Simplification_options level_options = options;
  level_options.target = cgal_policies::Face_target::faces(
      cgal_policies::Face_target::ratio(ratios[level]).of(input_faces));
  if (level > 0) {
    level_options.merge_distance = 0;
    level_options.min_component = 0;
  }
  return level_options;
}

}  // namespace apps
