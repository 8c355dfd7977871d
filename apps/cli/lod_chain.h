// simplify --lod: a chain of levels of detail, each level made from the one before through the
// pipeline the command line selects (docs/cli.md).
#ifndef CGAL_POLICIES_APPS_CLI_LOD_CHAIN_H
#define CGAL_POLICIES_APPS_CLI_LOD_CHAIN_H

#include <cgal_policies/Simplification_options.h>

#include <cstddef>
#include <string>
#include <vector>

namespace apps {

// The most levels --lod makes. Each may be a file, written all at once with any files beside them
// (kMaxFilesWrittenAtOnce, atomic_write.h).
constexpr std::size_t kMaxLodLevels = 16;

// The ratios of --lod R0,R1,...: the share of IN's faces each level keeps, finest first.
// App_error(exit_usage), one line naming --lod, unless each is a number in (0, 1] below the one
// before, and there are at most kMaxLodLevels.
std::vector<double> parse_lod_ratios(const std::string& text);

// Each level's MSFT_screencoverage, the share of the screen's area below which a viewer switches
// to the next coarser level. At a fixed number of faces per unit of screen area, the finest level
// suits a mesh filling the screen and level k a coverage of ratios[k] / ratios[0]; so level k
// gives way where level k + 1 suffices, at ratios[k + 1] / ratios[0], and the coarsest is never
// culled (0).
std::vector<double> lod_screen_coverage(const std::vector<double>& ratios);

// The options of level `level` of a chain from IN's `input_faces`: `options`, its target the
// level's share of IN's faces (Face_target::faces, as the level starts from the one before). The
// passes that clean IN (merging border pairs, dropping small components) run before level 0
// alone: the levels after it start from a clean mesh.
cgal_policies::Simplification_options lod_level_options(
    const cgal_policies::Simplification_options& options, const std::vector<double>& ratios,
    std::size_t level, std::size_t input_faces);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_LOD_CHAIN_H
