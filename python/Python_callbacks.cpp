#include "Python_callbacks.h"

#include <cgal_policies/Simplification_pass.h>

#include <utility>

namespace cgal_policies {
namespace python {

Python_callbacks::Python_callbacks(py::object progress) : m_progress(std::move(progress)) {}

void Python_callbacks::attach(Simplification_options& options) {
  if (!m_progress.is_none())
    options.progress = [this](Simplification_pass pass, double done, std::size_t) {
      if (pass != Simplification_pass::simplification || m_stop) return;
      py::gil_scoped_acquire gil;
      try {
        m_progress(done);
      } catch (py::error_already_set& error) {
        keep(std::move(error));
      }
    };
  // The parts of a partitioned run poll it from their own threads too: Python answers a signal
  // on its main thread only, and the first thread to see it stops them all.
  options.interrupted = [this] {
    if (m_stop) return true;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) keep(py::error_already_set());
    return m_stop.load();
  };
}

void Python_callbacks::keep(py::error_already_set&& error) {
  if (!m_raised) m_raised.emplace(std::move(error));
  m_stop = true;
}

void Python_callbacks::rethrow_if_raised() {
  if (!m_raised) return;
  py::error_already_set error = std::move(*m_raised);
  m_raised.reset();
  throw error;
}

}  // namespace python
}  // namespace cgal_policies
