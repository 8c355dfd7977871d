// A partitioned job run from Python a step at a time (Simplification_pipeline::cut,
// run_part, stitch, result; docs/scale.md): the tasks of cgal_policies.dask, each made anew in
// whichever process runs it from the folder the steps share and simplify()'s options.
#ifndef CGAL_POLICIES_PYTHON_PYTHON_JOB_H
#define CGAL_POLICIES_PYTHON_PYTHON_JOB_H

#include "Python_mesh.h"

#include "cli/simplify_request.h"

#include <pybind11/pybind11.h>

#include <cstddef>
#include <filesystem>
#include <utility>

namespace cgal_policies {
namespace python {

class Python_job {
 public:
  Python_job(std::filesystem::path folder, apps::Pipeline_request request);

  // Runs the repairs on a copy of `mesh` and cuts it into parts in the folder; their number.
  std::size_t cut(const Python_mesh& mesh) const;
  // Cuts the mesh file at `path` (binary PLY or OBJ) read in passes, never whole, as
  // `simplify --out-of-core` reads it; ValueError for the options that need the whole input.
  std::size_t cut_file(const std::filesystem::path& path) const;
  void run_part(int stage, std::size_t c) const;
  // True when another stage follows.
  bool stitch(int stage) const;
  // The output and simplify()'s report, `input` being the mesh given to cut(): its materials and
  // its repairs are the output's; none after cut_file().
  std::pair<Python_mesh, py::dict> result(const Python_mesh* input) const;

 private:
  std::filesystem::path m_folder;
  apps::Pipeline_request m_request;
};

}  // namespace python
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_PYTHON_PYTHON_JOB_H
