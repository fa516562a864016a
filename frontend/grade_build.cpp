#include "grade_build.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "build.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "layout.hpp"
#include "submission.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

// Whether the source check ran: it writes its report (vet_join.cmake), empty when all is well, and
// fails its target only with findings in it.
bool vet_ran(const std::string& report) {
  std::error_code error;
  return fs::exists(report) && fs::file_size(report, error) > 0;
}

// The source check of the exercise files that `item`'s program links (its plan's vet_target):
// nothing when it passed or there is none; when it refused a file, its report (the manifest's
// vet_report, for the driver's --reject), said here. A check that could not run (a fault of the
// build, not of the code) is tried once more after building the item again, then is a BuildError:
// code that was never checked scores nothing, not 0.
std::optional<std::string> vet(const std::string& build, const PlannedItem& item, std::ostream& out) {
  if (!item.vet_target || !item.item.vet_report) return std::nullopt;
  const std::string& report = *item.item.vet_report;
  const std::string log = build + "/" + *item.vet_target + ".log";
  for (int attempt = 0; attempt < 2; ++attempt) {
    std::error_code error;
    fs::remove(report, error);
    if (build_target(build, *item.vet_target, log)) return std::nullopt;
    if (vet_ran(report)) break;
    if (attempt == 1) {
      throw BuildError("the source check of " + item.name + " could not run, twice (its log: " + log +
                       "). This is a fault of the build folder, not of your code, which was not graded. Fix: delete " +
                       build + " and run the same command again; if it fails again, tell your instructor (the log "
                       "says why)");
    }
    out << "workbook: the source check of " << item.name << " could not run (" << log
        << "); building " << item.name << " again and trying once more\n" << std::flush;
    build_target(build, item.target, item.log);
  }
  std::string text;
  tools::read_file(report, text);
  out << "workbook: " << item.name << " was rejected by the source check (its tests score 0):\n" << text;
  return report;
}

// An item that built: its lister (a student's program could print any list: README,
// "Decisions"), then the source check.
ItemOutcome built_item(const std::string& build, const PlannedItem& item, std::ostream& out) {
  ItemOutcome outcome;
  if (item.lister_target) {
    const std::string log = build + "/" + *item.lister_target + ".build.log";
    outcome.lister_built = build_target(build, *item.lister_target, log);
    if (!outcome.lister_built) {
      out << "workbook: the reference of " << item.name << " does not build (" << log
          << "); its tests are listed by your build\n";
    }
  }
  if (const std::optional<std::string> report = vet(build, item, out)) {
    outcome.state = BuildState::rejected;
    outcome.report = *report;
  }
  return outcome;
}

// An item that does not build: its first errors shown and kept; with its lister at hand, its
// test list makes every test of the module count as failed, with the errors as their output.
ItemOutcome broken_item(const std::string& root, const std::string& build, const PlannedItem& item,
                        std::ostream& out) {
  const std::string text = first_errors(item.log, item.name, {submission_tree(root), root});
  std::ofstream(item.errors_file) << text;
  out << "workbook: " << item.name << " does not compile; the first errors (all in " << item.log << "):\n" << text;
  std::error_code error;
  fs::remove(item.program, error);  // never grade a stale build
  ItemOutcome outcome{BuildState::broken, false, item.errors_file};
  outcome.lister_built = item.lister_target && build_target(build, *item.lister_target, "/dev/null");
  return outcome;
}

ItemOutcome build_item(const std::string& root, const std::string& build, const PlannedItem& item, std::ostream& out) {
  out << "workbook: building " << item.name << " ...\n" << std::flush;
  if (build_target(build, item.target, item.log)) return built_item(build, item, out);
  if (!item.student_code) {  // not the student's doing
    out << "workbook: " << item.item.id << " does not build (" << item.log
        << "), and none of your files is in it: it is not graded here; tell your instructor\n";
    return ItemOutcome{BuildState::skipped, false, ""};
  }
  return broken_item(root, build, item, out);
}

}  // namespace

// One build of every target, the grade driver, then each item (grade_build.hpp).
std::vector<ItemOutcome> build_planned(const std::string& root, const GradingPlan& plan, std::ostream& out) {
  const std::string& build = plan.build;
  const BuildLayout layout{build};
  build_with_progress(build, layout.build_log("grade"), plan.targets, plan.watched, plan.tree, plan.exercises, out);
  if (!build_target(build, "fmbd-grade", layout.build_log("fmbd-grade"))) {
    throw BuildError("building the grade driver failed (" + layout.build_log("fmbd-grade") + ")");
  }
  fs::create_directories(BuildLayout{build}.compile_logs());
  std::vector<ItemOutcome> outcomes;
  std::string broken, rejected;  // the folders that do not compile, that the source check refused
  for (const PlannedItem& item : plan.items) {
    outcomes.push_back(build_item(root, build, item, out));
    if (outcomes.back().state == BuildState::broken) broken += " " + item.name;
    if (outcomes.back().state == BuildState::rejected) rejected += " " + item.name;
  }
  if (!broken.empty()) out << "workbook: these modules do not compile and score 0 (errors above):" << broken << "\n";
  if (!rejected.empty()) {
    out << "workbook: these modules were rejected by the source check and score 0 (reasons above):" << rejected
        << "\n";
  }
  show_warnings(build, out);
  return outcomes;
}

}  // namespace fmbd::frontend
