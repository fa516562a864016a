#include "commands.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>

#include "file_io.hpp"
#include "build.hpp"
#include "exit_status.hpp"
#include "classroom.hpp"
#include "demo.hpp"
#include "grade.hpp"
#include "release.hpp"
#include "hints.hpp"
#include "ids.hpp"
#include "inspect.hpp"
#include "jobs.hpp"
#include "layout.hpp"
#include "maintainer.hpp"
#include "problems.hpp"
#include "process.hpp"

namespace fmbd::frontend {

using tools::Child;
using tools::Command;
namespace fs = std::filesystem;
namespace {

// The module's hints.md when this copy has it: its path relative to the tree, or "".
std::string hints_file(const Context& context, const Module& module) {
  if (!module.hints || !fs::is_regular_file(fs::path(context.source_dir) / *module.hints)) return "";
  return *module.hints;
}

using fmbd::tools::absolute_path;

std::string dirname_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}


}  // namespace

const CommandSpec& hint_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "hint";
    s.options = {{"--reset", OptionKind::flag, "", "", "close the task's hints again"}};
    s.positional = "TASK";
    s.max_positionals = 1;
    s.too_many = "hint takes one task, e.g. ./workbook hint M01T3";
    s.help = {"The hints of a task (e.g. M01T3), one level more each time you ask: where the",
              "theory is, the shape of the result, the formula. Without TASK: every task and",
              "the levels you have opened. --reset closes a task's hints again."};
    return s;
  }();
  return spec;
}

const CommandSpec& handin_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "handin";
    s.options = {{"--out", OptionKind::value, "FILE.zip", "a file name", "the zip to write (default handin.zip)"}};
    s.help = {"Pack your exercise files and answers files (and nothing else) into a zip to upload",
              "(default handin.zip), as Gradescope and ./workbook grade --submission take it."};
    return s;
  }();
  return spec;
}

const std::vector<CommandEntry>& registry() {
  static const std::vector<CommandEntry> entries = {
      {&grade_command, Audience::students, &run_grade},
      {&problems_command, Audience::students, &run_problems},
      {&hint_command, Audience::students, &run_hint},
      {&handin_command, Audience::students, &run_handin},
      {&demo_command, Audience::students, &run_demo},
      {&classroom_command, Audience::students, &run_classroom},
      {&test_command, Audience::maintainers, &run_test},
      {&release_command, Audience::maintainers, &run_release},
      {&gradescope_command, Audience::maintainers, &run_gradescope},
      {&bench_command, Audience::maintainers, &run_bench},
      {&studentify_command, Audience::maintainers, &run_studentify},
      {&inspect_command, Audience::maintainers, &run_inspect},
  };
  return entries;
}

std::vector<const CommandSpec*> commands() {
  std::vector<const CommandSpec*> specs;
  for (const CommandEntry& entry : registry()) specs.push_back(&entry.spec());
  return specs;
}

std::string help_text(const std::string& source_dir, bool instructor) {
  const auto has = [&source_dir](const char* folder) { return fs::is_directory(fs::path(source_dir) / folder); };
  std::string text = "usage: ./workbook COMMAND [OPTIONS]\n\n";
  for (const CommandEntry& entry : registry()) {
    if (entry.audience == Audience::students || instructor) text += usage_text(entry.spec());
  }
  if (!instructor && has("extras") && has("solutions")) text += usage_text(bench_extras_command());
  const Jobs jobs = available_jobs();
  text += "  help  This text.\n\nCompiles and tests at once here: " + std::to_string(job_count(jobs)) + " (" +
          jobs.reason + "; FMBD_JOBS overrides).\n" + exit_status_help();
  return text;
}

int run_command(const std::string& name, const std::vector<std::string>& args, const Context& context) {
  for (const CommandEntry& entry : registry()) {
    if (entry.spec().name == name) return entry.run(args, context);
  }
  if (name == "help") {
    context.out << help_text(context.source_dir, context.manifest.instructor);
    return 0;
  }
  context.out.flush();
  std::cerr << "workbook: unknown command '" << name << "'\n\n" << help_text(context.source_dir, context.manifest.instructor);
  return kExitUsage;
}

int run_hint(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(hint_command(), args);
  if (print_usage_if_asked(options, hint_command(), context.out)) return 0;
  const bool reset = options.has("--reset");
  const fs::path opened_path = hints_opened_path(context.source_dir);

  std::vector<std::string> files;  // the ladder files of this copy, in module order
  for (const Module& module : context.manifest.modules) {
    const std::string file = hints_file(context, module);
    if (!file.empty()) files.push_back(file);
  }
  if (files.empty()) throw UsageError("this copy has no hints (its release carries none)");

  std::string opened;
  fmbd::tools::read_file(opened_path.string(), opened);  // none yet: nothing opened
  if (options.positionals.empty()) {
    std::vector<std::string> texts;
    for (const std::string& file : files) {
      std::string text;
      fmbd::tools::read_file((fs::path(context.source_dir) / file).string(), text);
      texts.push_back(text);
    }
    context.out << "Hints, opened one level at a time with ./workbook hint TASK (--reset closes them again):\n";
    for (const hints::Ladder& ladder : hints::list_ladders(texts)) {
      char line[128];
      std::snprintf(line, sizeof line, "  %-7s %d of %d level%s opened\n", ladder.task.c_str(),
                    hints::opened_level(opened, ladder.task), ladder.levels, ladder.levels == 1 ? "" : "s");
      context.out << line;
    }
    return 0;
  }

  const WrittenTask task = parse_task_id(options.positionals.front(), "hint");
  std::string file;
  for (const Module& module : context.manifest.modules) {
    if (module.number == task.task.module && file.empty()) file = hints_file(context, module);
  }
  if (file.empty()) {
    throw UsageError("hint: this copy has no hints for module " + std::to_string(task.task.module) +
                     " (./workbook hint lists the tasks it has)");
  }
  std::string text;
  fmbd::tools::read_file((fs::path(context.source_dir) / file).string(), text);
  const int levels = hints::levels_of(text, task.id);
  if (levels <= 0) {
    std::string tasks;
    for (const std::string& name : hints::task_headings(text)) tasks += name + " ";
    throw UsageError("hint: " + file + " has no task " + task.id + "; its tasks: " + tasks);
  }

  const int seen = hints::opened_level(opened, task.id);
  const int next = reset ? 0 : std::min(seen + 1, levels);
  fs::create_directories(opened_path.parent_path());
  const fs::path temporary = opened_path.string() + ".tmp";
  {
    std::ofstream write(temporary, std::ios::binary | std::ios::trunc);
    write << hints::with_opened(opened, task.id, next);
    if (!write.flush()) throw UsageError("cannot write " + temporary.string());
  }
  fs::rename(temporary, opened_path);
  if (next == 0) {
    context.out << "workbook: the hints of " << task.id << " are closed again\n";
    return 0;
  }

  context.out << hints::render(text, task.id, next) << "\n";
  const std::string folder = dirname_of(file);
  if (next < levels) {
    context.out << "Level " << next << " of " << levels << ". Still stuck? ./workbook hint " << task.id
                << " opens level " << next + 1 << ".\n";
  } else if (hints::ceiling(text)) {
    context.out << "Level " << next << " is the last hint of this release. The README (" << folder
                << "/README.md) has the theory; your instructor the rest.\n";
  } else {
    context.out << "That is the whole ladder (" << levels << " levels). The README (" << folder
                << "/README.md) derives it.\n";
  }
  return 0;
}

int run_handin(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(handin_command(), args);
  if (print_usage_if_asked(options, handin_command(), context.out)) return 0;
  const std::string out = options.has("--out") ? absolute_path(options.value("--out"), context.source_dir)
                                               : context.source_dir + "/handin.zip";
  if (out.size() < 4 || out.compare(out.size() - 4, 4, ".zip") != 0) throw UsageError("handin needs --out FILE.zip");

  std::vector<std::string> files;
  std::vector<std::string> missing;  // of the module folders this copy has
  for (const Module& module : context.manifest.modules) {
    for (const std::string& file : module.exercises) {
      if (fs::is_regular_file(fs::path(context.source_dir) / file)) {
        files.push_back(file);
      } else if (fs::is_directory(fs::path(context.source_dir) / module.folder)) {
        missing.push_back(file);
      }
    }
  }
  for (const GradedItem& item : context.manifest.graded) {
    for (const std::string& file : item.inputs) {  // the answers of the tutorial problems
      if (fs::is_regular_file(fs::path(context.source_dir) / file)) files.push_back(file);
    }
  }
  if (files.empty()) throw UsageError("no exercise files here (moduleNN_*/src/*.cpp); run handin in your workbook");
  std::sort(files.begin(), files.end());
  if (!missing.empty()) {
    context.out << "workbook: handin: not in this copy, so not in the zip (their tasks score 0):";
    for (const std::string& file : missing) context.out << " " << file;
    context.out << "\n";
  }

  fs::create_directories(fs::path(out).parent_path());
  fs::remove(out);
  std::vector<std::string> command = {cmake_program(), "-E", "tar", "cf", out, "--format=zip", "--"};
  command.insert(command.end(), files.begin(), files.end());
  context.out.flush();
  const int status = run(Command{command, context.source_dir});
  if (status != 0) throw std::runtime_error("handin: packing " + out + " failed (cmake -E tar, status " + std::to_string(status) + ")");
  context.out << "workbook: wrote " << out << " (" << files.size()
              << " exercise files); upload it, or grade it: ./workbook grade --submission DIR (unzipped)\n";
  return 0;
}

}  // namespace fmbd::frontend
