#include "classroom.hpp"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string_view>

#include "build.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "manifest.hpp"
#include "process.hpp"
#include "strings.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

// A task of the workflow: "M01 T2 4" from the driver.
struct Task {
  std::string module;
  std::string task;
  std::string points;
  std::string id() const {  // "m01-t2"
    std::string text = module + "-" + task;
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  }
};

bool has_hidden_tests(const std::string& root) {
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(root + "/autograder", error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (it->path().extension() == ".cpp" && it->path().parent_path().filename() == "hidden") return true;
  }
  return false;
}

}  // namespace

const CommandSpec& classroom_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "classroom";
    s.options = {{"--out", OptionKind::value, "FILE", "a file name", "the workflow file"}};
    s.help = {"In a student release: write the GitHub Classroom workflow (default",
              ".github/workflows/classroom.yml), one step per task worth its visible points."};
    return s;
  }();
  return spec;
}

namespace {

// The tasks of the visible tests, with their points, as the grade driver lists them from the
// built programs of the items in the workflow (their capability classroom). The others, such as
// the tutorial problems, are graded by the instructor's grader: a release checks only their
// format (their values need the reference, and the student's identity, which the workflow has not).
std::vector<Task> classroom_tasks(const std::string& build, const Manifest& manifest) {
  if (!build_target(build, "fmbd-grade", build + "/fmbd-grade.build.log")) {
    throw BuildError("building the grade driver failed");
  }
  std::vector<std::string> argv{manifest.grade_driver, "--list-tasks"};
  for (const GradedItem& item : manifest.graded) {
    if (!item.classroom) continue;
    const std::string log = build + "/" + item.target + ".build.log";
    if (!build_target(build, item.target, log)) {
      const Module* module = manifest.module(item.module);
      throw BuildError("the tests of " + (module ? module->folder : item.id) + " do not build (" + log +
                       "); a release builds as shipped");
    }
    argv.push_back(item.program);
  }
  int status = 0;
  const std::string listed = tools::capture(tools::Command(argv), status);
  if (status != 0) throw BuildError("listing the tasks failed");
  std::vector<Task> tasks;
  std::istringstream lines(listed);
  for (Task task; lines >> task.module >> task.task >> task.points;) tasks.push_back(task);
  return tasks;
}

// The workflow: install the packages, build every module, then one step per task and the reporter.
std::string workflow_yaml(const std::vector<Task>& tasks, const std::string& packages) {
  std::ostringstream yaml;
  yaml << "# GitHub Classroom autograding, written by ./workbook classroom: one step per task, worth the\n"
          "# points of its visible tests when they all pass (the command's exit status).\n"
          "name: Autograding Tests\n"
          "on: [push, repository_dispatch, workflow_dispatch]\n"
          "permissions:\n"
          "  checks: write\n"
          "  actions: read\n"
          "  contents: read\n"
          "jobs:\n"
          "  run-autograding-tests:\n"
          "    runs-on: ubuntu-22.04\n"
          "    if: github.actor != 'github-classroom[bot]'\n"
          "    steps:\n"
          "      - name: Checkout code\n"
          "        uses: actions/checkout@v4\n"
          "      - name: Install the build packages\n"
          "        run: sudo apt-get update -qq && sudo apt-get install -y -qq --no-install-recommends "
       << packages
       << "\n"
          "      - name: Build every module\n"
          "        run: ./workbook grade\n";
  for (const Task& task : tasks) {
    yaml << "      - name: " << task.module << " " << task.task << "\n"
         << "        id: " << task.id() << "\n"
         << "        uses: classroom-resources/autograding-command-grader@v1\n"
         << "        with:\n"
         << "          test-name: " << task.module << " " << task.task << "\n"
         << "          command: ./workbook grade --task " << task.module << task.task << " --strict\n"
         << "          timeout: 10\n"
         << "          max-score: " << task.points << "\n";
  }
  yaml << "      - name: Autograding Reporter\n"
       << "        uses: classroom-resources/autograding-grading-reporter@v1\n"
       << "        env:\n";
  std::string runners;
  for (const Task& task : tasks) {
    std::string upper = task.id();
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    yaml << "          " << upper << "_RESULTS: \"${{steps." << task.id() << ".outputs.result}}\"\n";
    runners += (runners.empty() ? "" : ",") + task.id();
  }
  yaml << "        with:\n"
       << "          runners: " << runners << "\n";
  return yaml.str();
}

}  // namespace

int run_classroom(const std::vector<std::string>& args, const Context& context) {
  const std::string& root = context.source_dir;
  const Manifest& manifest = context.manifest;
  std::ostream& out = context.out;
  const char* build_packages = std::getenv("FMBD_BUILD_PACKAGES");
  const std::string packages = build_packages != nullptr ? build_packages : "";
  const ParsedOptions options = parse_options(classroom_command(), args);
  if (print_usage_if_asked(options, classroom_command(), out)) return 0;
  const std::string path = options.has("--out") ? tools::absolute_path(options.value("--out"), fs::current_path().string())
                                                : root + "/.github/workflows/classroom.yml";
  if (has_hidden_tests(root)) {
    throw UsageError("classroom writes the workflow of a student copy; run it in a release (./workbook release), "
                     "whose tests are all visible");
  }
  const std::vector<Task> tasks = classroom_tasks(manifest.build_dir, manifest);
  if (!tools::write_if_changed(path, workflow_yaml(tasks, packages))) throw std::runtime_error("cannot write " + path);
  double points = 0;
  for (const Task& task : tasks) points += std::atof(task.points.c_str());
  std::ostringstream total;
  total << points;
  out << "workbook: wrote " << path << " (" << tasks.size() << " tasks, " << total.str() << " points)\n";
  return 0;
}

std::vector<ClassroomStep> parse_classroom_steps(const std::string& text, const std::string& origin) {
  constexpr std::string_view kGrader = "uses: classroom-resources/autograding-command-grader@v1";
  std::vector<ClassroomStep> steps;
  std::optional<ClassroomStep> step;  // the step being read, once it is a command grader's
  std::string id;
  bool max_score = false;
  const auto finish = [&](std::size_t line) {
    if (!step) return;
    if (step->id.empty() || step->command.empty() || !max_score) {
      throw StepFailed(origin + ": the step before line " + std::to_string(line) +
                       " lacks its id, command or max-score");
    }
    steps.push_back(*step);
  };
  const std::vector<std::string> lines = tools::split_lines(text);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string line = tools::trim(lines[n]);
    const auto value = [&line](std::string_view key) { return tools::trim(line.substr(key.size())); };
    if (tools::starts_with(line, "- name:")) {
      finish(n + 1);
      step.reset();
      id.clear();
      max_score = false;
    } else if (tools::starts_with(line, "id:")) {
      id = value("id:");
    } else if (line == kGrader) {
      step = ClassroomStep{id, "", 0};
    } else if (step && tools::starts_with(line, "command:")) {
      step->command = value("command:");
    } else if (step && tools::starts_with(line, "max-score:")) {
      const std::string number = value("max-score:");
      char* end = nullptr;
      step->max_score = std::strtod(number.c_str(), &end);
      if (number.empty() || *end != '\0') {
        throw StepFailed(origin + ": line " + std::to_string(n + 1) + ": max-score '" + number + "' is not a number");
      }
      max_score = true;
    }
  }
  finish(lines.size() + 1);
  return steps;
}

}  // namespace fmbd::frontend
