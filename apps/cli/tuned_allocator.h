// glibc's malloc tuned for meshes of millions of faces: the heap in transparent huge pages (the
// kernel's default "madvise" mode grants them only on request) and freed memory kept for reuse
// rather than handed back, so that arrays of hundreds of megabytes are not faulted in again and
// again 4 KiB at a time (docs/scale.md, "Page faults"). glibc reads these settings only when a
// process starts, from GLIBC_TUNABLES: an app restarts itself once with them.
#ifndef CGAL_POLICIES_APPS_CLI_TUNED_ALLOCATOR_H
#define CGAL_POLICIES_APPS_CLI_TUNED_ALLOCATOR_H

#include <optional>
#include <string>

namespace apps {

// GLIBC_TUNABLES as the restart sets it, given its value now (null: unset); nothing when that
// already sets a malloc tunable (the user's choice, or the restart done).
std::optional<std::string> tuned_allocator_tunables(const char* current);

// Runs this program again in this process, with the same arguments and the tunables above; returns
// when they are set already, when the C library is not glibc, under Valgrind (which would not
// follow), or when the program cannot be run again.
void restart_with_tuned_allocator(char** argv);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_TUNED_ALLOCATOR_H
