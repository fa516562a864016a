#pragma once
// Grading one tree in three steps (grade.cpp runs them, once it has taken the tree in, configured
// it and read its course manifest):
//
//  1. The plan (plan_grading): what is graded and how, decided from the course manifest, the grade
//     options and the facts of the world the front end looked up beforehand (TreeFacts): the
//     modules, the items to grade and those not started, the targets of the one build, each
//     item's program and the reference build that lists its tests, and what the grade says of the
//     identity. No file is read and no process runs; a command it refuses (--solutions without a
//     reference) is its UsageError.
//  2. The build (grade_build.hpp): the plan's targets in one build, then each item on its own, with an
//     outcome each (ItemOutcome): built, rejected by the source check (its report), broken (its
//     first errors), or skipped (it does not build, and none of the student's files is in it), and
//     whether its lister built.
//  3. The driver's invocation (driver_invocation): the programs fmbd-grade runs, each with its
//     lister and its report, made from the plan and the outcomes; driver_argv writes it as the
//     command line of fmbd-grade (autograder/driver/grade.cpp has its protocol).

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "build.hpp"
#include "manifest.hpp"

namespace fmbd::frontend {

// What a grading asks of fmbd-grade besides its programs, typed: driver_argv writes each as its
// option, in this order. The files are absolute; an empty one is not asked for.
struct DriverOptions {
  std::vector<std::string> modules;  // --module N, as given
  std::vector<std::string> tasks;    // --task MnnTk
  std::string json;                  // --json FILE: Gradescope's results.json
  std::string junit;                 // --junit FILE
  std::string csv;                   // --csv FILE: tasks.csv
  std::string timings_out;           // --timings-out FILE
  std::string timeout;               // --timeout SEC, as given; empty: the driver's default
  std::string jobs;                  // --jobs N, as given; empty: the plan's count
  std::string hidden_visibility;     // --hidden-visibility V; empty: the driver's default
  std::string earlier_note;          // --earlier-note TEXT: the advice where earlier modules' stubs fail
  bool strict = false;               // --strict: exit status 1 below a full score
};

// The grade options, checked (grade.cpp reads them from the command line).
struct GradeOptions {
  bool solutions = false;
  bool own_earlier = false;
  bool reference_earlier = false;
  bool resume = false;
  std::string submission;   // a folder (a zip is unpacked first)
  std::string submissions;  // a class
  std::string out;          // with --submissions
  std::string student;      // --student NAME, or the first user of --gradescope-metadata
  std::vector<int> modules;  // from --module and --task, in order; empty: all
  DriverOptions driver;      // what fmbd-grade is asked for
  std::string require_full;  // --require-full CAPABILITY: those items' tasks must score full
};

// The build preset of a grading: "reference" (earlier stages from the reference) for
// --reference-earlier and for a submission unless --own-earlier, else "student". `submission`:
// a submission is graded; `has_solutions`: the copy has its solutions/ folder. Throws
// UsageError for options that exclude each other or need what this copy has not.
std::string grading_preset(const GradeOptions& o, bool submission, bool has_solutions);

// What the plan needs to know of the world, looked up by the front end.
struct TreeFacts {
  std::string tree;                       // the graded tree: one's own, or a submission's copy
  std::string build;                      // its build folder (tree/build/PRESET)
  bool submission = false;                // a submission's copy (else one's own tree)
  std::set<std::string> existing_inputs;  // the graded items' inputs (relative to tree) that exist
  bool has_timings = false;               // tree/autograder/timings.txt exists
  std::string identity;                   // the identity the grader trusts, or ""
  int jobs = 1;                           // tests at once where --jobs is not given
};

// One item to grade, and how.
struct PlannedItem {
  GradedItem item;
  std::string name;     // in messages: its module's folder, or its id where it has none
  std::string target;   // what builds its program (the reference's under --solutions)
  std::string program;  // what the driver runs
  std::string log;      // the build log of `target`
  // The trusted build that lists its tests (--listed-by), or none: the program lists them.
  std::optional<std::string> lister_target;
  std::optional<std::string> lister;
  // Whether a failed build is the student's (the item scores 0 with its errors in errors_file);
  // otherwise it is not graded and the grade says to tell the instructor.
  bool student_code = true;
  std::optional<std::string> vet_target;  // the source check of its student code; none under --solutions
  std::string errors_file;                // build/compile/mNN.txt
};

// An item not started (one's own tree, none of its inputs there yet), named by its first input.
struct NotStarted {
  std::string id;
  std::string input;
};

// What the grade says of the identity and of the items without their reference.
struct IdentityNote {
  std::string identity;                  // "" where none is known
  std::vector<std::string> identified;   // the items graded with the identity's numbers
  std::vector<std::string> format_only;  // the items that check only the format of their inputs
};

struct GradingPlan {
  bool solutions = false;
  std::string tree;
  std::string build;
  std::vector<int> modules;  // the modules chosen; empty: all
  std::vector<PlannedItem> items;
  std::vector<NotStarted> not_started;
  bool problems_printable = false;   // ./workbook problems prints a not-started item's problems
  std::vector<std::string> targets;  // the one build: fmbd-grade, then each item's and lister's
  std::vector<Watched> watched;      // the outputs its progress names
  std::vector<std::string> exercises;  // the exercise files (absolute), for their warnings
  IdentityNote identity;
  // Whose code of the earlier modules the graded ones run on, a line ("workbook: module 7 runs on
  // your own code of modules 1-6; ..."); "" where no graded module has earlier ones. The advice for
  // the driver's line on earlier modules' stubs is options.earlier_note (--reference-earlier where
  // their reference is released).
  std::string earlier;
  // The driver and what every invocation of it takes.
  std::string driver;
  std::optional<std::string> timings;  // tree/autograder/timings.txt, where it exists
  std::optional<int> jobs;             // none where the user gave --jobs (it is among options)
  DriverOptions options;
};

// The plan of grading `facts.tree` with `manifest` and `o`. --solutions grades the items with a
// reference (each program the reference's) of the modules that have one: all of them, or the ones
// asked for, each of which must have one. In one's own tree (not a submission, not --solutions)
// an item with inputs none of which exists is not started: neither built nor graded. Throws
// UsageError.
GradingPlan plan_grading(const Manifest& manifest, const GradeOptions& o, const TreeFacts& facts);

// The items of `plan`, as stage_answers takes them (pointers into the plan).
std::vector<const GradedItem*> graded_items(const GradingPlan& plan);

// The line that names the items not started, or "" when there is none.
std::string not_started_message(const GradingPlan& plan);

// The lines on the identity: the items that need one graded with its numbers, or that they need
// one; the items that check only the format. "" when there is nothing to say.
std::string identity_message(const IdentityNote& note);

// How one item's build went (step 2).
enum class BuildState {
  built,     // graded
  rejected,  // the source check refused its files: its tests score 0 (--reject)
  broken,    // it does not compile: its tests score 0 with its first errors (--build-errors)
  skipped,   // it does not build, and none of the student's files is in it: not graded
};

struct ItemOutcome {
  BuildState state = BuildState::built;
  bool lister_built = false;  // its lister_target built
  std::string report;         // rejected: the source check's report; broken: its first errors
};

// A module's report for the driver: N=FILE.
struct ModuleReport {
  std::string module;
  std::string file;
};

// One program the driver runs, with the trusted program that lists its tests and the report that
// makes its module's tests fail unrun.
struct DriverProgram {
  std::string program;
  std::optional<std::string> lister;         // --listed-by LISTER after the program
  std::optional<ModuleReport> build_errors;  // --build-errors N=FILE
  std::optional<ModuleReport> rejected;      // --reject N=FILE
  // --grades-inputs after the program: it grades the student's inputs, not the module's code (its
  // item's capabilities give it inputs), so a module's --reject or --build-errors leaves it alone.
  bool grades_inputs = false;
};

struct DriverInvocation {
  std::string driver;                  // fmbd-grade
  std::optional<std::string> timings;  // --timings FILE
  std::optional<int> jobs;             // --jobs N
  DriverOptions options;
  std::vector<DriverProgram> programs;
};

// The driver's invocation for `plan` after its build (`outcomes`, one per plan item): a built or
// rejected item's program, listed by its lister where that built; a broken one's only where its
// lister built (its tests then fail with its errors); a skipped one's not. Throws UsageError
// ("nothing to grade") when no program is left.
DriverInvocation driver_invocation(const GradingPlan& plan, const std::vector<ItemOutcome>& outcomes);

// The command line of `invocation`: DRIVER [--timings FILE] [--jobs N] OPTIONS..., the --reject
// and --build-errors of the programs, then each PROGRAM [--listed-by LISTER] [--grades-inputs].
std::vector<std::string> driver_argv(const DriverInvocation& invocation);

}  // namespace fmbd::frontend
