// The pipeline's progress and interruption hooks for a run whose caller released the GIL: each
// takes the GIL back for a moment. `interrupted` asks Python for a pending signal (Ctrl-C raises
// KeyboardInterrupt) and stops the run when one, or an exception of the progress callback, is
// waiting; the run returns where it was and rethrow_if_raised raises it again in Python.
#ifndef CGAL_POLICIES_PYTHON_PYTHON_CALLBACKS_H
#define CGAL_POLICIES_PYTHON_PYTHON_CALLBACKS_H

#include <cgal_policies/Simplification_options.h>

#include <pybind11/pybind11.h>

#include <atomic>
#include <optional>

namespace cgal_policies {
namespace python {

namespace py = pybind11;

class Python_callbacks {
 public:
  // `progress`: None, or called with the fraction of the simplification pass done.
  explicit Python_callbacks(py::object progress);

  // Sets options.progress and options.interrupted to this object's hooks; it must outlive the run.
  void attach(Simplification_options& options);

  // With the GIL held, after the run: raises what stopped it, if anything did.
  void rethrow_if_raised();

 private:
  // With the GIL held: keeps the Python error being handled (the first one) and stops the run.
  void keep(py::error_already_set&& error);

  py::object m_progress;
  std::optional<py::error_already_set> m_raised;
  std::atomic<bool> m_stop{false};
};

}  // namespace python
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_PYTHON_PYTHON_CALLBACKS_H
