#include "grade.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "build.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "grade_batch.hpp"
#include "grade_build.hpp"
#include "grade_plan.hpp"
#include "ids.hpp"
#include "jobs.hpp"
#include "layout.hpp"
#include "manifest.hpp"
#include "problems.hpp"
#include "process.hpp"
#include "../autograder/driver/report.hpp"  // results.json's one writer (fmbd_report)
#include "strings.hpp"
#include "submission.hpp"
#include "tables.hpp"
#include "text.hpp"

namespace fmbd::frontend {

using tools::Child;
using tools::Command;
namespace {

namespace fs = std::filesystem;

using tools::is_digits;

// `path` absolute, "." and ".." removed, symbolic links of its existing part resolved (realpath -m).
std::string resolve(const std::string& path) { return tools::absolute_path(path, fs::current_path().string()); }

// A temporary folder below build/ for an unpacked zip, removed when the grading ends.
class UnpackedZip {
 public:
  UnpackedZip(const std::string& root, const std::string& zip) {
    fs::create_directories(root + "/build");
    std::string pattern = root + "/build/unpacked.XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("--submission: cannot unpack '" + zip + "'");
    folder_ = pattern;
    if (run(Command{{cmake_program(), "-E", "tar", "xf", resolve(zip)}, folder_, folder_ + ".log"}) != 0) {
      throw UsageError("--submission: cannot unpack '" + zip + "'");
    }
  }
  ~UnpackedZip() {
    std::error_code error;
    fs::remove_all(folder_, error);
    fs::remove(folder_ + ".log", error);
  }
  UnpackedZip(const UnpackedZip&) = delete;
  UnpackedZip& operator=(const UnpackedZip&) = delete;
  const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

GradeOptions check(const ParsedOptions& parsed) {
  GradeOptions o;
  o.solutions = parsed.has("--solutions");
  o.own_earlier = parsed.has("--own-earlier");
  o.reference_earlier = parsed.has("--reference-earlier");
  o.resume = parsed.has("--resume");
  o.driver.strict = parsed.has("--strict");
  if (parsed.has("--submission")) {
    o.submission = parsed.value("--submission");
    const bool zip = o.submission.size() >= 4 && o.submission.compare(o.submission.size() - 4, 4, ".zip") == 0;
    if (zip && !fs::is_regular_file(o.submission)) throw UsageError("--submission: no file '" + o.submission + "'");
    if (!zip && !fs::is_directory(o.submission)) {
      throw UsageError("--submission: '" + o.submission + "' is not a directory or a zip");
    }
  }
  if (parsed.has("--student")) {
    o.student = tools::trim(parsed.value("--student"));
    if (o.student.empty()) throw UsageError("--student needs a name");
  }
  if (parsed.has("--gradescope-metadata")) {
    if (parsed.has("--student")) throw UsageError("--student and --gradescope-metadata exclude each other");
    o.student = gradescope_identity(resolve(parsed.value("--gradescope-metadata")));
  }
  if (parsed.has("--submissions")) {
    o.submissions = parsed.value("--submissions");
    if (!fs::is_directory(o.submissions)) throw UsageError("--submissions: '" + o.submissions + "' is not a directory");
    o.submissions = resolve(o.submissions);
  }
  if (parsed.has("--out")) o.out = resolve(parsed.value("--out"));
  for (const std::string& module : parsed.all("--module")) {
    if (!is_digits(module)) throw UsageError("--module needs a number, got '" + module + "'");
    o.modules.push_back(std::stoi(module.substr(std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(module.size()) - 9))));
    o.driver.modules.push_back(module);
  }
  for (const std::string& text : parsed.all("--task")) {
    const std::optional<WrittenTask> task = task_id(text);
    if (!task) throw UsageError("--task needs a task such as M03T2, got '" + text + "'");
    o.modules.push_back(task->task.module);
    o.driver.tasks.push_back(task->id);
  }
  const std::pair<const char*, std::string*> files[] = {
      {"--json", &o.driver.json}, {"--junit", &o.driver.junit}, {"--csv", &o.driver.csv},
      {"--timings-out", &o.driver.timings_out}};
  for (const auto& [option, file] : files) {
    if (parsed.has(option)) *file = resolve(parsed.value(option));
  }
  o.driver.timeout = parsed.value("--timeout");
  o.driver.jobs = parsed.value("--jobs");
  if (parsed.has("--hidden-visibility")) {
    o.driver.hidden_visibility = parsed.value("--hidden-visibility");
    check_visibility(o.driver.hidden_visibility);
  }
  if (parsed.has("--require-full")) {
    o.require_full = parsed.value("--require-full");
    if (!has_capability(GradedItem{}, o.require_full)) {
      throw UsageError("--require-full: no capability '" + o.require_full + "' (" + kCapabilityNames + ")");
    }
    if (!o.submissions.empty()) throw UsageError("--require-full grades one tree, not a class (--submissions)");
  }
  return o;
}

// --require-full CAPABILITY, after the driver wrote `csv`: the tasks of the items with it, as this
// build's programs list them, each at its maximum (require_full), or exit status 1.
void check_full_of(const std::string& capability, const std::string& csv, const Manifest& manifest, std::ostream& out) {
  std::string text;
  if (!tools::read_file(csv, text)) throw StepFailed("--require-full: the driver wrote no table of tasks (" + csv + ")");
  std::vector<std::string> unbuilt;  // items this grading did not build (not started): none of their tasks is here
  const std::vector<grade::TaskRow> rows = rows_of_items(grade::parse_tasks_csv(text, csv), manifest, capability, &unbuilt);
  for (const std::string& id : unbuilt) out << "workbook: " << id << " was not graded here (not built), so not required\n";
  out << std::flush;
  require_full(rows, " of the items with " + capability, "", out);
  out << "workbook: every task of the items with " << capability << " scored full\n";
}

// The tree a grading builds: the root's own, or a submission taken in (prepare_submission), with
// the lock and the unpacked zip that live as long as the grading.
struct GradedTree {
  std::string path;
  std::unique_ptr<SubmissionLock> lock;
  std::unique_ptr<UnpackedZip> zip;
};

GradedTree take_in(const std::string& root, const GradeOptions& o, const std::string& submission, bool locked,
                   std::ostream& out) {
  GradedTree tree{root, nullptr, nullptr};
  if (submission.empty()) return tree;
  if (!locked) tree.lock = std::make_unique<SubmissionLock>(root);
  std::string folder = resolve(submission);
  if (fs::is_regular_file(folder)) {
    tree.zip = std::make_unique<UnpackedZip>(root, submission);
    folder = tree.zip->folder();
  }
  const Manifest own = read_manifest(BuildLayout::of_preset(root, "student").course_json());
  tree.path = prepare_submission(root, folder, own, o.modules, out);
  return tree;
}

// The course manifest of a configured build. One of an older schema (a build configured by an
// earlier version of the tree, which CMake regenerates only when it builds) is configured again,
// once, saying so, and then read: a failed re-configure is a BuildError naming its log, and a
// manifest still unreadable a ManifestError. Any other ManifestError is not configured away.
Manifest build_manifest(const std::string& tree, const std::string& build, std::ostream& out) {
  const std::string path = BuildLayout{build}.course_json();
  if (!fs::exists(path)) throw UsageError("no graded modules found (" + path + " is missing)");
  try {
    return read_manifest(path);
  } catch (const OlderManifest& older) {
    out << "workbook: " << path << " is of schema " << older.schema() << ", written before this tree changed; "
        << "configuring " << build << " again\n" << std::flush;
  }
  const std::string log = BuildLayout{build}.configure_log();
  if (const int status = run(Command{{cmake_program(), build}, tree, log}); status != 0) {
    throw BuildError("re-configuring " + build + " for its course manifest failed (status " + std::to_string(status) +
                     "; " + log + ")");
  }
  return read_manifest(path);
}

// The identity the grader trusts for the tutorial problems' variants: --student, a submission's
// folder (or zip) name, the remembered name, or "reference" under --solutions; empty if none.
std::string grading_identity(const std::string& root, const GradeOptions& o, const std::string& submission,
                             bool zipped) {
  std::string identity = o.student;
  if (identity.empty() && !submission.empty()) {
    identity = fs::path(resolve(submission)).filename().string();
    if (zipped) identity = fs::path(identity).stem().string();  // alice.zip: alice
  }
  if (identity.empty()) identity = remembered_student(root);
  if (identity.empty() && o.solutions) identity = "reference";
  return identity;
}

// What the plan needs to know of the tree `tree` built in `build` (grade_plan.hpp).
TreeFacts tree_facts(const std::string& root, const GradeOptions& o, const std::string& submission,
                     const GradedTree& tree, const std::string& build, const Manifest& manifest) {
  TreeFacts facts;
  facts.tree = tree.path;
  facts.build = build;
  facts.submission = !submission.empty();
  for (const GradedItem& item : manifest.graded) {
    for (const std::string& file : item.inputs) {
      if (fs::exists(fs::path(tree.path) / file)) facts.existing_inputs.insert(file);
    }
  }
  facts.has_timings = fs::exists(timings_path(tree.path));
  facts.identity = grading_identity(root, o, submission, tree.zip != nullptr);
  facts.jobs = job_count(available_jobs());
  return facts;
}

}  // namespace

std::pair<std::string, std::string> hint_levels_environment(const std::string& root, const std::string& submission) {
  return {protocol::kHintsOpenedVariable, submission.empty() ? hints_opened_path(root) : ""};
}

// Take the tree in, configure, plan, build, run the driver (grade_batch.hpp).
int grade_tree(const std::string& root, const GradeOptions& options, const std::string& submission, bool locked,
               std::ostream& out, const std::string& output) {
  const std::string preset = grading_preset(options, !submission.empty(), fs::is_directory(root + "/solutions"));
  const GradedTree tree = take_in(root, options, submission, locked, out);
  configure(tree.path, preset, out);
  const std::string build = preset_build_dir(tree.path, preset);
  GradeOptions o = options;  // --require-full reads the table of tasks: the --csv file, or one of its own
  if (!o.require_full.empty() && o.driver.csv.empty()) o.driver.csv = build + "/required.tasks.csv";
  const std::string tasks_csv = o.driver.csv;
  const Manifest manifest = build_manifest(tree.path, build, out);
  const GradingPlan plan = plan_grading(manifest, o, tree_facts(root, o, submission, tree, build, manifest));
  out << not_started_message(plan);
  const std::vector<ItemOutcome> outcomes = build_planned(root, plan, out);
  const DriverInvocation invocation = driver_invocation(plan, outcomes);

  // The items' inputs handed over, with the identity the grader trusts where an item needs it.
  const StagedAnswers staged;
  auto environment = stage_answers(graded_items(plan), plan.tree, plan.identity.identity, plan.solutions, staged);
  environment.push_back(hint_levels_environment(root, submission));
  out << identity_message(plan.identity) << plan.earlier << std::flush;
  Command command{driver_argv(invocation), "", output, true};
  command.environment = environment;
  const int status = run(command);
  if (!o.require_full.empty()) check_full_of(o.require_full, tasks_csv, manifest, out);
  return status;
}

namespace {

// The ids ("M01T2") of the tasks of the graded items of `manifest` with `capability`, of the
// modules among `modules` ("M01"), as the grade driver lists them from each item's lister: its
// reference program where it has one (the trusted list), else its program.
std::set<std::string> tasks_of_items(const Manifest& manifest, const std::string& capability,
                                     const std::set<std::string>& modules, std::vector<std::string>* unbuilt) {
  if (!has_capability(GradedItem{}, capability)) {
    throw UsageError("--of: no capability '" + capability + "' (" + kCapabilityNames + ")");
  }
  std::vector<std::string> argv{manifest.grade_driver, "--list-tasks"};
  for (const GradedItem& item : manifest.graded) {
    if (!*has_capability(item, capability) || !modules.count(module_id(item.module))) continue;
    const std::string lister = item.reference_program.value_or(item.program);
    if (!fs::exists(lister) && unbuilt != nullptr) {
      unbuilt->push_back(item.id);
      continue;
    }
    if (!fs::exists(lister)) {
      throw UsageError("--of: the tasks of " + item.id + " cannot be listed: " + lister +
                       " is not built (grading builds it)");
    }
    argv.push_back(lister);
  }
  std::set<std::string> ids;
  if (argv.size() == 2) return ids;
  if (manifest.grade_driver.empty() || !fs::exists(manifest.grade_driver)) {
    throw UsageError("--of: the grade driver of this build is not built (grading builds it)");
  }
  int status = 0;
  const std::string listed = tools::capture(tools::Command(argv), status);
  if (status != 0) {
    throw StepFailed("--of: listing the tasks of the items with " + capability + " failed (fmbd-grade --list-tasks, " +
                     "status " + std::to_string(status) + ")");
  }
  std::istringstream lines(listed);
  for (std::string module, task, points; lines >> module >> task >> points;) ids.insert(module + task);
  return ids;
}

}  // namespace

std::vector<grade::TaskRow> rows_of_items(std::vector<grade::TaskRow> rows, const Manifest& manifest,
                                          const std::string& capability, std::vector<std::string>* unbuilt) {
  std::set<std::string> modules;
  for (const grade::TaskRow& row : rows) modules.insert(row.module);
  const std::set<std::string> ids = tasks_of_items(manifest, capability, modules, unbuilt);
  const auto unselected = [&ids](const grade::TaskRow& row) { return ids.count(row.id()) == 0; };
  rows.erase(std::remove_if(rows.begin(), rows.end(), unselected), rows.end());
  return rows;
}

void require_full(const std::vector<grade::TaskRow>& rows, const std::string& which, const std::string& where,
                  std::ostream& out) {
  if (rows.empty()) throw StepFailed("no task" + which + where);
  std::size_t below = 0;
  for (const grade::TaskRow& row : rows) {
    if (row.score >= row.max_score) continue;
    ++below;
    out << row.module << " " << row.task << ": " << grade::format_number(row.score) << " of "
        << grade::format_number(row.max_score) << ", " << row.status << "\n";
  }
  if (below > 0) {
    throw StepFailed(std::to_string(below) + " of the " + std::to_string(rows.size()) + " tasks" + which + where +
                     " scored below their maximum (above)");
  }
}

const CommandSpec& grade_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "grade";
    s.unknown_hint = " (see ./workbook help)";
    s.options = {
        {"--solutions", OptionKind::flag, "", "", "grade the reference solutions this copy carries"},
        {"--reference-earlier", OptionKind::flag, "", "", "module N on the released reference of modules 1..N-1"},
        {"--submission", OptionKind::value, "DIR", "a directory or a zip (./workbook handin)", "a student's files"},
        {"--own-earlier", OptionKind::flag, "", "", "a submission's module N on its own modules 1..N-1"},
        {"--submissions", OptionKind::value, "DIR", "a directory", "a class: a subfolder per student"},
        {"--out", OptionKind::value, "DIR", "a directory", "the class's results"},
        {"--resume", OptionKind::flag, "", "", "skip the submissions graded already"},
        {"--module", OptionKind::repeatable, "N", "a number", "grade module N"},
        {"--task", OptionKind::repeatable, "MnTk", "a task such as M03T2", "grade one task"},
        {"--json", OptionKind::value, "FILE", "a file name", "Gradescope results.json"},
        {"--junit", OptionKind::value, "FILE", "a file name", "JUnit XML"},
        {"--csv", OptionKind::value, "FILE", "a file name", "a line per task"},
        {"--timings-out", OptionKind::value, "FILE", "a file name", "the reference's time per test"},
        {"--hidden-visibility", OptionKind::value, "V", "a value", "Gradescope visibility of hidden tests"},
        {"--timeout", OptionKind::number, "SEC", "a number", "seconds per test at most"},
        {"--jobs", OptionKind::number, "N", "a number", "tests at once"},
        {"--strict", OptionKind::flag, "", "", "exit 0 only on a full score"},
        {"--require-full", OptionKind::value, "CAPABILITY", "a capability of the manifest",
         "exit 1 unless those items' tasks score full"},
        {"--student", OptionKind::value, "NAME", "a name", "whose variant of the tutorial problems"},
        {"--gradescope-metadata", OptionKind::value, "FILE", "a file name", "the student of submission_metadata.json"},
        {"--failed-results", OptionKind::value, "REASON", "a reason", "only write --json FILE: a score of 0, REASON"},
    };
    s.synopsis =
        "[--solutions | --reference-earlier | --submission DIR [--own-earlier]]\n"
        "        [--module N]... [--task MnTk]... [--json FILE] [--junit FILE] [--csv FILE]\n"
        "        [--hidden-visibility V] [--timeout SEC] [--jobs N] [--strict]\n"
        "        [--require-full CAPABILITY]\n"
        "        [--student NAME | --gradescope-metadata FILE]\n"
        "        [--failed-results REASON --json FILE]";
    s.help = {
        "Build and grade the code in the module folders (--solutions: the reference, of",
        "every module whose solutions/ this copy has; --reference-earlier: module N on the",
        "released reference of modules 1..N-1, where solutions/ has it, in build/reference).",
        "--task M3T2 grades one task.",
        "--submission DIR|ZIP grades a student's exercise files from DIR in a pristine copy of",
        "this tree, module N on the reference modules 1..N-1 (--own-earlier: on the",
        "submission's). Prints the score table; exits 0 when grading ran (--strict: only",
        "on a full score). --json writes Gradescope results.json, where hidden tests get",
        "--hidden-visibility V (after_published by default; hidden, after_due_date, visible);",
        "--csv one line per task (module,task,score,max_score,status). --timeout: seconds",
        "per test at most (default 30; a test's limit is 20 times the reference's time for",
        "it, autograder/timings.txt, and at least 5 s); --jobs: tests at once (default: the",
        "cores, or the container's CPU quota).",
        "--submissions DIR --out DIR [--resume] grades every subfolder of DIR as a",
        "submission: OUT/NAME/{grade.txt,results.json,junit.xml,tasks.csv,logs/} and",
        "OUT/gradebook.csv (a column per module and per task). --resume skips the",
        "submissions already graded in OUT. --timings-out FILE writes the time of each",
        "passed test (./workbook bench writes autograder/timings.txt with it).",
        "--require-full CAPABILITY (links_student_code, classroom, inputs, needs_identity):",
        "exit 1, naming each task below its maximum, unless every task of the graded items",
        "with that capability of the course manifest scored full (Gradescope's setup.sh: the",
        "reference solutions score every task of the code).",
        "The tutorial problems (MnnPk) are graded with the numbers of --student NAME, or the",
        "name ./workbook problems remembers; of a submission's folder name (a class: each",
        "subfolder's); of the first user of Gradescope's --gradescope-metadata FILE.",
        "--failed-results REASON --json FILE grades nothing: it writes a results.json of",
        "score 0 that says REASON (Gradescope's run_autograder, where the grader did not run).",
    };
    return s;
  }();
  return spec;
}

namespace {

int grade_in(const std::string& root, const std::vector<std::string>& args, std::ostream& out) {
  const ParsedOptions parsed = parse_options(grade_command(), args);
  if (print_usage_if_asked(parsed, grade_command(), out)) return 0;
  if (parsed.has("--failed-results")) {
    if (!parsed.has("--json")) throw UsageError("--failed-results needs --json FILE");
    grade::write_file_atomically(tools::absolute_path(parsed.value("--json"), root),
                                 grade::failed_results_json(parsed.value("--failed-results")));
    return 0;
  }
  const GradeOptions o = check(parsed);
  if (!o.submissions.empty()) {
    if (o.out.empty()) throw UsageError("--submissions needs --out DIR");
    if (!o.submission.empty() || o.solutions) throw UsageError("--submissions excludes --submission and --solutions");
    return grade_class(root, o, out);
  }
  if (!o.out.empty()) throw UsageError("--out goes with --submissions");
  if (o.resume) throw UsageError("--resume goes with --submissions");
  return grade_tree(root, o, o.submission, false, out, "");
}

}  // namespace

int run_grade(const std::vector<std::string>& args, const Context& context) {
  try {
    return grade_in(context.source_dir, args, context.out);
  } catch (const std::exception& error) {  // results.json still says why (Gradescope shows it)
    write_failed_results(context.source_dir, args, error.what());
    throw;
  }
}

bool write_failed_results(const std::string& root, const std::vector<std::string>& args, const std::string& reason) {
  std::string file;
  for (std::size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] == "--json") file = tools::absolute_path(args[i + 1], root);
  }
  if (file.empty() || fs::exists(file)) return false;
  try {
    const std::string output = "The grader could not grade this submission: " + reason;
    grade::write_file_atomically(file, grade::failed_results_json(output));
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace fmbd::frontend
