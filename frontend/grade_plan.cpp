#include "grade_plan.hpp"

#include <algorithm>

#include "layout.hpp"
#include "options.hpp"

// Pure: no file is read, no process runs (grade_plan.hpp).
namespace fmbd::frontend {
namespace {

bool selected(const std::vector<int>& modules, int module) {
  return modules.empty() || std::count(modules.begin(), modules.end(), module) > 0;
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

// --solutions grades the modules whose reference this copy carries (a release may carry some):
// all of them, or the ones asked for, each of which must have one. Otherwise the modules asked for.
std::vector<int> graded_modules(const Manifest& manifest, const GradeOptions& o) {
  if (!o.solutions) return o.modules;
  std::string with_reference;
  std::vector<int> numbers;
  for (const GradedItem& item : manifest.graded) {
    if (item.reference_program && !std::count(numbers.begin(), numbers.end(), item.module)) {
      with_reference += " " + std::to_string(item.module);  // once, though a module has several items
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

// How `item` is graded: its own build, or the reference's under --solutions.
PlannedItem planned(const Manifest& manifest, const GradedItem& item, const std::string& build, bool solutions) {
  PlannedItem p;
  p.item = item;
  p.name = name_of(manifest, item);
  p.target = solutions ? *item.reference_target : item.target;
  p.program = solutions ? *item.reference_program : item.program;
  p.log = build + "/" + p.target + ".build.log";
  // A student's program could print any list (docs/decisions.md): the reference build lists.
  if (!solutions && item.reference_target && item.reference_program) {
    p.lister_target = item.reference_target;
    p.lister = item.reference_program;
  }
  p.student_code = item.links_student_code || solutions;
  if (!solutions) p.vet_target = item.vet_target;
  p.errors_file = BuildLayout{build}.errors_file(item.id);
  return p;
}

// The items of the chosen modules (under --solutions those with a reference). In one's own
// tree, an item with inputs none of which exists yet (tutorial problems without an answers file)
// is not started, so neither built nor graded: a first grade costs the code's build only. A
// submission's are always graded.
void choose_items(const Manifest& manifest, const GradeOptions& o, const TreeFacts& facts, GradingPlan& plan) {
  const bool own_tree = !facts.submission && !o.solutions;
  for (const GradedItem& item : manifest.graded) {
    if (!selected(plan.modules, item.module)) continue;
    if (o.solutions && !(item.reference_target && item.reference_program)) continue;
    const auto exists = [&facts](const std::string& file) { return facts.existing_inputs.count(file) > 0; };
    if (own_tree && !item.inputs.empty() && std::none_of(item.inputs.begin(), item.inputs.end(), exists)) {
      plan.not_started.push_back({item.id, item.inputs.front()});
      plan.problems_printable = plan.problems_printable || item.has_personal_problems();
      continue;
    }
    plan.items.push_back(planned(manifest, item, facts.build, o.solutions));
  }
}

// The lines of progress a build of these items may print.
std::vector<Watched> watched_outputs(const Manifest& manifest, const std::vector<PlannedItem>& items) {
  std::vector<Watched> watched{{manifest.grade_driver, "the grade driver is ready"}};
  for (const PlannedItem& planned : items) {
    const GradedItem& item = planned.item;
    const std::string module = "module " + std::to_string(item.module) + ": ";
    const Module* m = manifest.module(item.module);
    if (m && item.links_student_code) watched.push_back({m->student_library, module + "your code compiled"});
    if (m && m->reference_library) watched.push_back({*m->reference_library, module + "the reference compiled"});
    watched.push_back({item.program, module + item.id + " is ready"});
    if (item.reference_program) watched.push_back({*item.reference_program, module + item.id + "'s lister is ready"});
  }
  // Each output once (a module's items share its libraries; an item may be its own lister).
  std::vector<Watched> unique;
  for (const Watched& output : watched) {
    const bool seen = std::any_of(unique.begin(), unique.end(), [&output](const Watched& w) { return w.path == output.path; });
    if (!seen) unique.push_back(output);
  }
  return unique;
}

// Every item's target and its lister's in one build that keeps going past errors (both cores stay
// busy), after the grade driver's.
void plan_build(const Manifest& manifest, const std::string& tree, GradingPlan& plan) {
  plan.targets = {"fmbd-grade"};
  for (const PlannedItem& item : plan.items) {
    plan.targets.push_back(item.target);
    if (item.lister_target) plan.targets.push_back(*item.lister_target);
  }
  plan.watched = watched_outputs(manifest, plan.items);
  for (const Module& module : manifest.modules) {
    for (const std::string& file : module.exercises) plan.exercises.push_back(tree + "/" + file);
  }
}

IdentityNote identity_note(const std::vector<PlannedItem>& items, const std::string& identity) {
  IdentityNote note;
  note.identity = identity;
  for (const PlannedItem& planned : items) {
    const GradedItem& item = planned.item;
    if (item.needs_identity) note.identified.push_back(item.id);
    if (!item.reference_program && item.without_reference == WithoutReference::format) {
      note.format_only.push_back(item.id);
    }
  }
  return note;
}

std::string joined(const std::vector<std::string>& ids) {
  std::string text;
  for (const std::string& id : ids) text += " " + id;
  return text;
}

// "1", "1-6", "1, 3-5": module numbers, ascending, runs joined.
std::string module_ranges(const std::vector<int>& numbers) {
  std::string text;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    text += (text.empty() ? "" : ", ") + std::to_string(numbers[i]) + (j > i ? "-" + std::to_string(numbers[j]) : "");
    i = j + 1;
  }
  return text;
}

std::string modules_word(const std::vector<int>& numbers) {
  return (numbers.size() == 1 ? "module " : "modules ") + module_ranges(numbers);
}

// plan.earlier and the advice of plan.options.earlier_note (grade_plan.hpp): whose earlier modules
// the graded code runs on (the preset grading_preset chose), and, where an earlier module's task is
// not implemented yet, how to grade on its released reference (solutions/) or that there is none.
void plan_earlier(const Manifest& manifest, const GradeOptions& o, const TreeFacts& facts, GradingPlan& plan) {
  int last = 0;
  for (const PlannedItem& item : plan.items)
    if (item.item.links_student_code) last = std::max(last, item.item.module);
  std::vector<int> graded, released, own;
  for (const PlannedItem& item : plan.items)
    if (item.item.links_student_code && item.item.module > 1 && !std::count(graded.begin(), graded.end(), item.item.module))
      graded.push_back(item.item.module);
  for (const Module& module : manifest.modules) {
    if (module.number >= last) continue;
    (module.reference_library ? released : own).push_back(module.number);
  }
  if (graded.empty() || (released.empty() && own.empty())) return;
  std::vector<int> earlier = released;
  earlier.insert(earlier.end(), own.begin(), own.end());
  std::sort(earlier.begin(), earlier.end());
  std::sort(graded.begin(), graded.end());
  const std::string head = "workbook: " + modules_word(graded) + (graded.size() == 1 ? " runs" : " run") + " on ";
  if (o.solutions) {
    plan.earlier = head + "the reference solutions of " + modules_word(earlier) + "\n";
  } else if (facts.submission) {
    plan.earlier = head + (o.own_earlier ? "the submission's own code of " + modules_word(earlier) + " (--own-earlier)"
                                         : "the reference of " + modules_word(earlier) + " (--own-earlier: on the submission's own)") +
                   "\n";
  } else if (o.reference_earlier) {
    plan.earlier = head + (released.empty() ? "" : "the released reference (solutions/) of " + modules_word(released)) +
                   (released.empty() || own.empty() ? "" : " and ") +
                   (own.empty() ? "" : "your own code of " + modules_word(own) + " (no reference of it released)") + "\n";
    plan.options.earlier_note = "Their reference is not released here (solutions/): finish them first.";
  } else {
    plan.earlier = head + "your own code of " + modules_word(earlier) +
                   (released.empty() ? "" : " (--reference-earlier: on the released reference of " + modules_word(released) + ")") +
                   "\n";
    std::string command = "./workbook grade --reference-earlier";
    for (const int module : o.modules) command += " --module " + std::to_string(module);
    for (const std::string& task : o.driver.tasks) command += " --task " + task;
    plan.options.earlier_note =
        released.empty() ? "No earlier module's reference is released here (solutions/): finish them first."
                         : "Finish them, or grade on the released reference of " + modules_word(released) + ": " + command;
  }
}

}  // namespace

std::string grading_preset(const GradeOptions& o, bool submission, bool has_solutions) {
  if (o.reference_earlier) {
    if (submission) {
      throw UsageError("--reference-earlier is for your own code; a --submission is graded on the reference anyway");
    }
    if (!has_solutions) {
      throw UsageError("--reference-earlier: no module's reference has been released here (no solutions/ folder)");
    }
  }
  if (submission && o.solutions) throw UsageError("--solutions and --submission exclude each other");
  if (submission && !has_solutions) throw UsageError("--submission needs the solutions/ folder (an instructor's copy)");
  return (submission && !o.own_earlier) || o.reference_earlier ? "reference" : "student";
}

GradingPlan plan_grading(const Manifest& manifest, const GradeOptions& o, const TreeFacts& facts) {
  GradingPlan plan;
  plan.solutions = o.solutions;
  plan.tree = facts.tree;
  plan.build = facts.build;
  plan.modules = graded_modules(manifest, o);
  choose_items(manifest, o, facts, plan);
  plan_build(manifest, facts.tree, plan);
  plan.identity = identity_note(plan.items, facts.identity);
  plan.driver = manifest.grade_driver;
  // Each test's timeout follows the reference's own time for it (autograder/timings.txt, written
  // by ./workbook bench): a loop costs seconds, not --timeout.
  if (facts.has_timings) plan.timings = timings_path(facts.tree);
  if (o.driver.jobs.empty()) plan.jobs = facts.jobs;
  plan.options = o.driver;
  plan_earlier(manifest, o, facts, plan);
  return plan;
}

std::vector<const GradedItem*> graded_items(const GradingPlan& plan) {
  std::vector<const GradedItem*> items;
  for (const PlannedItem& planned : plan.items) items.push_back(&planned.item);
  return items;
}

std::string not_started_message(const GradingPlan& plan) {
  if (plan.not_started.empty()) return "";
  std::string text = "workbook: not started (no file of its answers yet), so not graded here:";
  for (const NotStarted& item : plan.not_started) text += " " + item.id + " (" + item.input + ")";
  return text + (plan.problems_printable ? "; ./workbook problems MNN prints the problems" : "") + "\n";
}

std::string identity_message(const IdentityNote& note) {
  std::string text;
  const std::string identified = joined(note.identified);
  if (!identified.empty() && note.identity.empty()) {
    text += "workbook: the numbers of" + identified +
            " depend on your name: ./workbook grade --student \"YOUR NAME\" "
            "(or ./workbook problems --student \"YOUR NAME\" once)\n";
  } else if (!identified.empty()) {
    text += "workbook:" + identified + " graded with the numbers of \"" + note.identity + "\"\n";
  }
  if (!note.format_only.empty()) {
    text += "workbook:" + joined(note.format_only) +
            " without the reference here: only the format of the answers is checked; your instructor's grader "
            "checks the values\n";
  }
  return text;
}

namespace {

// The options of `o`, in the order of DriverOptions, at the end of `argv`.
void append_options(const DriverOptions& o, std::vector<std::string>& argv) {
  for (const std::string& module : o.modules) argv.insert(argv.end(), {"--module", module});
  for (const std::string& task : o.tasks) argv.insert(argv.end(), {"--task", task});
  const std::pair<const char*, const std::string*> values[] = {
      {"--json", &o.json},       {"--junit", &o.junit}, {"--csv", &o.csv},
      {"--timings-out", &o.timings_out}, {"--timeout", &o.timeout}, {"--jobs", &o.jobs},
      {"--hidden-visibility", &o.hidden_visibility}, {"--earlier-note", &o.earlier_note}};
  for (const auto& [option, value] : values) {
    if (!value->empty()) argv.insert(argv.end(), {option, *value});
  }
  if (o.strict) argv.push_back("--strict");
}

}  // namespace

DriverInvocation driver_invocation(const GradingPlan& plan, const std::vector<ItemOutcome>& outcomes) {
  DriverInvocation invocation{plan.driver, plan.timings, plan.jobs, plan.options, {}};
  for (std::size_t i = 0; i < plan.items.size() && i < outcomes.size(); ++i) {
    const PlannedItem& item = plan.items[i];
    const ItemOutcome& outcome = outcomes[i];
    if (outcome.state == BuildState::skipped) continue;
    // A broken item's tests count as failed only where its lister says which they are.
    if (outcome.state == BuildState::broken && !outcome.lister_built) continue;
    DriverProgram program{item.program, std::nullopt, std::nullopt, std::nullopt, !item.item.inputs.empty()};
    if (outcome.lister_built) program.lister = item.lister;
    if (outcome.state == BuildState::broken) {
      program.build_errors = ModuleReport{std::to_string(item.item.module), outcome.report};
    }
    if (outcome.state == BuildState::rejected) program.rejected = ModuleReport{item.item.id.substr(1), outcome.report};
    invocation.programs.push_back(program);
  }
  if (invocation.programs.empty()) throw UsageError("nothing to grade");
  return invocation;
}

std::vector<std::string> driver_argv(const DriverInvocation& invocation) {
  std::vector<std::string> argv{invocation.driver};
  if (invocation.timings) argv.insert(argv.end(), {"--timings", *invocation.timings});
  if (invocation.jobs) argv.insert(argv.end(), {"--jobs", std::to_string(*invocation.jobs)});
  append_options(invocation.options, argv);
  for (const DriverProgram& program : invocation.programs) {
    if (program.rejected) argv.insert(argv.end(), {"--reject", program.rejected->module + "=" + program.rejected->file});
    if (program.build_errors) {
      argv.insert(argv.end(), {"--build-errors", program.build_errors->module + "=" + program.build_errors->file});
    }
  }
  for (const DriverProgram& program : invocation.programs) {
    argv.push_back(program.program);
    if (program.lister) argv.insert(argv.end(), {"--listed-by", *program.lister});
    if (program.grades_inputs) argv.push_back("--grades-inputs");
  }
  return argv;
}

}  // namespace fmbd::frontend
