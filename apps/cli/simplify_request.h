// What a `simplify` command line asks for, read and checked whole before any input is read: the
// pipeline's options (policy, target, passes), the files and the report.
#ifndef CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H
#define CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H

#include "Command_line.h"
#include "app_types.h"
#include "io/mesh_io.h"
#include "pipeline/policy_registry.h"

#include <cgal_policies/Simplification_options.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace apps {

// The pipeline's options of a command line, the target aside: the policy with its options, the
// passes, the bound and the cells. The target's --ratio and --faces are taken unchecked: the caller
// may have a RATIO among the positionals (face_target checks them).
struct Pipeline_request {
  cgal_policies::Simplification_options options;
  const Policy_entry* policy = nullptr;  // options.policy's entry
  std::optional<double> ratio, faces;
};

// Takes every option of simplify that sets the pipeline; App_error with exit_usage or
// Option_error when one is malformed or out of range. The Python module reads its keywords so.
Pipeline_request take_pipeline_request(Command_line& cli);

struct Simplify_request {
  cgal_policies::Simplification_options options;
  const Policy_entry* policy = nullptr;  // options.policy's entry
  std::optional<std::size_t> samples;    // --samples of --measure
  bool json = false, measure = false, force = false, quiet = false;
  bool out_of_core = false;  // read IN in passes (run_streamed), never whole
  // --lod: the chain's levels as shares of IN's faces, finest first (lod_chain.h); empty without.
  std::vector<double> lod_ratios;
  // --gltf-encoding: how a glTF OUT stores its vertices (gltf_io.h).
  Gltf_encoding gltf_encoding = Gltf_encoding::float32;
  // --asset-root: the folder IN's buffers, images and material libraries may come from (mesh_io.h's
  // Read_options); empty, IN's own folder.
  std::string asset_root;
  std::string input, output;
};

// Takes every option of simplify but --help and the snapshot's, then IN OUT [RATIO]; App_error
// with exit_usage (bad command line) or Io_error (OUT's folder is missing) otherwise. With --lod,
// the target is the first level's and every level's file is checked (lod_level_paths).
// --gltf-encoding needs a glTF OUT.
Simplify_request take_simplify_request(Command_line& cli);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_SIMPLIFY_REQUEST_H
