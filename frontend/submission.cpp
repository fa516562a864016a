#include "submission.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <ostream>
#include <set>

#include "build.hpp"
#include "file_io.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

// Writes `content` to `path` unless it holds exactly that: a fresh time for what changed only.
void update(const fs::path& source, const fs::path& target) {
  std::string content;
  std::string existing;
  if (!tools::read_file(source.string(), content)) return;
  if (tools::read_file(target.string(), existing) && existing == content) return;
  if (!tools::write_if_changed(target.string(), content)) {
    throw BuildError("cannot write " + target.string());
  }
  std::error_code error;
  fs::permissions(target, fs::status(source, error).permissions(), error);
}

// Every regular file below `folder` (relative, in path order), but those under `skip` (relative
// folders of the top level).
std::vector<std::string> files_below(const fs::path& folder, const std::set<std::string>& skip) {
  std::vector<std::string> files;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(folder, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    const std::string relative = it->path().lexically_relative(folder).generic_string();
    if (it.depth() == 0 && it->is_directory() && skip.count(relative)) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) files.push_back(relative);
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string base_name(const std::string& path) { return path.substr(path.rfind('/') + 1); }

}  // namespace

SubmissionLock::SubmissionLock(const std::string& root) {
  const std::string path = root + "/build/submission.lock";
  std::error_code error;
  fs::create_directories(root + "/build", error);
  if (fs::is_directory(path, error)) fs::remove_all(path, error);  // the lock of an earlier version
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw BuildError("cannot lock " + path);
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    std::string holder;
    tools::read_file(path, holder);
    holder.erase(std::remove(holder.begin(), holder.end(), '\n'), holder.end());
    ::close(fd_);
    fd_ = -1;
    throw BuildError("another grading of submissions (process " + (holder.empty() ? "?" : holder) +
                     ") is using this copy; wait for it to end, or grade in another copy");
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The number is for the message of a second grading only; the lock holds without it.
  }
}

SubmissionLock::~SubmissionLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

std::string submission_tree(const std::string& root) { return root + "/build/submission/tree"; }

std::string prepare_submission(const std::string& root, const std::string& submission, const Manifest& manifest,
                               const std::vector<int>& modules, std::ostream& out) {
  const fs::path tree = submission_tree(root);
  std::set<std::string> exercises;  // and the other files of the student's (answers)
  for (const Module& module : manifest.modules) exercises.insert(module.exercises.begin(), module.exercises.end());
  for (const GradedItem& item : manifest.graded) exercises.insert(item.inputs.begin(), item.inputs.end());

  // Everything but the exercise files, the builds and the repository.
  for (const std::string& file : files_below(root, {"build", "out", ".git"})) {
    if (!exercises.count(file)) update(fs::path(root) / file, tree / file);
  }

  const std::vector<std::string> submitted = files_below(submission, {"build"});
  std::set<std::string> found_names;
  std::string missing;
  for (const Module& module : manifest.modules) {
    const bool selected = modules.empty() || std::count(modules.begin(), modules.end(), module.number) > 0;
    for (const std::string& file : module.exercises) {
      const std::string name = base_name(file);
      fs::path source;
      if (std::binary_search(submitted.begin(), submitted.end(), file)) {
        source = fs::path(submission) / file;
      } else {
        const auto match = std::find_if(submitted.begin(), submitted.end(),
                                        [&name](const std::string& path) { return base_name(path) == name; });
        if (match != submitted.end()) source = fs::path(submission) / *match;
      }
      if (source.empty()) {
        if (selected) missing += " " + file;
        source = fs::path(root) / file;  // the skeleton
      } else {
        found_names.insert(name);
      }
      update(source, tree / file);
    }
  }
  // The graded items' inputs (answers files): at their path, or at it below a folder of the
  // submission (an unpacked handin.zip in a folder of its own). None: the item scores 0, as unanswered.
  std::set<std::string> found_inputs;
  for (const GradedItem& item : manifest.graded) {
    const bool selected = modules.empty() || std::count(modules.begin(), modules.end(), item.module) > 0;
    for (const std::string& file : item.inputs) {
      const auto match = std::find_if(submitted.begin(), submitted.end(), [&file](const std::string& path) {
        return path == file || tools::ends_with(path, "/" + file);
      });
      std::error_code error;
      if (match == submitted.end()) {
        fs::remove(tree / file, error);
        if (selected) missing += " " + file;
        continue;
      }
      found_inputs.insert(*match);
      update(fs::path(submission) / *match, tree / file);
    }
  }
  std::string ignored;
  std::size_t extras = 0;
  for (const std::string& path : submitted) {
    if (found_names.count(base_name(path)) || found_inputs.count(path)) continue;
    if (++extras <= 10) ignored += " " + path;
  }
  if (extras > 10) ignored += " ... (" + std::to_string(extras) + " files in all)";
  if (!missing.empty()) out << "workbook: missing from the submission (their tasks score 0):" << missing << "\n";
  if (!ignored.empty()) out << "workbook: ignored (not exercise files):" << ignored << "\n";
  return tree.string();
}

}  // namespace fmbd::frontend
