#include "atomic_write.h"

#include "Io_error.h"
#include "Removed_on_interrupt.h"

#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {
namespace {

[[noreturn]] void fail_output(const std::string& path, const std::string& cause) {
  throw Io_error(Io_error::Kind::unwritable_output, path + ": " + cause);
}

// The folder `path` is written in, checked to exist.
fs::path existing_output_folder(const std::string& path) {
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) fail_output(path, "cannot write: no such folder");
  return folder;
}

}  // namespace

void check_output_folder(const std::string& path) { existing_output_folder(path); }

void write_atomically(const std::string& path,
                      const std::function<bool(const std::string& temporary)>& write) {
  const fs::path folder = existing_output_folder(path);
  const fs::path target(path);
  std::error_code ec;
  const fs::path temporary = folder / ("." + target.stem().string() + ".tmp-" +
                                       std::to_string(::getpid()) + target.extension().string());
  // Held from before the file exists until after it is renamed: no moment without a guard.
  const Removed_on_interrupt guard(temporary.string());
  {
    std::ofstream probe(temporary);
    if (!probe) fail_output(path, std::string("cannot write: ") + std::strerror(errno));
  }
  bool written = false;
  try {
    written = write(temporary.string());
  } catch (const std::exception&) {
    written = false;
  }
  if (!written) {
    fs::remove(temporary, ec);
    fail_output(path, "cannot write: the writer failed (disk full?)");
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ec);
    fail_output(path, "cannot write: " + ec.message());
  }
}

}  // namespace io
}  // namespace cgal_policies
