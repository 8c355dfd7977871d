// The one exception the io layer throws: "<file>: <cause>", and whether the file could not be read
// or could not be written, so that an app can tell its exit code (3 or 4) from it.
#ifndef CGAL_POLICIES_IO_IO_ERROR_H
#define CGAL_POLICIES_IO_IO_ERROR_H

#include <stdexcept>
#include <string>

namespace cgal_policies {
namespace io {

class Io_error : public std::runtime_error {
 public:
  enum class Kind {
    unreadable_input,  // missing, malformed, or not a triangle mesh once repaired
    unwritable_output  // no such folder, a write or a rename failed
  };

  Io_error(Kind kind, const std::string& message) : std::runtime_error(message), m_kind(kind) {}
  Kind kind() const { return m_kind; }

 private:
  Kind m_kind;
};

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_IO_ERROR_H
