// A header that declares more elements than its file can hold (a truncated or forged OFF, PLY or
// binary STL) is refused before any reader sizes its arrays by it: each element takes at least a
// few bytes of the file, and some memory once read.
#ifndef CGAL_POLICIES_IO_DECLARED_COUNTS_H
#define CGAL_POLICIES_IO_DECLARED_COUNTS_H

#include <string>

namespace cgal_policies {
namespace io {

// Throws Io_error (unreadable input, "<path>: declares ...") when the element counts of the header
// need more bytes than the file has after it, or more memory than the machine has. A header it
// cannot make out (OBJ has none) is left to the reader.
void check_declared_counts(const std::string& path);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_DECLARED_COUNTS_H
