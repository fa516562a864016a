#include "inspect.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <set>
#include <sstream>

#include "classroom.hpp"
#include "exit_status.hpp"
#include "file_io.hpp"
#include "grade.hpp"
#include "ids.hpp"
#include "listing.hpp"
#include "maintainer.hpp"
#include "process.hpp"
#include "release.hpp"
#include "strings.hpp"
#include "tables.hpp"
#include "text.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

std::string here() { return fs::current_path().string(); }

// The text of FILE, or a UsageError (exit status 2) when it cannot be read.
std::string inspected_text(const std::string& file) {
  std::string text;
  if (!fs::is_regular_file(file) || !tools::read_file(file, text)) throw UsageError("inspect: cannot read " + file);
  return text;
}

// The options that go with one format only, checked against the one asked for.
void check_options_of(const std::string& format, const ParsedOptions& options) {
  const std::vector<std::pair<const char*, const char*>> owners = {
      {"--rule", "policy"}, {"--sum", "tasks classroom"}, {"--count", "tasks classroom"},
      {"--full", "tasks"},  {"--of", "tasks"},            {"--manifest", "tasks"}};
  for (const auto& [option, owners_of] : owners) {
    const std::vector<std::string> formats = tools::split(owners_of, ' ');
    if (options.has(option) && std::find(formats.begin(), formats.end(), format) == formats.end()) {
      throw UsageError(std::string(option) + " goes with inspect " + formats.front() + ", not inspect " + format);
    }
  }
  if (format == "classroom" && options.has("--sum") && options.value("--sum") != "max_score") {
    throw UsageError("inspect classroom --sum: max_score, not '" + options.value("--sum") + "'");
  }
  if (format == "classroom" && options.has("--sum") && options.has("--count")) {
    throw UsageError("inspect classroom: --sum or --count, not both");
  }
  if (options.has("--manifest") && !options.has("--of")) throw UsageError("--manifest goes with --of");
  if (format == "policy" && !options.has("--rule")) throw UsageError("inspect policy needs --rule RULE");
  if (format == "tasks" && options.has("--sum") + options.has("--count") + options.has("--full") != 1) {
    throw UsageError("inspect tasks needs one of --sum score|max_score, --count and --full");
  }
}

// inspect tasks: the rows of FILE (those of the items with --of's capability), summed, counted or
// checked at their maximum.
int inspect_tasks(const std::string& file, const ParsedOptions& options, const Context& context) {
  std::vector<grade::TaskRow> rows = grade::parse_tasks_csv(inspected_text(file), file);
  if (options.has("--of")) {
    const Manifest manifest =
        options.has("--manifest") ? read_manifest(tools::absolute_path(options.value("--manifest"), here()))
                                  : context.manifest;
    rows = rows_of_items(std::move(rows), manifest, options.value("--of"));
  }
  if (options.has("--count")) {
    context.out << rows.size() << "\n";
  } else if (options.has("--sum")) {
    const std::string column = options.value("--sum");
    if (column != "score" && column != "max_score") throw UsageError("--sum: score or max_score, not '" + column + "'");
    double sum = 0;
    for (const grade::TaskRow& row : rows) sum += column == "score" ? row.score : row.max_score;
    context.out << grade::format_number(sum) << "\n";
  } else {  // --full
    require_full(rows, options.has("--of") ? " of the items with " + options.value("--of") : "", " in " + file,
                 context.out);
  }
  return kExitOk;
}

// inspect classroom: the workflow's command-grader steps, "ID<TAB>MAX_SCORE<TAB>COMMAND" each, or
// how many (--count), or their points (--sum max_score).
int inspect_classroom(const std::string& file, const ParsedOptions& options, const Context& context) {
  const std::vector<ClassroomStep> steps = parse_classroom_steps(inspected_text(file), file);
  double points = 0;
  for (const ClassroomStep& step : steps) points += step.max_score;
  if (options.has("--count")) {
    context.out << steps.size() << "\n";
  } else if (options.has("--sum")) {
    context.out << grade::format_number(points) << "\n";
  } else {
    for (const ClassroomStep& step : steps) {
      context.out << step.id << "\t" << grade::format_number(step.max_score) << "\t" << step.command << "\n";
    }
  }
  return kExitOk;
}

// inspect listing: a test program's --fmbd-list output (FILE), read as the grade driver reads it:
// "MNN<TAB>NAME" of each test ("other" for a test of no module), or exit 1 with the driver's reason.
int inspect_listing(const std::string& file, const Context& context) {
  const grade::ParsedList listing = grade::parse_test_list(inspected_text(file), file);
  if (!listing.error.empty()) throw StepFailed("inspect: " + file + ": " + listing.error);
  for (const grade::TestCase& test : listing.tests) context.out << grade::module_label(test.module) << "\t" << test.name << "\n";
  return kExitOk;
}

// inspect gradebook: its columns add up, or the submissions whose do not are named.
int inspect_gradebook(const std::string& file, const Context& context) {
  const std::vector<std::string> mismatches = gradebook_mismatches(inspected_text(file), file);
  for (const std::string& line : mismatches) context.out << line << "\n";
  if (!mismatches.empty()) throw StepFailed("inspect: the columns of " + file + " do not add up (above)");
  return kExitOk;
}

}  // namespace

const CommandSpec& inspect_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "inspect";
    s.options = {{"--rule", OptionKind::value, "RULE", "a rule of the policy", "policy: the arguments of RULE"},
                 {"--sum", OptionKind::value, "COLUMN", "score or max_score", "tasks, classroom: the column's sum"},
                 {"--count", OptionKind::flag, "", "", "tasks, classroom: how many"},
                 {"--full", OptionKind::flag, "", "", "tasks: each at its maximum"},
                 {"--of", OptionKind::value, "CAPABILITY", "a capability of the manifest", "tasks: of those items"},
                 {"--manifest", OptionKind::value, "FILE", "a file name", "tasks --of: the build that graded"}};
    s.positional = "FORMAT FILE";
    s.max_positionals = 2;
    s.too_many = "inspect takes a format and a file, e.g. ./workbook inspect gradebook grades/gradebook.csv";
    s.synopsis =
        "tasks FILE (--sum score|max_score | --count | --full)\n"
        "        [--of CAPABILITY [--manifest FILE]]\n"
        "        | gradebook FILE | timings FILE | policy FILE --rule RULE\n"
        "        | classroom FILE [--sum max_score | --count] | listing FILE | bench FILE";
    s.help = {"Read a file of the workbook's own for a script, through the code that writes it.",
              "tasks: a --csv table of tasks: a column's sum, the number of tasks, or --full:",
              "exit 1 naming each task below its maximum. --of CAPABILITY (inputs,",
              "needs_identity, links_student_code, classroom): only the tasks of the graded items",
              "with it, as their built programs list them (--manifest: the course.json of the",
              "build that graded). gradebook: exit 1 naming each submission whose columns do not",
              "add up. timings: MNN<TAB>NAME of each timed test. policy: the arguments of the",
              "release policy's RULE. classroom: a workflow's command-grader steps,",
              "ID<TAB>MAX_SCORE<TAB>COMMAND each, their --count or --sum max_score. listing: a test",
              "program's --fmbd-list output as the grade driver reads it, MNN<TAB>NAME of each test.",
              "bench: a benchmark CSV's number of rows. A file that is not in its format: exit 1."};
    return s;
  }();
  return spec;
}

int run_inspect(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(inspect_command(), args);
  if (print_usage_if_asked(options, inspect_command(), context.out)) return 0;
  constexpr const char* kFormats = "tasks, gradebook, timings, policy, classroom, listing, bench";
  if (options.positionals.size() != 2) {
    throw UsageError(std::string("inspect needs a format (") + kFormats + ") and a file");
  }
  const std::string& format = options.positionals[0];
  const std::string file = tools::absolute_path(options.positionals[1], here());
  const std::string listed = std::string(", ") + kFormats + ",";
  if (format.empty() || listed.find(", " + format + ",") == std::string::npos) {
    throw UsageError("inspect: no format '" + format + "' (" + kFormats + ")");
  }
  check_options_of(format, options);
  try {
    if (format == "tasks") return inspect_tasks(file, options, context);
    if (format == "gradebook") return inspect_gradebook(file, context);
    if (format == "classroom") return inspect_classroom(file, options, context);
    if (format == "listing") return inspect_listing(file, context);
    if (format == "bench") {
      context.out << parse_bench_csv(inspected_text(file), file).size() << " rows\n";
      return kExitOk;
    }
    if (format == "timings") {
      for (const grade::Timing& timing : grade::parse_timings(inspected_text(file), file)) {
        context.out << timing.module << "\t" << timing.name << "\n";
      }
      return kExitOk;
    }
    const std::string text = inspected_text(file);
    ReleasePolicy policy;
    try {
      policy = parse_policy(text, file);
    } catch (const UsageError& error) {  // a file not in its format, not a wrong command line
      throw StepFailed(error.what());
    }
    for (const std::string& argument : policy_rule(policy, options.value("--rule"))) context.out << argument << "\n";
    return kExitOk;
  } catch (const grade::TableError& error) {
    throw StepFailed(error.what());
  }
}

}  // namespace fmbd::frontend
