#include "grade.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "build.hpp"
#include "csv.hpp"
#include "file_io.hpp"
#include "ids.hpp"
#include "jobs.hpp"
#include "json.hpp"
#include "manifest.hpp"
#include "problems.hpp"
#include "process.hpp"
#include "strings.hpp"
#include "submission.hpp"
#include "tables.hpp"
#include "text.hpp"

namespace fmbd::frontend {

using tools::Child;
using tools::Command;
namespace {

namespace fs = std::filesystem;

// The grade options, checked.
struct GradeOptions {
  bool solutions = false;
  bool own_earlier = false;
  bool reference_earlier = false;
  bool resume = false;
  bool strict = false;
  std::string submission;   // a folder (a zip is unpacked first)
  std::string submissions;  // a class
  std::string out;          // with --submissions
  std::string student;      // --student NAME, or the first user of --gradescope-metadata
  std::vector<int> modules;  // from --module and --task, in order; empty: all
  std::vector<std::string> driver;  // options for fmbd-grade: --module, --task, --timeout, ...
  bool jobs_given = false;
};

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
  o.strict = parsed.has("--strict");
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
    o.driver.insert(o.driver.end(), {"--module", module});
  }
  for (const std::string& text : parsed.all("--task")) {
    const std::optional<TaskId> task = task_id(text);
    if (!task) throw UsageError("--task needs a task such as M03T2, got '" + text + "'");
    o.modules.push_back(task->module);
    o.driver.insert(o.driver.end(), {"--task", task->id});
  }
  for (const char* option : {"--json", "--junit", "--csv", "--timings-out"}) {
    if (parsed.has(option)) o.driver.insert(o.driver.end(), {option, resolve(parsed.value(option))});
  }
  for (const char* option : {"--timeout", "--jobs"}) {
    if (parsed.has(option)) o.driver.insert(o.driver.end(), {option, parsed.value(option)});
  }
  o.jobs_given = parsed.has("--jobs");
  if (parsed.has("--hidden-visibility")) {
    const std::string v = parsed.value("--hidden-visibility");
    check_visibility(v);
    o.driver.insert(o.driver.end(), {"--hidden-visibility", v});
  }
  if (o.strict) o.driver.push_back("--strict");
  return o;
}

bool selected(const GradeOptions& o, int module) {
  return o.modules.empty() || std::count(o.modules.begin(), o.modules.end(), module) > 0;
}

std::string folder_of(const Manifest& manifest, int number) {
  const Module* module = manifest.module(number);
  return module ? module->folder : "";
}

// What a message calls a graded item: its module's folder, or its id where it has none.
std::string name_of(const Manifest& manifest, const GradedItem& item) {
  const std::string folder = folder_of(manifest, item.module);
  return folder.empty() ? item.id : folder;
}

// The lines of progress a build of these items may print.
std::vector<Watched> watched_outputs(const Manifest& manifest, const std::vector<const GradedItem*>& items) {
  std::vector<Watched> watched{{manifest.grade_driver, "the grade driver is ready"}};
  for (const GradedItem* item : items) {
    const std::string module = "module " + std::to_string(item->module) + ": ";
    const Module* m = manifest.module(item->module);
    if (m && item->links_student_code) watched.push_back({m->student_library, module + "your code compiled"});
    if (m && m->reference_library) watched.push_back({*m->reference_library, module + "the reference compiled"});
    watched.push_back({item->program, module + item->id + " is ready"});
    if (item->reference_program) watched.push_back({*item->reference_program, module + item->id + "'s lister is ready"});
  }
  // Each output once (a module's items share its libraries; an item may be its own lister).
  std::vector<Watched> unique;
  for (const Watched& output : watched) {
    const bool seen = std::any_of(unique.begin(), unique.end(), [&output](const Watched& w) { return w.path == output.path; });
    if (!seen) unique.push_back(output);
  }
  return unique;
}

// The source check of the exercise files that `item`'s program links: whether it passed; when it
// refused a file, its report goes to the driver (--reject).
bool vet(const std::string& build, const GradedItem& item, const std::string& folder, std::vector<std::string>& driver,
         std::ostream& out) {
  const std::string number = item.id.substr(1);
  const std::string report = build + "/vet/m" + number + ".txt";
  std::error_code error;
  fs::remove(report, error);
  const std::string log = build + "/m" + number + "_vet.log";
  if (!item.vet_target || build_target(build, *item.vet_target, log)) return true;
  if (!fs::exists(report) || fs::file_size(report, error) == 0) {
    fs::create_directories(build + "/vet", error);
    std::ofstream(report) << "the source check could not run (log: " << log << ")\n"
                          << "  fix: tell your instructor; the log says why\n";
  }
  std::string text;
  tools::read_file(report, text);
  out << "workbook: " << folder << " was rejected by the source check (its tests score 0):\n" << text;
  driver.insert(driver.end(), {"--reject", number + "=" + report});
  return false;
}

// The build preset of a grading: "reference" (earlier stages from the reference) for
// --reference-earlier and for a submission unless --own-earlier, else "student". Throws
// UsageError for options that exclude each other or need what this copy has not.
std::string grading_preset(const std::string& root, const GradeOptions& o, const std::string& submission) {
  if (o.reference_earlier) {
    if (!submission.empty()) {
      throw UsageError("--reference-earlier is for your own code; a --submission is graded on the reference anyway");
    }
    if (!fs::is_directory(root + "/solutions")) {
      throw UsageError("--reference-earlier: no module's reference has been released here (no solutions/ folder)");
    }
  }
  if (!submission.empty() && o.solutions) throw UsageError("--solutions and --submission exclude each other");
  if (!submission.empty() && !fs::is_directory(root + "/solutions")) {
    throw UsageError("--submission needs the solutions/ folder (an instructor's copy)");
  }
  return (!submission.empty() && !o.own_earlier) || o.reference_earlier ? "reference" : "student";
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
  const Manifest own = read_manifest(root + "/build/student/course.json");
  tree.path = prepare_submission(root, folder, own, o.modules, out);
  return tree;
}

// The course manifest of a configured build. One of an older schema (a build configured by an
// earlier version of the tree, which CMake regenerates only when it builds) is configured again,
// once, saying so, and then read: a failed re-configure is a BuildError naming its log, and a
// manifest still unreadable a ManifestError. Any other ManifestError is not configured away.
Manifest build_manifest(const std::string& tree, const std::string& build, std::ostream& out) {
  const std::string path = build + "/course.json";
  if (!fs::exists(path)) throw UsageError("no graded modules found (" + path + " is missing)");
  try {
    return read_manifest(path);
  } catch (const OlderManifest& older) {
    out << "workbook: " << path << " is of schema " << older.schema() << ", written before this tree changed; "
        << "configuring " << build << " again\n" << std::flush;
  }
  const std::string log = build + "/configure.log";
  if (const int status = run(Command{{cmake_program(), build}, tree, log}); status != 0) {
    throw BuildError("re-configuring " + build + " for its course manifest failed (status " + std::to_string(status) +
                     "; " + log + ")");
  }
  return read_manifest(path);
}

// --solutions grades the modules whose reference this copy carries (a release may carry some):
// all of them, or the ones asked for, each of which must have one. Otherwise the modules asked for.
std::vector<int> graded_modules(const Manifest& manifest, const GradeOptions& o) {
  if (!o.solutions) return o.modules;
  std::string with_reference;
  std::vector<int> numbers;
  for (const GradedItem& item : manifest.graded) {
    if (item.reference_program) {
      with_reference += " " + std::to_string(item.module);
      numbers.push_back(item.module);
    }
  }
  if (numbers.empty()) throw UsageError("--solutions: this copy carries the reference solution of no module (solutions/)");
  if (o.modules.empty()) return numbers;
  for (const int number : o.modules) {
    if (std::count(numbers.begin(), numbers.end(), number)) continue;
    const std::string folder = folder_of(manifest, number);
    throw UsageError("--solutions: module " + std::to_string(number) + " (" +
                     (folder.empty() ? "not in this copy" : folder) +
                     ") has no reference solution here; this copy carries those of modules" + with_reference);
  }
  return o.modules;
}

// The graded items of the chosen modules. In one's own tree, an item with inputs none of which
// exists yet (tutorial problems without an answers file) is not started, so neither built nor
// graded: a first grade costs the code's build only. A submission's are always graded.
std::vector<const GradedItem*> graded_items(const Manifest& manifest, const GradeOptions& chosen, const std::string& tree,
                                            bool own_tree, std::ostream& out) {
  std::vector<const GradedItem*> items;
  std::string unstarted;
  bool printable = false;
  for (const GradedItem& item : manifest.graded) {
    if (!selected(chosen, item.module)) continue;
    if (own_tree && !item.inputs.empty() &&
        std::none_of(item.inputs.begin(), item.inputs.end(),
                     [&tree](const std::string& file) { return fs::exists(fs::path(tree) / file); })) {
      unstarted += " " + item.id + " (" + item.inputs.front() + ")";
      printable = printable || item.has_personal_problems();
      continue;
    }
    items.push_back(&item);
  }
  if (!unstarted.empty()) {
    out << "workbook: not started (no file of its answers yet), so not graded here:" << unstarted
        << (printable ? "; ./workbook problems MNN prints the problems" : "") << "\n";
  }
  return items;
}

// Every selected item in one build that keeps going past errors (both cores stay busy); then the
// grade driver, which must build.
void build_items(const std::string& build, const Manifest& manifest, const std::vector<const GradedItem*>& items,
                 const std::string& tree, bool solutions, std::ostream& out) {
  std::vector<std::string> targets{"fmbd-grade"};
  std::vector<std::string> exercises;
  for (const GradedItem* item : items) {
    if (solutions) {
      targets.push_back(*item->reference_target);
    } else {
      targets.push_back(item->target);
      if (item->reference_target) targets.push_back(*item->reference_target);  // it lists the tests
    }
  }
  for (const Module& module : manifest.modules) {
    for (const std::string& file : module.exercises) exercises.push_back(tree + "/" + file);
  }
  build_with_progress(build, build + "/grade.build.log", targets, watched_outputs(manifest, items), tree, exercises,
                      out);
  if (!build_target(build, "fmbd-grade", build + "/fmbd-grade.build.log")) {
    throw BuildError("building the grade driver failed (" + build + "/fmbd-grade.build.log)");
  }
}

// The driver's programs (each with its lister, --listed-by) and options (--reject of the source
// check, --build-errors of a module that does not compile), item by item.
struct DriverPlan {
  std::vector<std::string> options;
  std::vector<std::string> programs;
  std::string broken, rejected;  // the folders that do not compile, that the source check refused
};

// One item that built: its program, listed by the reference build where there is one (a student's
// program could print any list: README, "Decisions"), and the source check.
void plan_built(const std::string& build, const GradedItem& item, const std::string& folder, bool solutions,
                DriverPlan& plan, std::ostream& out) {
  plan.programs.push_back(solutions ? *item.reference_program : item.program);
  if (solutions) return;
  if (item.reference_target) {
    const std::string reference_log = build + "/" + *item.reference_target + ".build.log";
    if (build_target(build, *item.reference_target, reference_log)) {
      plan.programs.insert(plan.programs.end(), {"--listed-by", *item.reference_program});
    } else {
      out << "workbook: the reference of " << folder << " does not build (" << reference_log
          << "); its tests are listed by your build\n";
    }
  }
  if (!vet(build, item, folder, plan.options, out)) plan.rejected += " " + folder;
}

// One item that does not build: its first errors shown and kept; with the reference at hand, its
// test list makes every test of the module count as failed, with the errors as their output.
void plan_broken(const std::string& root, const std::string& build, const GradedItem& item, const std::string& folder,
                 const std::string& program, const std::string& log, DriverPlan& plan, std::ostream& out) {
  const std::string errors = build + "/compile/m" + item.id.substr(1) + ".txt";
  const std::string text = first_errors(log, folder, {root + "/build/submission/tree", root});
  std::ofstream(errors) << text;
  out << "workbook: " << folder << " does not compile; the first errors (all in " << log << "):\n" << text;
  plan.broken += " " + folder;
  std::error_code error;
  fs::remove(program, error);  // never grade a stale build
  if (item.reference_target && build_target(build, *item.reference_target, "/dev/null")) {
    plan.programs.insert(plan.programs.end(), {program, "--listed-by", *item.reference_program});
    plan.options.insert(plan.options.end(), {"--build-errors", std::to_string(item.module) + "=" + errors});
  }
}

DriverPlan plan_driver(const std::string& root, const std::string& build, const Manifest& manifest,
                       const std::vector<const GradedItem*>& items, const GradeOptions& chosen, std::ostream& out) {
  DriverPlan plan;
  plan.options = chosen.driver;
  fs::create_directories(build + "/compile");
  for (const GradedItem* item : items) {
    const std::string folder = name_of(manifest, *item);
    const std::string target = chosen.solutions ? *item->reference_target : item->target;
    const std::string program = chosen.solutions ? *item->reference_program : item->program;
    const std::string log = build + "/" + target + ".build.log";
    out << "workbook: building " << folder << " ...\n" << std::flush;
    if (build_target(build, target, log)) {
      plan_built(build, *item, folder, chosen.solutions, plan, out);
    } else if (!item->links_student_code && !chosen.solutions) {  // not the student's doing
      out << "workbook: " << item->id << " does not build (" << log
          << "), and none of your files is in it: it is not graded here; tell your instructor\n";
    } else {
      plan_broken(root, build, *item, folder, program, log, plan, out);
    }
  }
  if (!plan.broken.empty()) out << "workbook: these modules do not compile and score 0 (errors above):" << plan.broken << "\n";
  if (!plan.rejected.empty()) {
    out << "workbook: these modules were rejected by the source check and score 0 (reasons above):" << plan.rejected
        << "\n";
  }
  show_warnings(build, out);
  if (plan.programs.empty()) throw UsageError("nothing to grade");
  return plan;
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

// What the items that need the identity are graded with (or that they need one), and what the
// items without their reference check.
void say_identity(const std::vector<const GradedItem*>& items, const std::string& identity, std::ostream& out) {
  std::string identified;
  std::string format_only;
  for (const GradedItem* item : items) {
    if (item->needs_identity) identified += " " + item->id;
    if (!item->reference_program && item->without_reference == WithoutReference::format) {
      format_only += " " + item->id;
    }
  }
  if (!identified.empty() && identity.empty()) {
    out << "workbook: the numbers of" << identified << " depend on your name: ./workbook grade --student \"YOUR NAME\" "
           "(or ./workbook problems --student \"YOUR NAME\" once)\n";
  } else if (!identified.empty()) {
    out << "workbook:" << identified << " graded with the numbers of \"" << identity << "\"\n";
  }
  if (!format_only.empty()) {
    out << "workbook:" << format_only
        << " without the reference here: only the format of the answers is checked; your instructor's grader "
           "checks the values\n";
  }
}

// Grades one tree (the root's, or a submission's copy) and returns the driver's exit status:
// take the tree in, configure and build it, plan the driver's programs, and run the driver.
// `output`: where the driver writes (empty: the terminal).
int grade_tree(const std::string& root, const GradeOptions& o, const std::string& submission, bool locked,
               std::ostream& out, const std::string& output) {
  const std::string preset = grading_preset(root, o, submission);
  const GradedTree tree = take_in(root, o, submission, locked, out);
  configure(tree.path, preset, out);
  const std::string build = tree.path + "/build/" + preset;
  const Manifest manifest = build_manifest(tree.path, build, out);
  GradeOptions chosen = o;
  chosen.modules = graded_modules(manifest, o);
  const std::vector<const GradedItem*> items =
      graded_items(manifest, chosen, tree.path, submission.empty() && !o.solutions, out);
  build_items(build, manifest, items, tree.path, o.solutions, out);
  const DriverPlan plan = plan_driver(root, build, manifest, items, chosen, out);

  // The items' inputs handed over, with the identity the grader trusts where an item needs it.
  const std::string identity = grading_identity(root, o, submission, tree.zip != nullptr);
  const StagedAnswers staged;
  const auto environment = stage_answers(items, tree.path, identity, o.solutions, staged);
  say_identity(items, identity, out);

  std::vector<std::string> argv{manifest.grade_driver};
  // Each test's timeout follows the reference's own time for it (autograder/timings.txt, written
  // by ./workbook bench): a loop costs seconds, not --timeout.
  if (fs::exists(tree.path + "/autograder/timings.txt")) {
    argv.insert(argv.end(), {"--timings", tree.path + "/autograder/timings.txt"});
  }
  if (!o.jobs_given) argv.insert(argv.end(), {"--jobs", std::to_string(job_count(available_jobs()))});
  argv.insert(argv.end(), plan.options.begin(), plan.options.end());
  argv.insert(argv.end(), plan.programs.begin(), plan.programs.end());
  out << std::flush;
  Command command{argv, "", output, true};
  command.environment = environment;
  return run(command);
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::string text;
  if (!tools::read_file(path, text)) return rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) rows.push_back(csv::split(line));
  }
  return rows;
}

// The rows of the tasks.csv at `path`, read by the driver's reader (tables.hpp); none where it is
// missing or not one (grading stopped before the driver wrote it).
std::vector<grade::TaskRow> read_task_rows(const std::string& path) {
  std::string text;
  if (!tools::read_file(path, text)) return {};
  try {
    return grade::parse_tasks_csv(text, path);
  } catch (const grade::TableError&) {
    return {};
  }
}

}  // namespace

Summary summarise_tasks(const std::string& tasks_csv) {
  Summary summary;
  const std::vector<grade::TaskRow> rows = read_task_rows(tasks_csv);
  if (rows.empty()) return summary;
  double score = 0;
  double max_score = 0;
  std::string status;
  std::vector<std::string> modules_seen;
  for (const grade::TaskRow& row : rows) {
    score += row.score;
    max_score += row.max_score;
    const std::string& why = row.status;
    std::string item;
    if ((why == "build_error" || why == "rejected") &&
        std::find(modules_seen.begin(), modules_seen.end(), row.module) == modules_seen.end()) {
      modules_seen.push_back(row.module);
      item = why + ":" + row.module;
    } else if (why == "timed_out" || why == "crashed") {
      item = why + ":" + row.id();
    }
    if (!item.empty()) status += (status.empty() ? "" : " ") + item;
  }
  summary.score = grade::format_number(score);
  summary.max_score = grade::format_number(max_score);
  summary.status = status.empty() ? "graded" : status;
  return summary;
}

namespace {

// `text` with every build path of the submission tree's logs ("ROOT/build/submission/tree/build/
// PRESET/", then "compile/" or "vet/" if there) written "logs/", where the submission's own copies are.
std::string to_logs(std::string text, const std::string& root) {
  const std::string prefix = root + "/build/submission/tree/build/";
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) {
    std::size_t end = at + prefix.size();
    while (end < text.size() && text[end] >= 'a' && text[end] <= 'z') ++end;
    if (end >= text.size() || text[end] != '/') {
      at = end;
      continue;
    }
    ++end;
    for (const char* sub : {"compile/", "vet/"}) {
      if (text.compare(end, std::string(sub).size(), sub) == 0) end += std::string(sub).size();
    }
    text.replace(at, end - at, "logs/");
    at += 5;
  }
  return text;
}

int grade_class(const std::string& root, const GradeOptions& o, std::ostream& out) {
  SubmissionLock lock(root);
  fs::create_directories(o.out);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(o.submissions)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name[0] != '.') names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) throw UsageError("--submissions: no subfolders in '" + o.submissions + "'");
  const std::string total = std::to_string(names.size());
  std::size_t count = 0;
  for (const std::string& name : names) {
    ++count;
    const std::string result = o.out + "/" + name;
    const std::string tag = "[" + std::to_string(count) + "/" + total + "] " + name;
    const auto previous = read_csv(result + "/summary.csv");
    if (o.resume && !previous.empty() && previous.front().size() >= 4) {
      const auto& row = previous.front();
      out << "workbook: " << tag << ": graded before (--resume): " << row[1] << "," << row[2] << "," << row[3] << "\n";
      continue;
    }
    std::error_code error;
    fs::remove_all(result, error);
    fs::create_directories(result + "/logs");
    const auto start = std::chrono::steady_clock::now();
    GradeOptions one = o;  // --strict is for one grading's exit status, not a class's
    one.driver.erase(std::remove(one.driver.begin(), one.driver.end(), "--strict"), one.driver.end());
    one.driver.insert(one.driver.end(), {"--json", result + "/results.json", "--junit", result + "/junit.xml", "--csv",
                                         result + "/tasks.csv"});
    const std::string grade_txt = result + "/grade.txt";
    {
      std::ofstream text(grade_txt);
      try {
        grade_tree(root, one, o.submissions + "/" + name, true, text, grade_txt);
      } catch (const std::exception& failure) {
        text << "workbook: " << failure.what() << "\n";
      }
    }
    // The logs of this submission, kept with its results (the next one overwrites the tree's).
    const std::string builds = root + "/build/submission/tree/build";
    for (const auto& preset : fs::directory_iterator(builds, error)) {
      std::vector<fs::path> logs;
      for (const auto& entry : fs::directory_iterator(preset.path(), error)) {
        const std::string file = entry.path().filename().string();
        if (file[0] == 'm' && file.size() > 10 && file.compare(file.size() - 10, 10, ".build.log") == 0) {
          logs.push_back(entry.path());
        }
      }
      for (const char* sub : {"compile", "vet"}) {
        for (const auto& entry : fs::directory_iterator(preset.path() / sub, error)) {
          if (entry.path().extension() == ".txt") logs.push_back(entry.path());
        }
      }
      for (const fs::path& log : logs) {
        fs::copy_file(log, result + "/logs/" + log.filename().string(), fs::copy_options::overwrite_existing, error);
      }
    }
    std::string text;
    tools::read_file(grade_txt, text);
    tools::write_if_changed(grade_txt, to_logs(text, root));
    const Summary summary = summarise_tasks(result + "/tasks.csv");
    std::ofstream(result + "/summary.csv") << csv::row({name, summary.score, summary.max_score, summary.status});
    const long seconds = static_cast<long>(
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count());
    out << "workbook: " << tag << ": " << summary.score << "/" << summary.max_score << " " << summary.status << " ("
        << seconds << " s; " << grade_txt << ")\n" << std::flush;
    write_gradebook(o.out);
  }
  out << "workbook: graded " << count << " submissions; gradebook: " << o.out << "/gradebook.csv\n";
  return 0;
}

}  // namespace

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
        {"--student", OptionKind::value, "NAME", "a name", "whose variant of the tutorial problems"},
        {"--gradescope-metadata", OptionKind::value, "FILE", "a file name", "the student of submission_metadata.json"},
    };
    s.synopsis =
        "[--solutions | --reference-earlier | --submission DIR [--own-earlier]]\n"
        "        [--module N]... [--task MnTk]... [--json FILE] [--junit FILE] [--csv FILE]\n"
        "        [--hidden-visibility V] [--timeout SEC] [--jobs N] [--strict]\n"
        "        [--student NAME | --gradescope-metadata FILE]";
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
        "The tutorial problems (MnnPk) are graded with the numbers of --student NAME, or the",
        "name ./workbook problems remembers; of a submission's folder name (a class: each",
        "subfolder's); of the first user of Gradescope's --gradescope-metadata FILE.",
    };
    return s;
  }();
  return spec;
}

int run_grade(const std::string& root, const std::vector<std::string>& args, std::ostream& out) {
  const ParsedOptions parsed = parse_options(grade_command(), args);
  if (print_usage_if_asked(parsed, grade_command(), out)) return 0;
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

void write_gradebook(const std::string& out_dir) {
  std::vector<std::string> folders;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(out_dir, error)) {
    if (entry.is_directory()) folders.push_back(entry.path().string());
  }
  std::sort(folders.begin(), folders.end());
  // The columns: the modules, then the tasks, of the first submission graded in full.
  std::vector<std::string> modules;
  std::vector<std::pair<std::string, std::string>> tasks;  // (module, module + task)
  for (const std::string& folder : folders) {
    const std::vector<grade::TaskRow> rows = read_task_rows(folder + "/tasks.csv");
    if (rows.empty()) continue;
    for (const grade::TaskRow& row : rows) {
      if (std::find(modules.begin(), modules.end(), row.module) == modules.end()) modules.push_back(row.module);
      tasks.emplace_back(row.module, row.id());
    }
    break;
  }
  std::vector<std::string> header{"submission", "score", "max_score", "status"};
  header.insert(header.end(), modules.begin(), modules.end());
  for (const auto& task : tasks) header.push_back(task.second);
  std::string text = csv::row(header);
  for (const std::string& folder : folders) {
    const auto summary = read_csv(folder + "/summary.csv");
    if (summary.empty()) continue;
    std::vector<std::string> row = summary.front();
    std::map<std::string, double> module_points;
    std::map<std::string, std::string> task_points;
    for (const grade::TaskRow& task : read_task_rows(folder + "/tasks.csv")) {
      module_points[task.module] += task.score;
      task_points[task.id()] = grade::format_number(task.score);
    }
    for (const std::string& module : modules) {
      row.push_back(module_points.count(module) ? grade::format_number(module_points[module]) : "");
    }
    for (const auto& task : tasks) row.push_back(task_points.count(task.second) ? task_points[task.second] : "");
    text += csv::row(row);
  }
  const std::string path = out_dir + "/gradebook.csv";
  std::ofstream(path + ".new") << text;
  fs::rename(path + ".new", path, error);
}

namespace {

// A cell of the gradebook as a number: an empty one is 0 (a submission graded without that module
// or task); nothing where it is none.
std::optional<double> points_of(const std::string& cell) {
  if (cell.empty()) return 0.0;
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (*end != '\0' || !std::isfinite(value)) return std::nullopt;
  return value;
}

// The gradebook's columns after the first four: for each, the module column it is a task of
// (one before it of which it is the name and more: M01T2 of M01), or itself for a module.
std::vector<std::size_t> owners_of(const std::vector<std::string>& header) {
  std::vector<std::size_t> owner(header.size());
  for (std::size_t i = 4; i < header.size(); ++i) {
    owner[i] = i;
    for (std::size_t m = 4; m < i && owner[i] == i; ++m) {
      const bool task_of_m = header[i].size() > header[m].size() && tools::starts_with(header[i], header[m]);
      if (owner[m] == m && task_of_m) owner[i] = m;
    }
  }
  return owner;
}

// Whether a column and the sum of `cells` columns agree, each written to a thousandth
// (format_number): within half a thousandth per column.
bool same_points(double column, double sum, std::size_t cells) {
  return std::abs(column - sum) <= 5e-4 * static_cast<double>(cells + 1) + 1e-9;
}

}  // namespace

std::vector<std::string> gradebook_mismatches(const std::string& text, const std::string& origin) {
  const std::vector<std::string> lines = tools::split_lines(text);
  const std::vector<std::string> header = lines.empty() ? std::vector<std::string>{} : csv::split(lines.front());
  if (header.size() < 4 || header[0] != "submission" || header[1] != "score" || header[2] != "max_score" ||
      header[3] != "status") {
    throw grade::TableError(origin + ":1: not a gradebook: its header does not start with "
                            "submission,score,max_score,status");
  }
  const std::vector<std::size_t> owner = owners_of(header);
  std::vector<std::string> mismatches;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    if (lines[l].empty()) continue;
    const std::vector<std::string> row = csv::split(lines[l]);
    std::vector<double> points(row.size(), 0.0);  // the status column (3) counts 0
    bool numbers = row.size() == header.size();
    for (std::size_t i = 1; i < row.size() && numbers; ++i) {
      const std::optional<double> value = i == 3 ? 0.0 : points_of(row[i]);
      numbers = value.has_value();
      points[i] = value.value_or(0);
    }
    if (!numbers) {
      throw grade::TableError(origin + ":" + std::to_string(l + 1) + ": expected the " + std::to_string(header.size()) +
                              " columns of the header, points after the status, got: " + lines[l]);
    }
    // Per module column: the sum of its tasks and their number; at 1: of the modules.
    std::vector<double> sums(row.size(), 0.0);
    std::vector<std::size_t> cells(row.size(), 0);
    for (std::size_t i = 4; i < row.size(); ++i) {
      const std::size_t sum = owner[i] == i ? 1 : owner[i];
      sums[sum] += points[i];
      ++cells[sum];
    }
    if (!same_points(points[1], sums[1], cells[1])) {
      mismatches.push_back(row[0] + ": the modules add up to " + grade::format_number(sums[1]) + ", the score is " +
                           row[1]);
    }
    for (std::size_t m = 4; m < row.size(); ++m) {
      if (owner[m] == m && cells[m] > 0 && !same_points(points[m], sums[m], cells[m])) {
        mismatches.push_back(row[0] + ": the tasks of " + header[m] + " add up to " + grade::format_number(sums[m]) +
                             ", " + header[m] + " is " + grade::format_number(points[m]));
      }
    }
  }
  return mismatches;
}

bool write_failed_results(const std::string& root, const std::vector<std::string>& args, const std::string& reason) {
  std::string file;
  for (std::size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] == "--json") file = tools::absolute_path(args[i + 1], root);
  }
  if (file.empty() || fs::exists(file)) return false;
  const json::Value results = {{"score", 0},
                               {"output", "The grader could not grade this submission: " + reason},
                               {"stdout_visibility", "hidden"},
                               {"tests", json::Value::array()}};
  std::error_code error;
  fs::create_directories(fs::path(file).parent_path(), error);
  const std::string temporary = file + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << json::write(results) << "\n";
    if (!out.flush()) return false;
  }
  fs::rename(temporary, file, error);
  return !error;
}

}  // namespace fmbd::frontend
