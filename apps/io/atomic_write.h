// Every output file of the apps is written all or nothing: into a temporary file of the same
// folder, renamed into place once complete, and removed on failure or interruption.
#ifndef CGAL_POLICIES_IO_ATOMIC_WRITE_H
#define CGAL_POLICIES_IO_ATOMIC_WRITE_H

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

// Calls `write` with the temporary's path (same folder, a name of its own that keeps the
// extension, since writers pick the format from it), then renames it to `path`. Throws
// Io_error (unwritable output) naming `path`, and leaves no file, when the folder is missing, when
// `write` returns false or throws, or when the rename fails; SIGINT and SIGTERM remove the
// temporary too (Removed_on_interrupt).
void write_atomically(const std::string& path,
                      const std::function<bool(const std::string& temporary)>& write);

// The same for several files, all or none: `write(i, temporary)` writes paths[i]'s temporary, for
// every i, before any is renamed into place. When a write or a rename fails, or SIGINT or SIGTERM
// comes before the last rename, no file of this call is left: the temporaries are removed, and so
// are the files already renamed (which had replaced any older ones). Throws Io_error naming the
// path that failed. At most kMaxFilesWrittenAtOnce paths: room for a chain of levels of detail
// (apps/cli/lod_chain.h), and beside OBJ levels of a glTF input, their material library and its
// images (mesh_io.h).
constexpr std::size_t kMaxFilesWrittenAtOnce = 64;
void write_all_atomically(
    const std::vector<std::string>& paths,
    const std::function<bool(std::size_t index, const std::string& temporary)>& write);

// Throws Io_error (unwritable output) naming `path` when its folder does not exist: the check
// write_atomically makes, for the apps to make before they read any input.
void check_output_folder(const std::string& path);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_ATOMIC_WRITE_H
