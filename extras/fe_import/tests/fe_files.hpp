#pragma once
// Files for the tests of the FE model import (extras/fe_import) and of the sparse path that reads
// them (extras/sparse): a temporary directory, and a small Matrix Market file with its matrix.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "fmbd/planar.hpp"

namespace fmbd::testing {

// A fresh directory under the system's temporary directory, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("fmbd-files-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // Writes `text` to the file `name` in this directory; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = path(name);
    std::ofstream(file) << text;
    return file;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline constexpr const char* kSmallSymmetric =
    "%%MatrixMarket matrix coordinate real symmetric\n"
    "% a 3 x 3 example\n"
    "\n"
    "3 3 4\n"
    "1 1 2.0\n"
    "2 1 -1.0\n"
    "2 2 +2.5e0\n"
    "3 3 1\n";

inline MatX small_symmetric() {
  MatX A(3, 3);
  A << 2.0, -1.0, 0.0, -1.0, 2.5, 0.0, 0.0, 0.0, 1.0;
  return A;
}

}  // namespace fmbd::testing
