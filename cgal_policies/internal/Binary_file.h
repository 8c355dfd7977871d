// A file of plain values in this machine's byte order, written and read back by the steps of one
// partitioned job (Partitioned_job_files.h), which run on machines of one kind. Every failure, a
// short file included, throws std::runtime_error naming the file.
#ifndef CGAL_POLICIES_INTERNAL_BINARY_FILE_H
#define CGAL_POLICIES_INTERNAL_BINARY_FILE_H

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace cgal_policies {
namespace internal {

class Binary_file {
 public:
  enum class Mode { write, read };

  Binary_file(std::filesystem::path path, Mode mode)
      : m_path(std::move(path)),
        m_file(std::fopen(m_path.c_str(), mode == Mode::write ? "wb" : "rb")) {
    if (!m_file) fail(mode == Mode::write ? "cannot create" : "cannot open");
  }

  Binary_file(const Binary_file&) = delete;
  Binary_file& operator=(const Binary_file&) = delete;

  ~Binary_file() {
    if (m_file) std::fclose(m_file);
  }

  template <class T>
  void put(const T& value) {
    put(&value, 1);
  }

  template <class T>
  void put(const T* values, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (count > 0 && std::fwrite(values, sizeof(T), count, m_file) != count) fail("cannot write");
  }

  template <class T>
  void put_vector(const std::vector<T>& values) {
    put(std::size_t(values.size()));
    put(values.data(), values.size());
  }

  void put_string(const std::string& s) {
    put(std::size_t(s.size()));
    put(s.data(), s.size());
  }

  template <class T>
  T get() {
    T value;
    get(&value, 1);
    return value;
  }

  template <class T>
  void get(T* values, std::size_t count) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (count > 0 && std::fread(values, sizeof(T), count, m_file) != count) fail("cannot read");
  }

  // A vector written by put_vector; its length is checked against what the file has left, so a
  // damaged file cannot ask for an absurd allocation.
  template <class T>
  std::vector<T> get_vector() {
    std::vector<T> values(checked_length(sizeof(T)));
    get(values.data(), values.size());
    return values;
  }

  std::string get_string() {
    std::string s(checked_length(1), '\0');
    get(s.data(), s.size());
    return s;
  }

  // Ends the writing: the file is complete on disk.
  void close() {
    const bool closed = std::fclose(m_file) == 0;
    m_file = nullptr;
    if (!closed) fail("cannot write");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(what + " the job file " + m_path.string());
  }

 private:
  std::size_t checked_length(std::size_t element_size) {
    const std::size_t length = get<std::size_t>();
    const long at = std::ftell(m_file);
    std::error_code error;
    const auto size = std::filesystem::file_size(m_path, error);
    if (error || at < 0 || length > (size - std::uintmax_t(at)) / element_size) fail("cannot read");
    return length;
  }

  std::filesystem::path m_path;
  std::FILE* m_file;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_BINARY_FILE_H
