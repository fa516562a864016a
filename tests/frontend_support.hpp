#pragma once
// What the front end's tests share (frontend.test.cpp, frontend_grade.test.cpp,
// frontend_files.test.cpp, grade_earlier.test.cpp): files read and written whole, a scratch
// folder per test, the message of a UsageError, and the tree a grading plan is made for.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grade_plan.hpp"
#include "options.hpp"

namespace fmbd::frontend_testing {

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A fresh folder for one test, removed with it.
struct Scratch {
  std::filesystem::path path;
  explicit Scratch(const std::string& name) {
    path = std::filesystem::temp_directory_path() / ("fmbd-frontend-" + name + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~Scratch() { std::filesystem::remove_all(path); }
};

// The message of the UsageError that `run` throws, or "" when it throws none.
template <typename Run>
std::string usage_error(Run run) {
  try {
    run();
  } catch (const frontend::UsageError& error) {
    return error.what();
  }
  return "";
}

// The facts of the tree "/t", built in "/t/build/ci", that a grading plan is made for: one's own
// tree or a submission's copy, `jobs` tests at once.
inline frontend::TreeFacts planned_tree(bool submission, int jobs) {
  frontend::TreeFacts facts;
  facts.tree = "/t";
  facts.build = "/t/build/ci";
  facts.submission = submission;
  facts.jobs = jobs;
  return facts;
}

}  // namespace fmbd::frontend_testing
