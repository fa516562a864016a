#include "build.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

#include "file_io.hpp"
#include "json.hpp"
#include "layout.hpp"
#include "process.hpp"
#include "strings.hpp"

namespace fmbd::frontend {

using tools::Child;
using tools::Command;
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::optional<fs::file_time_type> modified(const std::string& path) {
  std::error_code error;
  const auto time = fs::last_write_time(path, error);
  if (error) return std::nullopt;
  return time;
}

using tools::split_lines;
using tools::starts_with;

std::string read_text(const std::string& path) {
  std::string text;
  tools::read_file(path, text);
  return text;
}

// Ninja's last status "[DONE/TOTAL] " at the start of a line of `log` (NINJA_STATUS below).
std::string last_steps(const std::string& log) {
  std::string steps;
  for (const std::string& line : split_lines(read_text(log))) {
    if (line.empty() || line[0] != '[') continue;
    const auto slash = line.find('/');
    const auto close = line.find("] ");
    if (slash == std::string::npos || close == std::string::npos || slash > close) continue;
    // Compiling and linking steps only: CMake's own checks count steps too.
    const std::string step = line.substr(close + 2);
    if (!starts_with(step, "Building") && !starts_with(step, "Linking")) continue;
    const std::string done = line.substr(1, slash - 1);
    const std::string total = line.substr(slash + 1, close - slash - 1);
    if (tools::is_digits(done) && tools::is_digits(total)) steps = done + " of " + total;
  }
  return steps;
}

// The objects of the exercise files, from compile_commands.json: source (absolute) -> object.
std::map<std::string, std::string> exercise_objects(const std::string& build, const std::vector<std::string>& exercises) {
  std::map<std::string, std::string> objects;
  json::Value commands;
  try {
    commands = json::parse(read_text(build + "/compile_commands.json"));
  } catch (const std::exception&) {
    return objects;  // no record: no warnings recorded, the build itself is not affected
  }
  if (!commands.is_array()) return objects;
  for (const json::Value& entry : commands) {
    const auto text = [&entry](const char* key) -> std::string {  // a member that is a string, or ""
      const auto member = entry.find(key);  // end() where the entry is not an object
      return member != entry.end() && member->is_string() ? member->get<std::string>() : "";
    };
    const std::string file = text("file");
    const std::string directory = text("directory");
    if (file.empty() || directory.empty()) continue;
    if (std::find(exercises.begin(), exercises.end(), file) == exercises.end()) continue;
    // The object: "output" where CMake writes it, else the compiler's -o argument.
    std::string path = text("output");
    if (path.empty()) {
      const std::string command = text("command");
      const std::size_t o = command.find(" -o ");
      if (o != std::string::npos) path = command.substr(o + 4, command.find(' ', o + 4) - (o + 4));
    }
    if (path.empty()) continue;
    fs::path object(path);
    if (object.is_relative()) object = fs::path(directory) / object;
    objects[file] = object.string();
  }
  return objects;
}

// build/warnings/NAME.txt for the exercise file `relative` ("module01_kinematics/src/dof.cpp").
std::string warnings_file(const std::string& build, std::string relative) {
  std::replace(relative.begin(), relative.end(), '/', '+');
  return build + "/warnings/" + relative + ".txt";
}

// The warnings of `relative` in `log`: each "RELATIVE:LINE:COLUMN: warning: ..." once, from
// where its path starts (the compiler writes it absolute).
std::string warnings_of(const std::vector<std::string>& log, const std::string& relative) {
  std::string text;
  for (const std::string& line : log) {
    for (std::size_t at = line.find(relative); at != std::string::npos; at = line.find(relative, at + 1)) {
      if (at > 0 && line[at - 1] != '/') continue;
      std::size_t i = at + relative.size();
      const auto number = [&]() {
        if (i >= line.size() || line[i] != ':') return false;
        const std::size_t first = ++i;
        while (i < line.size() && line[i] >= '0' && line[i] <= '9') ++i;
        return i > first;
      };
      if (!number() || !number()) continue;
      if (line.compare(i, 11, ": warning: ") != 0) continue;
      const std::string warning = line.substr(at) + "\n";
      if (text.find(warning) == std::string::npos) text += warning;
      break;
    }
  }
  return text;
}

}  // namespace

std::string cmake_program() {
  const std::string cmake = FMBD_CMAKE_COMMAND;
  return ::access(cmake.c_str(), X_OK) == 0 ? cmake : "cmake";
}

std::string ctest_program() {
  const std::string cmake = cmake_program();
  const std::size_t slash = cmake.rfind('/');
  const std::string ctest = slash == std::string::npos ? "" : cmake.substr(0, slash + 1) + "ctest";
  return !ctest.empty() && ::access(ctest.c_str(), X_OK) == 0 ? ctest : "ctest";
}

std::string preset_build_dir(const std::string& tree, const std::string& preset) {
  return BuildLayout::of_preset(tree, preset).dir;
}

void configure(const std::string& tree, const std::string& preset, std::ostream& out) {
  const BuildLayout layout = BuildLayout::of_preset(tree, preset);
  const std::string& build = layout.dir;
  std::string home;
  for (const std::string& line : split_lines(read_text(build + "/CMakeCache.txt"))) {
    if (starts_with(line, "CMAKE_HOME_DIRECTORY:INTERNAL=")) home = line.substr(30);
  }
  std::error_code error;
  if (!home.empty() && !fs::equivalent(home, tree, error)) {
    out << "workbook: build/" << preset << " was configured for " << home << "; this copy is " << tree
        << ": configuring it afresh\n";
    fs::remove_all(build, error);
  }
  if (fs::exists(build + "/build.ninja") && fs::exists(layout.course_json())) return;
  if (fs::exists(build + "/build.ninja")) {  // configured before the manifest existed: once more
    if (run(Command{{cmake_program(), build}, tree, layout.configure_log()}) == 0) return;
  }
  fs::create_directories(build, error);
  const std::string shown = BuildLayout::of_preset(preset).configure_log();  // as the messages name it
  out << "workbook: configuring build/" << preset << " (the first time only; its log: " << shown << ")\n"
      << std::flush;
  const std::string log = layout.configure_log();
  if (run(Command{{cmake_program(), "--preset", preset}, tree, log}) != 0) {
    out << read_text(log);
    throw BuildError("configuring preset '" + preset + "' failed (log above, also in " + shown + ")");
  }
}

void build_with_progress(const std::string& build, const std::string& log, const std::vector<std::string>& targets,
                         const std::vector<Watched>& watched, const std::string& tree,
                         const std::vector<std::string>& exercises, std::ostream& out) {
  const auto began = Clock::now();
  const auto seconds = [&began]() {
    return static_cast<long>(std::chrono::duration_cast<std::chrono::seconds>(Clock::now() - began).count());
  };
  const auto say = [&](const std::string& line) {
    char elapsed[32];
    std::snprintf(elapsed, sizeof elapsed, "[%4ld s] ", seconds());
    out << "workbook: " << elapsed << line << "\n" << std::flush;
  };
  // What the build has before: an output is reported when its time changes.
  std::vector<std::optional<fs::file_time_type>> before;
  for (const Watched& output : watched) before.push_back(modified(output.path));
  const std::map<std::string, std::string> objects = exercise_objects(build, exercises);
  std::map<std::string, std::optional<fs::file_time_type>> objects_before;
  for (const auto& [source, object] : objects) objects_before[source] = modified(object);

  // A first build: nothing it watches exists yet (the front end itself may have been built).
  const bool first = std::none_of(before.begin(), before.end(), [](const auto& time) { return time.has_value(); });
  Command command{{cmake_program(), "--build", build, "--target"}, "", log};
  command.argv.insert(command.argv.end(), targets.begin(), targets.end());
  command.argv.insert(command.argv.end(), {"--", "-k", "0"});
  command.environment = {{"NINJA_STATUS", "[%f/%t] "}};
  Child builder = start(command);

  std::vector<bool> reported(watched.size(), false);
  const auto report_outputs = [&]() {
    for (std::size_t i = 0; i < watched.size(); ++i) {
      if (reported[i]) continue;
      const auto now = modified(watched[i].path);
      if (now && now != before[i]) {
        reported[i] = true;
        say(watched[i].message);
      }
    }
  };
  bool announced = false;
  auto said = Clock::now();
  while (!poll(builder)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const std::size_t count = static_cast<std::size_t>(std::count(reported.begin(), reported.end(), true));
    report_outputs();
    if (static_cast<std::size_t>(std::count(reported.begin(), reported.end(), true)) != count) said = Clock::now();
    if (!announced && (first || seconds() >= 5)) {
      out << "workbook: building" << (first ? " (a first build takes minutes)" : "") << "; the compiler's log: "
          << log << "\n" << std::flush;
      announced = true;
    }
    if (Clock::now() - said >= std::chrono::seconds(10)) {
      const std::string steps = last_steps(log);
      if (!steps.empty()) say("building: " + steps + " steps done");
      said = Clock::now();
    }
  }
  report_outputs();

  // The warnings of each exercise file compiled now replace its record (none: emptied).
  std::error_code error;
  fs::create_directories(build + "/warnings", error);
  const std::vector<std::string> lines = split_lines(read_text(log));
  for (const auto& [source, object] : objects) {
    const auto now = modified(object);
    if (!now || now == objects_before[source]) continue;
    const std::string relative = fs::path(source).lexically_relative(tree).generic_string();
    if (tools::ends_with(relative, "_given.cpp")) continue;
    tools::write_if_changed(warnings_file(build, relative), warnings_of(lines, relative));
  }
}

bool build_target(const std::string& build, const std::string& target, const std::string& log) {
  return run(Command{{cmake_program(), "--build", build, "--target", target}, "", log}) == 0;
}

void show_warnings(const std::string& build, std::ostream& out) {
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(build + "/warnings", error)) {
    if (entry.path().extension() == ".txt") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::string warnings;
  for (const std::string& file : files) warnings += read_text(file);
  if (warnings.empty()) return;
  out << "workbook: warnings in your exercise files (they compile, but each points at a likely mistake):\n";
  for (const std::string& line : split_lines(warnings)) out << "  " << line << "\n";
}

std::string first_errors(const std::string& log, const std::string& folder, const std::vector<std::string>& roots) {
  const auto relative = [&roots](std::string line) {
    for (const std::string& root : roots) {
      const std::string prefix = root + "/";
      for (std::size_t at; (at = line.find(prefix)) != std::string::npos;) line.erase(at, prefix.size());
    }
    for (std::size_t at; (at = line.find("../")) != std::string::npos;) line.erase(at, 3);
    return line;
  };
  const auto is_error = [](const std::string& line) {
    return line.find(": error:") != std::string::npos || line.find(": fatal error:") != std::string::npos ||
           line.find("undefined reference") != std::string::npos;
  };
  const std::vector<std::string> lines = split_lines(read_text(log));
  std::string text;
  const auto first = std::find_if(lines.begin(), lines.end(), is_error);
  if (first != lines.end()) {
    const std::string line = relative(*first);
    if (starts_with(line, "module")) {
      const std::string culprit = line.substr(0, line.find('/'));
      if (culprit != folder && culprit.size() > 9 && culprit[6] >= '0' && culprit[6] <= '9') {
        text += "the first error is in " + culprit + ", which " + folder + " builds on: fix it there\n";
      }
    }
  }
  // Each error with the three lines after it (the compiler's notes and the code), as grep -A 3.
  std::vector<bool> keep(lines.size(), false);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (is_error(lines[i]) || lines[i].find("multiple definition") != std::string::npos) {
      for (std::size_t j = i; j < lines.size() && j <= i + 3; ++j) keep[j] = true;
    }
  }
  int shown = 0;
  for (std::size_t i = 0; i < lines.size() && shown < 40; ++i) {
    if (!keep[i] || starts_with(lines[i], "ninja: ") || starts_with(lines[i], "FAILED: ")) continue;
    text += relative(lines[i]) + "\n";
    ++shown;
  }
  if (first == lines.end()) {
    const std::size_t from = lines.size() > 20 ? lines.size() - 20 : 0;
    for (std::size_t i = from; i < lines.size(); ++i) text += lines[i] + "\n";
  }
  return text;
}

}  // namespace fmbd::frontend
