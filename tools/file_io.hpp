#pragma once
// File helpers shared by the build tools (studentify, mutate) and the front end (frontend/):
// whole-file reads, lines, and writes that leave an unchanged file untouched so that builds stay
// incremental.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace fmbd::tools {

/// Reads the whole regular file `path` into `content`; false if it cannot.
inline bool read_file(const std::string& path, std::string& content) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  content = buffer.str();
  return !in.bad();
}

/// `path` made absolute against `base`, symbolic links of its existing part resolved, "." and
/// ".." removed (realpath -m).
inline std::string absolute_path(const std::string& path, const std::string& base) {
  std::filesystem::path full = path;
  if (full.is_relative()) full = std::filesystem::path(base) / full;
  return std::filesystem::weakly_canonical(full).string();
}

/// Writes `content` to `path` (through a temporary file and a rename) unless the file already
/// holds exactly that content. Creates missing parent folders. False on failure.
inline bool write_if_changed(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  std::string existing;
  if (read_file(path, existing) && existing == content) return true;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const std::string temp = path + ".tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out << content;
    out.close();
    if (!out) return false;
  }
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    return false;
  }
  return true;
}

}  // namespace fmbd::tools
