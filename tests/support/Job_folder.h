// A folder of its own for a partitioned job's files, under the test's temporary folder, removed
// with what it holds.
#ifndef CGAL_POLICIES_TESTS_JOB_FOLDER_H
#define CGAL_POLICIES_TESTS_JOB_FOLDER_H

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

class Job_folder {
 public:
  explicit Job_folder(const std::string& name)
      : m_path(std::filesystem::path(testing::TempDir()) /
               ("job_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~Job_folder() { std::filesystem::remove_all(m_path); }
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
};

#endif  // CGAL_POLICIES_TESTS_JOB_FOLDER_H
