// What SIGINT and SIGTERM leave behind: nothing partial. While a Removed_on_interrupt lives, an
// interrupt removes its file before the app exits, so an output is either the old file or the
// complete new one (README.md, "Command line").
#ifndef CGAL_POLICIES_IO_REMOVED_ON_INTERRUPT_H
#define CGAL_POLICIES_IO_REMOVED_ON_INTERRUPT_H

#include <string>

namespace cgal_policies {
namespace io {

// Makes SIGINT and SIGTERM remove every file held by a Removed_on_interrupt, print
// "<app>: interrupted" and exit with 128 + the signal's number (130, 143), as shells report it.
// `app` must live as long as the program (a string literal).
void install_interrupt_handlers(const char* app);

class Removed_on_interrupt {
 public:
  // Throws Io_error (unwritable output) for a path too long to hold for the handler.
  explicit Removed_on_interrupt(const std::string& path);
  ~Removed_on_interrupt();
  Removed_on_interrupt(const Removed_on_interrupt&) = delete;
  Removed_on_interrupt& operator=(const Removed_on_interrupt&) = delete;

 private:
  int m_slot;
};

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_REMOVED_ON_INTERRUPT_H
