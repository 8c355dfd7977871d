#include "atomic_write.h"

#include "Io_error.h"
#include "Removed_on_interrupt.h"

#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

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

// A temporary beside `path` (whose folder must exist), with a name of its own that keeps the
// extension, since writers pick the format from it.
fs::path temporary_of(const std::string& path) {
  const fs::path target(path);
  return existing_output_folder(path) / ("." + target.stem().string() + ".tmp-" +
                                         std::to_string(::getpid()) + target.extension().string());
}

}  // namespace

void check_output_folder(const std::string& path) { existing_output_folder(path); }

void write_atomically(const std::string& path,
                      const std::function<bool(const std::string& temporary)>& write) {
  write_all_atomically(
      {path}, [&write](std::size_t, const std::string& temporary) { return write(temporary); });
}

void write_all_atomically(
    const std::vector<std::string>& paths,
    const std::function<bool(std::size_t index, const std::string& temporary)>& write) {
  if (paths.size() > kMaxFilesWrittenAtOnce)
    throw std::logic_error("write_all_atomically: more files than kMaxFilesWrittenAtOnce");
  std::vector<fs::path> temporaries;
  for (const std::string& path : paths) temporaries.push_back(temporary_of(path));
  std::error_code ec;
  const auto fail_all = [&](std::size_t i, const std::string& cause) {
    for (const fs::path& temporary : temporaries) fs::remove(temporary, ec);
    fail_output(paths[i], "cannot write: " + cause);
  };
  // Each held from before any file exists (a guard that cannot be made throws with none written)
  // until after its file is renamed: no moment without a guard.
  std::vector<std::unique_ptr<Removed_on_interrupt>> temporary_guards;
  for (const fs::path& temporary : temporaries)
    temporary_guards.push_back(std::make_unique<Removed_on_interrupt>(temporary.string()));
  for (std::size_t i = 0; i < paths.size(); ++i) {
    {
      std::ofstream probe(temporaries[i]);
      if (!probe) fail_all(i, std::strerror(errno));
    }
    bool written = false;
    try {
      written = write(i, temporaries[i].string());
    } catch (const std::exception&) {
      written = false;
    }
    if (!written) fail_all(i, "the writer failed (disk full?)");
  }
  // One file is the old one or the new one. Of several, each one renamed is removed again by an
  // interrupt until the last is in place, so that they land all together or not at all.
  std::vector<std::unique_ptr<Removed_on_interrupt>> renamed_guards;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (paths.size() > 1)
      renamed_guards.push_back(std::make_unique<Removed_on_interrupt>(paths[i]));
    fs::rename(temporaries[i], paths[i], ec);
    if (ec) {
      const std::string cause = ec.message();
      for (std::size_t renamed = 0; renamed < i; ++renamed) fs::remove(paths[renamed], ec);
      fail_all(i, cause);
    }
    temporary_guards[i].reset();
  }
}

}  // namespace io
}  // namespace cgal_policies
