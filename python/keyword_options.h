// simplify()'s keywords read as simplify's command line reads its options: each keyword becomes
// the option of the same name (underscores for dashes: `min_component=50` is
// `--min-component 50`, `smooth_bounded=True` the flag `--smooth-bounded`), so that every value
// is checked by the command line's own code and refused with its message.
#ifndef CGAL_POLICIES_PYTHON_KEYWORD_OPTIONS_H
#define CGAL_POLICIES_PYTHON_KEYWORD_OPTIONS_H

#include "cli/simplify_request.h"

#include <pybind11/pybind11.h>

namespace cgal_policies {
namespace python {

namespace py = pybind11;

// The pipeline's options and the policy's entry, target included (the library's default, 10% of
// the faces, when `keywords` names none). `fit` False turns the fitting pass off, which no
// command line can ask of the default pipeline. ValueError with the command line's message for an
// unknown keyword or a value out of range; TypeError for a value that is no number or string.
apps::Pipeline_request pipeline_request(const py::dict& keywords, const py::object& fit);

// The request of simplify()'s named arguments and its other keywords: target_count is `faces`,
// target_reduction r is `ratio` 1 - r, the others keep their names. ValueError as above, and for
// an option given twice or a reduction out of [0, 1).
apps::Pipeline_request simplify_request(const py::object& target_count,
                                        const py::object& target_reduction,
                                        const py::object& policy, const py::object& fit,
                                        const py::object& max_error, const py::object& threads,
                                        py::dict keywords);

}  // namespace python
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_PYTHON_KEYWORD_OPTIONS_H
