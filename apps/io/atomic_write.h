// Every output file of the apps is written all or nothing: into a temporary file of the same
// folder, renamed into place once complete, and removed on failure or interruption.
#ifndef CGAL_POLICIES_IO_ATOMIC_WRITE_H
#define CGAL_POLICIES_IO_ATOMIC_WRITE_H

#include <functional>
#include <string>

namespace cgal_policies {
namespace io {

// Calls `write` with the temporary's path (same folder, a name of its own that keeps the
// extension, since writers pick the format from it), then renames it to `path`. Throws
// Io_error (unwritable output) naming `path`, and leaves no file, when the folder is missing, when
// `write` returns false or throws, or when the rename fails; SIGINT and SIGTERM remove the
// temporary too (Removed_on_interrupt).
void write_atomically(const std::string& path,
                      const std::function<bool(const std::string& temporary)>& write);

// Throws Io_error (unwritable output) naming `path` when its folder does not exist: the check
// write_atomically makes, for the apps to make before they read any input.
void check_output_folder(const std::string& path);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_ATOMIC_WRITE_H
