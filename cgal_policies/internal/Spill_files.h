// The triangles of each cell of a streamed run (docs/scale.md), spilled to temporary files while
// the input streams past, and read back one cell at a time: a folder of its own under the system's
// temporary folder, one file per cell of 12-byte triangles (three vertex numbers), each followed by
// a fixed number of doubles of its own (its corners' values, when the input has them), removed with
// everything in it when the object goes, an exception or an interruption included.
#ifndef CGAL_POLICIES_INTERNAL_SPILL_FILES_H
#define CGAL_POLICIES_INTERNAL_SPILL_FILES_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace cgal_policies {
namespace internal {

class Spill_files {
 public:
  using Triangle = std::array<std::uint32_t, 3>;

  // The triangles of one cell and their doubles, `doubles()` per triangle, in order.
  struct Cell {
    std::vector<Triangle> triangles;
    std::vector<double> values;
  };

  explicit Spill_files(std::size_t cells, std::size_t doubles = 0)
      : m_doubles(doubles), m_counts(cells, 0) {
    namespace fs = std::filesystem;
    std::random_device random;
    for (int attempt = 0; m_folder.empty(); ++attempt) {
      const fs::path folder =
          fs::temp_directory_path() /
          ("cgal_policies_spill_" + std::to_string(random()) + "_" + std::to_string(random()));
      if (fs::create_directory(folder)) m_folder = folder;
      if (attempt == 100) throw std::runtime_error("cannot make a temporary folder");
    }
    m_files.assign(cells, nullptr);
    try {
      for (std::size_t c = 0; c < cells; ++c)
        if (!(m_files[c] = std::fopen(path(c).c_str(), "wb"))) fail("cannot create", c);
    } catch (...) {
      remove();
      throw;
    }
  }

  Spill_files(const Spill_files&) = delete;
  Spill_files& operator=(const Spill_files&) = delete;

  ~Spill_files() { remove(); }

  // Appends t and its doubles() values.
  void append(std::size_t cell, const Triangle& t, const double* values = nullptr) {
    if (std::fwrite(t.data(), sizeof t, 1, m_files[cell]) != 1 ||
        std::fwrite(values, sizeof(double), m_doubles, m_files[cell]) != m_doubles)
      fail("cannot write", cell);
    ++m_counts[cell];
  }

  // Ends the writing; every file is complete on disk.
  void close() {
    for (std::size_t c = 0; c < m_files.size(); ++c) {
      const bool closed = std::fclose(m_files[c]) == 0;
      m_files[c] = nullptr;
      if (!closed) fail("cannot write", c);
    }
    m_files.clear();
  }

  std::size_t size() const { return m_counts.size(); }
  std::size_t doubles() const { return m_doubles; }

  // The triangles of `cell` and their values, in the order they were appended; after close().
  Cell read(std::size_t cell) const {
    Cell read{std::vector<Triangle>(m_counts[cell]),
              std::vector<double>(m_counts[cell] * m_doubles)};
    std::FILE* file = std::fopen(path(cell).c_str(), "rb");
    const std::size_t n = read.triangles.size();
    bool complete = file != nullptr;
    if (complete && m_doubles == 0)  // most inputs: the triangles alone, in one read
      complete = std::fread(read.triangles.data(), sizeof(Triangle), n, file) == n;
    else
      for (std::size_t i = 0; complete && i < n; ++i)
        complete = std::fread(read.triangles[i].data(), sizeof(Triangle), 1, file) == 1 &&
                   std::fread(read.values.data() + i * m_doubles, sizeof(double), m_doubles,
                              file) == m_doubles;
    if (file) std::fclose(file);
    if (!complete) fail("cannot read", cell);
    return read;
  }

 private:
  std::filesystem::path path(std::size_t cell) const {
    return m_folder / ("cell_" + std::to_string(cell));
  }

  [[noreturn]] void fail(const char* what, std::size_t cell) const {
    throw std::runtime_error(std::string(what) + " the temporary file " + path(cell).string());
  }

  void remove() {
    for (std::FILE* file : m_files)
      if (file) std::fclose(file);
    m_files.clear();
    std::error_code ignored;
    std::filesystem::remove_all(m_folder, ignored);
  }

  std::size_t m_doubles;
  std::filesystem::path m_folder;
  std::vector<std::FILE*> m_files;
  std::vector<std::size_t> m_counts;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_SPILL_FILES_H
