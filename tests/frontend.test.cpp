// The front end's library (frontend/): JSON, CSV, option tables, ids, the job count, hint ladders
// and the course manifest, the latter also as this build wrote it, checked against the tree.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "commands.hpp"
#include "csv.hpp"
#include "demo.hpp"
#include "exit_status.hpp"
#include "build.hpp"
#include "grade.hpp"
#include "grade_plan.hpp"
#include "grading.hpp"
#include "grading_protocol.hpp"
#include "hints.hpp"
#include "ids.hpp"
#include "inspect.hpp"
#include "jobs.hpp"
#include "layout.hpp"
#include "json.hpp"
#include "manifest.hpp"
#include "maintainer.hpp"
#include "markdown.hpp"
#include "classroom.hpp"
#include "release.hpp"
#include "options.hpp"
#include "tables.hpp"
#include "task_id.hpp"

namespace fs = std::filesystem;
using namespace fmbd::frontend;
namespace json = fmbd::json;
namespace csv = fmbd::csv;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A fresh folder for one test, removed with it.
struct Scratch {
  fs::path path;
  explicit Scratch(const std::string& name) {
    path = fs::temp_directory_path() / ("fmbd-frontend-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() { fs::remove_all(path); }
};

// The message of the UsageError that `run` throws, or "" when it throws none.
template <typename Run>
std::string usage_error(Run run) {
  try {
    run();
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Exit status: a script tells a typo from a failed build and from failed tests", "[frontend][exit]") {
  CHECK(exit_status_of(UsageError("--module needs a number")) == 2);
  CHECK(exit_status_of(BuildError("building build/ci failed")) == 3);
  CHECK(exit_status_of(ManifestError("build/student/course.json: schema 0")) == 3);
  CHECK(exit_status_of(StepFailed("these demos failed: spin_up_beam")) == 1);
  CHECK(exit_status_of(std::runtime_error("cannot write results.json")) == 4);
  // The help states the same table.
  const std::string help = exit_status_help();
  for (const char* part : {"0 done", "1 a step failed", "2 a wrong command", "3 configuring or building failed",
                           "4 any other error"})
    CHECK(help.find(part) != std::string::npos);
}

TEST_CASE("JSON: a document goes round through write and parse unchanged", "[frontend][json]") {
  const json::Value value = {{"schema", 1},
                             {"name", "a \"quoted\" name\twith\ncontrol \x01 and UTF-8: \xCF\x86"},
                             {"ratio", 0.1},
                             {"big", 1e300},
                             {"negative", -42},
                             {"flags", {true, false, nullptr}},
                             {"empty", json::Value::array()},
                             {"nested", {{"inner", json::Value::object()}}}};
  CHECK(json::parse(json::write(value)) == value);
  CHECK(json::write({{"a", nullptr}, {"b", json::Value::array()}}) == "{\n  \"a\": null,\n  \"b\": []\n}");
  CHECK(json::write(value).find("\"name\": \"a \\\"quoted\\\" name\\twith\\ncontrol \\u0001 and UTF-8: \xCF\x86\"") !=
        std::string::npos);
  // Points and seconds: whole numbers without a fraction (Gradescope's and CMake's readers).
  CHECK(json::write({json::whole_or_fraction(26), json::whole_or_fraction(0.5), json::whole_or_fraction(-3)}) ==
        "[\n  26,\n  0.5,\n  -3\n]");
  // Test output is any bytes: what is not UTF-8 becomes U+FFFD, the text stays valid JSON.
  const std::string repaired = json::write(json::Value("invalid \xff\xfe and \xc3\x28"));
  CHECK(repaired.find("\xff") == std::string::npos);
  CHECK(json::parse(repaired).get<std::string>().find("\xEF\xBF\xBD") != std::string::npos);
}

TEST_CASE("JSON: escapes and numbers are read as the standard says", "[frontend][json]") {
  const json::Value value = json::parse(R"( {"s": "a\u00e9\ud83d\ude00\n\/", "n": -12.5e1, "z": 0} )");
  CHECK(value["s"] == "a\xC3\xA9\xF0\x9F\x98\x80\n/");
  CHECK(value["n"].get<double>() == -125.0);
  CHECK(value["z"].get<double>() == 0.0);
  CHECK(value.find("missing") == value.end());
  CHECK(value.begin().key() == "s");  // the order of the text
}

TEST_CASE("JSON: malformed text is refused with its line and column", "[frontend][json]") {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      json::parse(text);
    } catch (const json::ParseError& error) {
      return error.what();
    }
    return "";
  };
  CHECK(error_of("{\n  \"a\": 1,\n}").find("line 3, column 1: ") == 0);
  CHECK(error_of("[1 2]").find("line 1, column 4: ") == 0);
  CHECK(error_of("{\"a\": 1, \"a\": 2}") == "duplicate key \"a\"");
  CHECK(error_of("{\"o\": {\"a\": 1}, \"p\": {\"a\": 2}}").empty());  // one key in two objects
  CHECK(error_of("[01]").find("line 1, column 3: ") == 0);
  CHECK(error_of("\"tab\there\"").find("line 1, column 5: ") == 0);
  CHECK(error_of("[1] x").find("line 1, column 5: ") == 0);
  CHECK(error_of("\"\\ud800\"").find("U+DC00..U+DFFF") != std::string::npos);
  CHECK(error_of("").find("line 1, column 1: ") == 0);
  CHECK(error_of("nul").find("line 1, column ") == 0);
  CHECK(error_of("// comment\n1").find("line 1, column ") == 0);  // no comments
  CHECK(error_of("[1,]").find("line 1, column 4: ") == 0);        // no trailing commas
  CHECK(error_of("[NaN]").find("line 1, column 2: ") == 0);
  CHECK(error_of("[1e999]").find("1e999") != std::string::npos);
  CHECK(error_of("[1] x").find("[json.exception") == std::string::npos);  // the library's words only
  try {
    json::parse("{\n\n   tru}");
    FAIL("parsed");
  } catch (const json::ParseError& error) {
    CHECK(error.line() == 3);
    CHECK(error.column() >= 4);
  }
}

TEST_CASE("CSV: fields with commas, quotes or line breaks are quoted", "[frontend][csv]") {
  CHECK(csv::field("plain") == "plain");
  CHECK(csv::field("") == "");
  CHECK(csv::field("a,b") == "\"a,b\"");
  CHECK(csv::field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv::field("two\nlines") == "\"two\nlines\"");
  CHECK(csv::field("cr\r") == "\"cr\r\"");
  CHECK(csv::row({"M01", "T1", "3,5", ""}) == "M01,T1,\"3,5\",\n");
  // What row() writes, split() reads back.
  const std::vector<std::string> fields{"a,b", "say \"hi\"", "", "plain", "x\"", ","};
  std::string line = csv::row(fields);
  line.pop_back();  // its newline
  CHECK(csv::split(line) == fields);
  CHECK(csv::split("") == std::vector<std::string>{""});
}

TEST_CASE("Gradebook: a submission's summary and the class's columns from tasks.csv", "[frontend][gradebook]") {
  const Scratch scratch("gradebook");
  const fs::path out = scratch.path / "class results";
  const std::string header = "module,task,score,max_score,status\n";
  write_file(out / "alice/tasks.csv", header + "M01,T1,4,4,passed\nM01,T2,1.5,3,failed\nM02,T1,2,2,passed\n");
  write_file(out / "bob/tasks.csv", header + "M01,T1,0,4,build_error\nM01,T2,0,3,build_error\n"
                                              "M02,T1,0,2,timed_out\n");
  write_file(out / "carol, jr/tasks.csv", "");  // grading failed: no rows

  const fmbd::grade::SummaryRow alice = summarise_tasks("alice", (out / "alice/tasks.csv").string());
  CHECK(alice.submission == "alice");
  CHECK(alice.score == 7.5);
  CHECK(alice.max_score == 9.0);
  CHECK(alice.status == "graded");
  const fmbd::grade::SummaryRow bob = summarise_tasks("bob", (out / "bob/tasks.csv").string());
  CHECK(bob.score == 0);
  CHECK(bob.status == "build_error:M01 timed_out:M02T1");  // a module once, a task each
  const fmbd::grade::SummaryRow carol = summarise_tasks("carol, jr", (out / "carol, jr/tasks.csv").string());
  CHECK(carol.status == "error");
  CHECK_FALSE(carol.max_score.has_value());

  for (const fmbd::grade::SummaryRow& row : {alice, bob, carol}) {
    write_file(out / row.submission / "summary.csv", fmbd::grade::summary_csv_text(row));
  }
  write_gradebook(out.string());
  CHECK(read_file(out / "gradebook.csv") ==
        "submission,score,max_score,status,M01,M02,M01T1,M01T2,M02T1\n"
        "alice,7.5,9,graded,5.5,2,4,1.5,2\n"
        "bob,0,9,build_error:M01 timed_out:M02T1,0,0,0,0,0\n"
        "\"carol, jr\",0,,error,,,,,\n");

  // Read back: the columns add up (an empty cell counts 0) ...
  const std::string book = read_file(out / "gradebook.csv");
  CHECK(gradebook_mismatches(book, "gradebook.csv").empty());
  // ... or the submission is named, with the columns that do not: a task, then a score changed.
  std::string wrong_task = book;
  wrong_task.replace(wrong_task.find("alice,7.5,9,graded,5.5,2,4,"), 27, "alice,7.5,9,graded,5.5,2,3,");
  CHECK(gradebook_mismatches(wrong_task, "gradebook.csv") ==
        std::vector<std::string>{"alice: the tasks of M01 add up to 4.5, M01 is 5.5"});
  std::string wrong_score = book;
  wrong_score.replace(wrong_score.find("bob,0,"), 6, "bob,1,");
  CHECK(gradebook_mismatches(wrong_score, "gradebook.csv") ==
        std::vector<std::string>{"bob: the modules add up to 0, the score is 1"});
  // What is not a gradebook is refused, with its line.
  const auto table_error = [](const std::string& text) {
    try {
      gradebook_mismatches(text, "gradebook.csv");
    } catch (const fmbd::grade::TableError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  CHECK(table_error("module,task,score,max_score,status\n").find("gradebook.csv:1: not a gradebook") == 0);
  std::string short_row = book;
  short_row.replace(short_row.find(",0,0,0,0,0\n"), 11, ",0,0\n");
  CHECK(table_error(short_row).find("gradebook.csv:3: expected the 9 columns of the header") == 0);
  CHECK(table_error(book + "dave,x,9,graded,0,0,0,0,0\n").find("gradebook.csv:5: ") == 0);
}

TEST_CASE("Tables: tasks.csv, summary.csv and the timings, written and read back by their code", "[frontend][tables]") {
  namespace grade = fmbd::grade;
  const std::vector<grade::TaskRow> rows = {{"M01", "T1", 4, 4, "passed"}, {"M01", "P2", 1.5, 3, "failed"},
                                            {"other", "-", 0, 0, "crashed"}};
  const std::string text = grade::tasks_csv_text(rows);
  CHECK(text == "module,task,score,max_score,status\nM01,T1,4,4,passed\nM01,P2,1.5,3,failed\nother,-,0,0,crashed\n");
  const std::vector<grade::TaskRow> back = grade::parse_tasks_csv(text, "tasks.csv");
  REQUIRE(back.size() == 3);
  CHECK((back[1].id() == "M01P2" && back[1].score == 1.5 && back[1].max_score == 3 && back[1].status == "failed"));
  CHECK(grade::parse_tasks_csv("", "tasks.csv").empty());  // the driver wrote nothing
  const auto table_error = [](const auto& read, const std::string& text) {
    try {
      read(text, "FILE");
    } catch (const grade::TableError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  const auto tasks = [](const std::string& t, const std::string& o) { return grade::parse_tasks_csv(t, o); };
  CHECK(table_error(tasks, "submission,score\n").find("FILE:1: not a table of tasks") == 0);
  CHECK(table_error(tasks, "module,task,score,max_score,status\nM01,T1,four,4,passed\n") ==
        "FILE:2: expected MODULE,TASK,SCORE,MAX_SCORE,STATUS, got: M01,T1,four,4,passed");
  CHECK(table_error(tasks, "module,task,score,max_score,status\nM01,T1,4,4\n").find("FILE:2: ") == 0);

  const std::vector<grade::Timing> timings = {{"M01", false, 0.02, "rotation: A is orthonormal"},
                                              {"M01", true, 1.5, "four-bar: a\tname with a tab"}};
  const std::string timed = grade::timings_text(timings);
  CHECK(timed.find("# The reference's seconds per graded test") == 0);
  CHECK(timed.find("\nM01\tvisible\t0.02\trotation: A is orthonormal\nM01\thidden\t1.5\tfour-bar: a\tname") !=
        std::string::npos);
  const std::vector<grade::Timing> read = grade::parse_timings(timed, "timings.txt");
  REQUIRE(read.size() == 2);
  CHECK((read[1].hidden && read[1].seconds == 1.5 && read[1].name == "four-bar: a\tname with a tab"));
  const auto timing = [](const std::string& t, const std::string& o) { return grade::parse_timings(t, o); };
  CHECK(table_error(timing, "# a comment\nM01 0.01 rotation\n") ==
        "FILE:2: expected MNN<TAB>visible|hidden<TAB>SECONDS<TAB>NAME, got: M01 0.01 rotation");
  CHECK(table_error(timing, "M01\tseen\t0.01\trotation\n").find("FILE:1: ") == 0);
  CHECK(table_error(timing, "M01\tvisible\t0\trotation\n").find("FILE:1: ") == 0);
  // The course's own timings are in the format.
  CHECK_FALSE(grade::parse_timings(read_file(fs::path(FMBD_SOURCE_DIR) / "autograder/timings.txt"), "timings.txt").empty());

  // summary.csv: a header and one typed row; what the writer writes, the reader reads back.
  const grade::SummaryRow carol{"carol, jr", 0, std::nullopt, "error"};
  const grade::SummaryRow bob{"bob", 2.5, 9, "build_error:M01 timed_out:M02T1"};
  CHECK(grade::summary_csv_text(carol) == "submission,score,max_score,status\n\"carol, jr\",0,,error\n");
  CHECK(grade::summary_csv_text(bob) ==
        "submission,score,max_score,status\nbob,2.5,9,build_error:M01 timed_out:M02T1\n");
  for (const grade::SummaryRow& row : {carol, bob}) {
    const std::optional<grade::SummaryRow> back = grade::parse_summary_csv(grade::summary_csv_text(row), "summary.csv");
    REQUIRE(back.has_value());
    CHECK((back->submission == row.submission && back->score == row.score && back->max_score == row.max_score &&
           back->status == row.status));
  }
  CHECK_FALSE(grade::parse_summary_csv("", "summary.csv").has_value());  // grading stopped before it
  const auto summary = [](const std::string& t, const std::string& o) { return grade::parse_summary_csv(t, o); };
  CHECK(table_error(summary, "bob,2.5,9,graded\n").find("FILE:1: not a submission's summary") == 0);  // no header
  CHECK(table_error(summary, "submission,score,max_score,status\nbob,x,9,graded\n") ==
        "FILE:2: expected SUBMISSION,SCORE,MAX_SCORE,STATUS, got: bob,x,9,graded");
  const std::string two_rows = "submission,score,max_score,status\nbob,1,9,graded\nal,1,9,graded\n";
  CHECK(table_error(summary, two_rows).find("FILE:2: ") == 0);
}

TEST_CASE("Options: parsed after the table, with the workbook's messages", "[frontend][options]") {
  CommandSpec spec;
  spec.name = "grade";
  spec.options = {{"--strict", OptionKind::flag, "", "", "exit 1 unless full marks"},
                  {"--json", OptionKind::value, "FILE", "a file name", "results.json"},
                  {"--module", OptionKind::repeatable, "N", "a number", "a module"},
                  {"--timeout", OptionKind::number, "SEC", "a number", "seconds a test"}};
  spec.unknown_hint = " (see ./workbook help)";
  spec.pass_rest = true;

  const ParsedOptions parsed = parse_options(
      spec, {"--module", "1", "--json", "a.json", "--strict", "--module", "3", "--json", "b.json", "--", "--x"});
  CHECK(parsed.all("--module") == std::vector<std::string>{"1", "3"});
  CHECK(parsed.value("--json") == "b.json");  // the last one given
  CHECK(parsed.has("--strict"));
  CHECK_FALSE(parsed.has("--timeout"));
  CHECK(parsed.value("--timeout", "30") == "30");
  CHECK(parsed.rest == std::vector<std::string>{"--x"});
  CHECK(parse_options(spec, {"--strict", "-h", "--nonsense"}).help);

  CHECK(usage_error([&] { parse_options(spec, {"--x"}); }) == "grade: unknown option '--x' (see ./workbook help)");
  CHECK(usage_error([&] { parse_options(spec, {"--json"}); }) == "--json needs a file name");
  CHECK(usage_error([&] { parse_options(spec, {"--timeout", "ten"}); }) == "--timeout needs a number, got 'ten'");
  CHECK(usage_error([&] { parse_options(spec, {"word"}); }) == "grade: unknown option 'word' (see ./workbook help)");
  CHECK(usage_error([&] { parse_options(spec, {"--strict=no"}); }) == "--strict takes no value");
  CHECK(parse_options(spec, {"--json=c.json"}).value("--json") == "c.json");
  // The order given, options and positionals alike (fmbd-grade: EXE --listed-by LISTER ...).
  CHECK(parse_options(spec, {"--module", "2", "--strict", "--json", "a"}).sequence ==
        std::vector<std::pair<std::string, std::string>>{{"--module", "2"}, {"--strict", ""}, {"--json", "a"}});
  // The accessors know the table: a name it lacks is the program's mistake, not its user's.
  CHECK_THROWS_AS(parse_options(spec, {}).has("--jsn"), std::logic_error);
  CHECK(parse_options(spec, {"--timeout", "2.5"}).number("--timeout") == 2.5);

  CHECK(usage_error([] { parse_options(handin_command(), {"--x"}); }) == "handin: unknown option '--x'");
  CHECK(usage_error([] { parse_options(handin_command(), {"--out"}); }) == "--out needs a file name");
  CHECK(usage_error([] { parse_options(hint_command(), {"M01T1", "M01T2"}); }) ==
        "hint takes one task, e.g. ./workbook hint M01T3");
  CHECK(usage_error([] { parse_options(hint_command(), {"--"}); }) == "hint: unknown option '--'");
  CHECK(parse_options(handin_command(), {"--out", "-h"}).value("--out") == "-h");  // a value, not help
  // A demo's own parameters go after "--", which the demo command passes on.
  CHECK(usage_error([] { parse_options(demo_command(), {"spinning_beam", "--spin-rate", "40"}); }) ==
        "demo: unknown option '--spin-rate' (a demo's own parameters go after --: ./workbook demo NAME -- --spin-rate ...)");
  const ParsedOptions demo = parse_options(demo_command(), {"spinning_beam", "--", "--spin-rate", "40", "--help"});
  CHECK(demo.ended);
  CHECK_FALSE(demo.help);
  CHECK(demo.rest == std::vector<std::string>{"--spin-rate", "40", "--help"});
  CHECK(parse_options(demo_command(), {"--"}).ended);
  CHECK_FALSE(parse_options(demo_command(), {"spinning_beam"}).ended);
}

TEST_CASE("Options: the usage text names every option", "[frontend][options]") {
  CommandSpec spec;
  spec.name = "demo";
  spec.positional = "NAME";
  spec.max_positionals = 1;
  spec.options = {{"--out", OptionKind::value, "DIR", "a directory", ""},
                  {"--module", OptionKind::repeatable, "N", "a number", ""},
                  {"--quick", OptionKind::flag, "", "", ""}};
  spec.help = {"Run the demos."};
  CHECK(usage_text(spec) == "  demo [NAME] [--out DIR] [--module N]... [--quick]\n        Run the demos.\n");
  // Every command's table names each of its options in its usage.
  for (const CommandSpec* command : commands()) {
    INFO(usage_text(*command));
    for (const OptionSpec& option : command->options) CHECK(usage_text(*command).find(option.name) != std::string::npos);
  }
}

TEST_CASE("Help: a copy lists the commands it can run", "[frontend][options]") {
  Scratch copy("help");
  bool instructor = false;  // the course manifest's
  const auto listed = [&](const CommandSpec& spec) {
    return help_text(copy.path.string(), instructor).find(usage_text(spec)) != std::string::npos;
  };
  const auto lists_command = [&](const std::string& name) {
    return help_text(copy.path.string(), instructor).find("\n  " + name + " ") != std::string::npos;
  };
  // A student release without the extras: the students' commands only.
  for (const CommandSpec* spec : {&grade_command(), &hint_command(), &handin_command(), &demo_command(), &classroom_command()}) {
    CHECK(listed(*spec));
  }
  for (const char* name : {"test", "release", "gradescope", "bench", "studentify"}) CHECK_FALSE(lists_command(name));
  // A release with every solution carries the extras: bench, for their benchmark programs.
  fs::create_directories(copy.path / "extras");
  fs::create_directories(copy.path / "solutions");
  CHECK(listed(bench_extras_command()));
  CHECK_FALSE(lists_command("test"));
  // The instructor's copy: every command.
  instructor = true;
  for (const CommandSpec* spec : commands()) CHECK(listed(*spec));
  CHECK_FALSE(listed(bench_extras_command()));
  CHECK(help_text(copy.path.string(), instructor).find("\nCompiles and tests at once here: ") != std::string::npos);
}

TEST_CASE("Grade: where grading stops, results.json still says why", "[frontend][grade]") {
  Scratch folder("failed results");
  const std::vector<std::string> args = {"--module", "one", "--json", "out dir/results.json"};
  REQUIRE(write_failed_results(folder.path.string(), args, "--module needs a number, got 'one'"));
  const json::Value results = json::parse(read_file(folder.path / "out dir/results.json"));
  CHECK(results.at("score") == 0);
  CHECK(results.at("output").get<std::string>().find("--module needs a number, got 'one'") != std::string::npos);
  CHECK(results.at("tests").empty());
  // Results the driver wrote are kept; without --json nothing is written.
  CHECK_FALSE(write_failed_results(folder.path.string(), args, "another reason"));
  CHECK(read_file(folder.path / "out dir/results.json").find("another reason") == std::string::npos);
  CHECK_FALSE(write_failed_results(folder.path.string(), {"--module", "one"}, "a reason"));
  // Gradescope's fallback (run_autograder, where the grader did not run): the same writer, through
  // ./workbook grade --failed-results REASON --json FILE, which grades nothing.
  std::ostringstream out;
  const std::string reason = "The grader could not run (exit status 3); your instructor has its log.";
  const Context context{folder.path.string(), Manifest{}, out};
  CHECK(run_grade({"--failed-results", reason, "--json", "fallback/results.json"}, context) == 0);
  const json::Value fallback = json::parse(read_file(folder.path / "fallback/results.json"));
  CHECK(fallback.at("score") == 0);
  CHECK(fallback.at("output") == reason);
  CHECK(fallback.at("stdout_visibility") == "hidden");
  CHECK(fallback.at("tests").empty());
  CHECK(out.str().empty());
  CHECK_THROWS_AS(run_grade({"--failed-results", reason}, context), UsageError);
}

namespace {

// A course of two modules: module 1 with its reference (its code's tests listed by the reference
// build; its problems their own lister, built without the student's code), module 2 without
// (its problems check only the format). Each module has a problems item with an answers file.
// A graded item whose programs are /b/TARGET.
GradedItem graded(const std::string& id, int module, const std::string& target,
                  const std::optional<std::string>& reference_target, const std::optional<std::string>& vet_target) {
  GradedItem item;
  item.id = id;
  item.kind = id.back() == 'P' ? "problems" : "catch";
  item.module = module;
  item.target = target;
  item.program = "/b/" + target;
  item.reference_target = reference_target;
  if (reference_target) item.reference_program = "/b/" + *reference_target;
  item.vet_target = vet_target;
  if (vet_target) item.vet_report = "/b/vet/" + *vet_target + ".txt";
  return item;
}

Manifest planned_course() {
  Manifest manifest;
  manifest.schema = kManifestSchema;
  manifest.grade_driver = "/b/fmbd-grade";
  manifest.modules = {{1, "M01", "module01_kinematics", {"module01_kinematics/src/planar.cpp"}, std::nullopt,
                       "/b/libstage01_student.a", "/b/libstage01_reference.a"},
                      {2, "M02", "module02_newton_raphson", {"module02_newton_raphson/src/newton.cpp"}, std::nullopt,
                       "/b/libstage02_student.a", std::nullopt}};
  GradedItem code = graded("M01", 1, "m01_student", "m01_reference", "m01_vet");
  code.links_student_code = true;
  GradedItem problems = graded("M01P", 1, "m01_problems", "m01_problems", std::nullopt);
  problems.inputs = {"module01_kinematics/answers.txt"};
  problems.needs_identity = true;
  GradedItem code2 = graded("M02", 2, "m02_student", std::nullopt, "m02_vet");
  code2.links_student_code = true;
  GradedItem problems2 = graded("M02P", 2, "m02_problems", std::nullopt, std::nullopt);
  problems2.inputs = {"module02_newton_raphson/answers.txt"};
  problems2.needs_identity = true;
  problems2.links_student_code = true;
  problems2.without_reference = WithoutReference::format;
  manifest.graded = {code, problems, code2, problems2};
  return manifest;
}

TreeFacts planned_tree(bool submission) {
  TreeFacts facts;
  facts.tree = "/t";
  facts.build = "/t/build/ci";
  facts.submission = submission;
  facts.existing_inputs = {"module02_newton_raphson/answers.txt"};
  facts.jobs = 3;
  return facts;
}

std::vector<std::string> ids_of(const GradingPlan& plan) {
  std::vector<std::string> ids;
  for (const PlannedItem& item : plan.items) ids.push_back(item.item.id);
  return ids;
}

}  // namespace

TEST_CASE("Grade plan: one's own tree skips an item not started, a submission grades it", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.driver.timeout = "10";
  const GradingPlan own = plan_grading(course, o, planned_tree(false));
  CHECK(ids_of(own) == std::vector<std::string>{"M01", "M02", "M02P"});
  REQUIRE(own.not_started.size() == 1);
  CHECK(own.not_started[0].id == "M01P");
  CHECK(own.not_started[0].input == "module01_kinematics/answers.txt");
  CHECK(not_started_message(own) ==
        "workbook: not started (no file of its answers yet), so not graded here: M01P "
        "(module01_kinematics/answers.txt); ./workbook problems MNN prints the problems\n");
  // What is built: the driver, each item's program and its lister; nothing of the item not started.
  CHECK(own.targets == std::vector<std::string>{"fmbd-grade", "m01_student", "m01_reference", "m02_student",
                                                "m02_problems"});
  const PlannedItem& m01 = own.items[0];
  CHECK(m01.program == "/b/m01_student");
  CHECK(m01.lister == std::optional<std::string>("/b/m01_reference"));
  CHECK(m01.vet_target == std::optional<std::string>("m01_vet"));
  CHECK(m01.log == "/t/build/ci/m01_student.build.log");
  CHECK(m01.errors_file == "/t/build/ci/compile/m01.txt");
  CHECK(m01.name == "module01_kinematics");
  CHECK_FALSE(own.items[1].lister);  // module 2 has no reference: its program lists its tests
  CHECK(own.watched.front().message == "the grade driver is ready");
  CHECK(own.exercises == std::vector<std::string>{"/t/module01_kinematics/src/planar.cpp",
                                                  "/t/module02_newton_raphson/src/newton.cpp"});
  CHECK(own.options.timeout == "10");
  CHECK(own.jobs == std::optional<int>(3));
  CHECK_FALSE(own.timings);

  const GradingPlan submission = plan_grading(course, o, planned_tree(true));
  CHECK(ids_of(submission) == std::vector<std::string>{"M01", "M01P", "M02", "M02P"});
  CHECK(submission.not_started.empty());
  CHECK(not_started_message(submission).empty());
  const PlannedItem& m01p = submission.items[1];
  CHECK_FALSE(m01p.student_code);  // built without the student's code: its failure is not theirs
  CHECK(m01p.lister == std::optional<std::string>("/b/m01_problems"));
  CHECK(submission.items[0].student_code);
}

TEST_CASE("Grade plan: --solutions grades the items with a reference, and refuses a module without", "[frontend][grade][plan]") {
  Manifest course = planned_course();
  GradeOptions o;
  o.solutions = true;
  TreeFacts facts = planned_tree(false);
  facts.identity = "reference";
  const GradingPlan plan = plan_grading(course, o, facts);
  CHECK(ids_of(plan) == std::vector<std::string>{"M01", "M01P"});  // M01P's answers: the model answers
  CHECK(plan.items[0].program == "/b/m01_reference");
  CHECK(plan.items[0].target == "m01_reference");
  CHECK_FALSE(plan.items[0].lister);
  CHECK_FALSE(plan.items[0].vet_target);
  CHECK(plan.targets == std::vector<std::string>{"fmbd-grade", "m01_reference", "m01_problems"});
  CHECK(identity_message(plan.identity) == "workbook: M01P graded with the numbers of \"reference\"\n");

  // An item of the module without its own reference is not graded: there is nothing to run.
  Manifest unlisted = course;
  unlisted.graded[1].reference_program = unlisted.graded[1].reference_target = std::nullopt;
  CHECK(ids_of(plan_grading(unlisted, o, facts)) == std::vector<std::string>{"M01"});

  o.modules = {2};
  CHECK(usage_error([&] { plan_grading(course, o, facts); })
            .find("--solutions: module 2 (module02_newton_raphson) has no reference solution here; this copy "
                  "carries those of modules 1") == 0);
  o.modules = {7};
  CHECK(usage_error([&] { plan_grading(course, o, facts); })
            .find("--solutions: module 7 (not in this copy) has no reference solution here") == 0);
  for (GradedItem& item : course.graded) item.reference_program = item.reference_target = std::nullopt;
  o.modules.clear();
  CHECK(usage_error([&] { plan_grading(course, o, facts); }) ==
        "--solutions: this copy carries the reference solution of no module (solutions/)");
}

TEST_CASE("Grade plan: --module and --task choose the modules; the identity's message", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.modules = {2};
  const GradingPlan plan = plan_grading(course, o, planned_tree(true));
  CHECK(ids_of(plan) == std::vector<std::string>{"M02", "M02P"});
  CHECK(plan.targets == std::vector<std::string>{"fmbd-grade", "m02_student", "m02_problems"});
  CHECK(identity_message(plan.identity) ==
        "workbook: the numbers of M02P depend on your name: ./workbook grade --student \"YOUR NAME\" "
        "(or ./workbook problems --student \"YOUR NAME\" once)\n"
        "workbook: M02P without the reference here: only the format of the answers is checked; your "
        "instructor's grader checks the values\n");
  o.modules = {1, 2};  // --module 1 --task M02T1
  CHECK(ids_of(plan_grading(course, o, planned_tree(true))).size() == 4);
  // The preset: a submission on the reference's earlier modules, unless --own-earlier.
  CHECK(grading_preset(o, true, true) == "reference");
  CHECK(grading_preset(o, false, false) == "student");
  o.own_earlier = true;
  CHECK(grading_preset(o, true, true) == "student");
  CHECK(usage_error([&] { grading_preset(o, true, false); }) ==
        "--submission needs the solutions/ folder (an instructor's copy)");
  o.solutions = true;
  CHECK(usage_error([&] { grading_preset(o, true, true); }) == "--solutions and --submission exclude each other");
}

TEST_CASE("Driver invocation: each program with its lister, a broken or rejected module's report", "[frontend][grade][plan]") {
  const Manifest course = planned_course();
  GradeOptions o;
  o.driver.modules = {"1", "2"};
  TreeFacts facts = planned_tree(true);
  facts.has_timings = true;
  const GradingPlan plan = plan_grading(course, o, facts);
  REQUIRE(plan.items.size() == 4);
  const std::vector<ItemOutcome> outcomes = {
      {BuildState::built, true, ""},
      {BuildState::broken, true, "/t/build/ci/compile/m01P.txt"},
      {BuildState::rejected, false, "/t/build/ci/vet/m02.txt"},
      {BuildState::broken, false, "/t/build/ci/compile/m02P.txt"},  // no lister: not graded
  };
  const DriverInvocation invocation = driver_invocation(plan, outcomes);
  REQUIRE(invocation.programs.size() == 3);
  CHECK(invocation.programs[1].build_errors->module == "1");
  CHECK(driver_argv(invocation) ==
        std::vector<std::string>{"/b/fmbd-grade", "--timings", "/t/autograder/timings.txt", "--jobs", "3",
                                 "--module", "1", "--module", "2",
                                 "--build-errors", "1=/t/build/ci/compile/m01P.txt",
                                 "--reject", "02=/t/build/ci/vet/m02.txt",
                                 "/b/m01_student", "--listed-by", "/b/m01_reference",
                                 "/b/m01_problems", "--listed-by", "/b/m01_problems", "--grades-inputs",
                                 "/b/m02_student"});
  // M01P grades the student's inputs (its capabilities), so module 1's build errors leave it alone.
  CHECK(invocation.programs[1].grades_inputs);
  CHECK_FALSE(invocation.programs[0].grades_inputs);
  // A lister that did not build lists nothing: the program lists its own tests.
  std::vector<ItemOutcome> unlisted = outcomes;
  unlisted[0].lister_built = false;
  const std::vector<std::string> unlisted_argv = driver_argv(driver_invocation(plan, unlisted));
  REQUIRE(unlisted_argv.size() == 19);
  CHECK(std::vector<std::string>(unlisted_argv.begin() + 13, unlisted_argv.begin() + 15) ==
        std::vector<std::string>{"/b/m01_student", "/b/m01_problems"});
  // The user's --jobs is the driver's; no timings file, no --timings.
  o.driver = DriverOptions{};
  o.driver.jobs = "1";
  facts.has_timings = false;
  const std::vector<std::string> argv = driver_argv(driver_invocation(plan_grading(course, o, facts), outcomes));
  CHECK(std::vector<std::string>(argv.begin(), argv.begin() + 4) ==
        std::vector<std::string>{"/b/fmbd-grade", "--jobs", "1", "--build-errors"});
  // Nothing built that can be graded: nothing to grade.
  const std::vector<ItemOutcome> skipped(4, ItemOutcome{BuildState::skipped, false, ""});
  CHECK(usage_error([&] { driver_invocation(plan, skipped); }) == "nothing to grade");
  // Every option of the driver, typed, written in one order.
  DriverOptions all;
  all.modules = {"1"};
  all.tasks = {"M01T2"};
  all.json = "/o/results.json";
  all.junit = "/o/junit.xml";
  all.csv = "/o/tasks.csv";
  all.timings_out = "/o/timings.txt";
  all.timeout = "30";
  all.jobs = "2";
  all.hidden_visibility = "hidden";
  all.strict = true;
  const DriverInvocation typed{"/b/fmbd-grade", std::nullopt, std::nullopt, all, {}};
  CHECK(driver_argv(typed) == std::vector<std::string>{"/b/fmbd-grade", "--module", "1", "--task", "M01T2",
                                                       "--json", "/o/results.json", "--junit", "/o/junit.xml",
                                                       "--csv", "/o/tasks.csv", "--timings-out", "/o/timings.txt",
                                                       "--timeout", "30", "--jobs", "2", "--hidden-visibility",
                                                       "hidden", "--strict"});
}

TEST_CASE("Bench: the table of a CSV text, and the speed targets met or not", "[frontend][bench]") {
  const std::string table = bench_table("group,case,quantity,value,unit\n"
                                        "simulate,pendulum,cost per step,2.5,us\n"
                                        "simulate,pendulum,ratio_to_target,0.8,1\n"
                                        "modal,beam 1000 elements,ratio_to_target,3.2,1\n");
  CHECK(table.rfind("group          case ", 0) == 0);  // the header, in the columns of the rows
  CHECK(table.find("\nsimulate       pendulum ") != std::string::npos);
  CHECK(table.find("Speed targets (cost per step / target):\n") != std::string::npos);
  CHECK(table.find("simulate: pendulum") != std::string::npos);
  CHECK(table.find("met (0.8x)") != std::string::npos);
  CHECK(table.find("not met: 3.2x the target") != std::string::npos);
  CHECK(bench_table("group,case,quantity,value,unit\nsimulate,pendulum,cost per step,2.5,us\n").find("Speed targets") ==
        std::string::npos);
  CHECK_THROWS_AS(bench_table("simulate,pendulum,2.5,us\n"), StepFailed);  // a row of four fields
}

TEST_CASE("Layout: the paths of a build folder and of the timings, each spelled once", "[frontend][layout]") {
  const BuildLayout layout = BuildLayout::of_preset("/t", "ci");
  CHECK(layout.dir == "/t/build/ci");
  CHECK(BuildLayout::of_preset("ci").configure_log() == "build/ci/configure.log");
  CHECK(layout.course_json() == "/t/build/ci/course.json");
  CHECK(layout.configure_log() == "/t/build/ci/configure.log");
  CHECK(layout.errors_file("M01") == "/t/build/ci/compile/m01.txt");
  CHECK(layout.errors_file("M01P") == "/t/build/ci/compile/m01P.txt");
  CHECK(layout.build_log("fmbd-grade") == "/t/build/ci/fmbd-grade.build.log");
  CHECK(timings_path("/t") == "/t/autograder/timings.txt");
  CHECK(preset_build_dir("/t", "ci") == layout.dir);
}

TEST_CASE("Task ids: one strict parser and its formatter (common/task_id.hpp)", "[protocol][ids]") {
  using fmbd::protocol::TaskId;
  struct Valid {
    const char* text;
    TaskId task;
    const char* formatted;
  };
  for (const Valid& v : {Valid{"M01T3", {1, 'T', 3}, "M01T3"}, Valid{"M08T12", {8, 'T', 12}, "M08T12"},
                         Valid{"M01P2", {1, 'P', 2}, "M01P2"}, Valid{"M99P99", {99, 'P', 99}, "M99P99"},
                         Valid{"M00T0", {0, 'T', 0}, "M00T0"}, Valid{"M01T03", {1, 'T', 3}, "M01T3"}}) {
    INFO(v.text);
    const std::optional<TaskId> task = fmbd::protocol::parse_task_id(v.text);
    REQUIRE(task);
    CHECK(*task == v.task);
    CHECK(fmbd::protocol::format_task_id(*task) == v.formatted);
  }
  for (const char* text : {"", "M", "M01", "M01T", "M1T3", "m01t3", "M01t3", "M01X3", "M01T123", "M001T3", " M01T3",
                           "M01T3 ", "M01T3x", "MA1T3", "M01T-3", "N01T3", "M01TT3", "M01T+3"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(fmbd::protocol::parse_task_id(text));
  }
  CHECK(fmbd::protocol::format_module_id(7) == "M07");
  CHECK(fmbd::protocol::is_task_kind('T'));
  CHECK(fmbd::protocol::is_task_kind('P'));
  CHECK_FALSE(fmbd::protocol::is_task_kind('t'));
  CHECK_FALSE(fmbd::protocol::is_task_kind('\0'));
  // The code's tasks are reported before those of the inputs, each kind by number.
  CHECK(fmbd::protocol::task_before('T', 9, 'P', 1));
  CHECK_FALSE(fmbd::protocol::task_before('P', 1, 'T', 9));
  CHECK(fmbd::protocol::task_before('P', 1, 'P', 2));
  CHECK_FALSE(fmbd::protocol::task_before('T', 2, 'T', 2));
}

TEST_CASE("Grading protocol: listing lines, task tags and the test-name escaping", "[protocol]") {
  CHECK(fmbd::protocol::listing_line("a test", "[M01][T2]") == "a test\t[M01][T2]\n");
  CHECK(fmbd::protocol::task_tags({1, 'P', 2}, "3") == "[M01][P2][points=3]");
  CHECK(fmbd::protocol::catch_test_spec("a, [b] *c~ \"d\" \\") == "\"a\\, \\[b\\] \\*c\\~ \\\"d\\\" \\\\\"");
  for (const char* name : {"plain", "M01P2: the angle, in degrees", "a, [b] *c~ \"d\" \\", ""}) {
    CHECK(fmbd::protocol::test_name_of_spec(fmbd::protocol::catch_test_spec(name)) == name);
  }
  CHECK(fmbd::protocol::test_name_of_spec("M01P2") == "M01P2");  // a bare name is itself
  CHECK(std::string(fmbd::protocol::kCompletionTokenPrefix) == "fmbd-completion-token: ");
}

TEST_CASE("Ids: M1T3, m01t3 and M01T3 name one task; others are refused", "[frontend][ids]") {
  for (const char* text : {"M1T3", "m01t3", "M01T3", "m1t3"}) {
    const auto task = task_id(text);
    REQUIRE(task);
    CHECK(task->id == "M01T3");
    CHECK(task->task == fmbd::protocol::TaskId{1, 'T', 3});
  }
  CHECK(task_id("M12T10")->id == "M12T10");
  CHECK(task_id("m1p2")->id == "M01P2");  // a tutorial problem
  CHECK(task_id("M01P2")->task.number == 2);
  CHECK(task_id("m1t03")->id == "M01T03");  // as written: it names no ladder's task
  CHECK(module_id(7) == "M07");
  CHECK_FALSE(task_id("M01"));
  CHECK_FALSE(task_id("M123T1"));
  CHECK_FALSE(task_id("M01T123"));
  CHECK_FALSE(task_id("X"));
  CHECK(usage_error([] { parse_task_id("x", "hint"); }) ==
        "hint: 'x' is not a task id; write it like M01T3 (./workbook hint lists them)");
  // The refusal quotes the id as rewritten: upper-cased, the module's zero added.
  CHECK(usage_error([] { parse_task_id("m1t3x", "hint"); }) ==
        "hint: 'M01T3x' is not a task id; write it like M01T3 (./workbook hint lists them)");
}

TEST_CASE("Jobs: cores, CPU quota and memory limit, with the reason", "[frontend][jobs]") {
  Scratch scratch("jobs");
  const fs::path root = scratch.path / "cgroup";
  const std::string meminfo = (scratch.path / "meminfo").string();
  write_file(meminfo, "MemTotal:       16000000 kB\nMemFree: 1 kB\n");

  fs::create_directories(root);
  Jobs jobs = available_jobs(4, root.string(), meminfo);  // no cgroup files
  CHECK(jobs.count == 4);
  CHECK(jobs.reason == "4 cores");

  write_file(root / "cpu.max", "150000 100000\n");
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 1);
  CHECK(jobs.reason == "4 cores, a CPU quota of 1");

  write_file(root / "cpu.max", "max 100000\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores");

  write_file(root / "cpu.max", "800000 100000\n");  // a quota above the cores keeps the cores
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 4);
  CHECK(jobs.reason == "4 cores, a CPU quota of 8");

  fs::remove(root / "cpu.max");  // cgroup v1
  write_file(root / "cpu/cpu.cfs_quota_us", "200000\n");
  write_file(root / "cpu/cpu.cfs_period_us", "100000\n");
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 2);
  CHECK(jobs.reason == "4 cores, a CPU quota of 2");
  write_file(root / "cpu/cpu.cfs_quota_us", "-1\n");
  CHECK(available_jobs(4, root.string(), meminfo).count == 4);

  write_file(root / "memory.max", "2147483648\n");  // 2 GiB: two jobs of 700 MB
  jobs = available_jobs(4, root.string(), meminfo);
  CHECK(jobs.count == 2);
  CHECK(jobs.reason == "4 cores, 2048 MB of memory");
  write_file(root / "memory.max", "max\n");
  CHECK(available_jobs(4, root.string(), meminfo).count == 4);
  write_file(root / "memory.max", "100000000\n");  // below 700 MB: still one job
  CHECK(available_jobs(4, root.string(), meminfo).count == 1);

  fs::remove(root / "memory.max");  // cgroup v1: its "no limit" is a number above the machine's memory
  write_file(root / "memory/memory.limit_in_bytes", "9223372036854771712\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores");
  write_file(root / "memory/memory.limit_in_bytes", "1073741824\n");
  CHECK(available_jobs(4, root.string(), meminfo).reason == "4 cores, 1024 MB of memory");
}

namespace {

constexpr const char* kLadders = R"(# Module 1 hints

Open them one level at a time.

## M01T1

### Level 1
Where the theory is.


Second paragraph.

### Level 2
The shape.

### Level 3
The formula `x = y`.

## M01T2

### Level 1
Only one level here.
)";

}  // namespace

TEST_CASE("Hints: ladders are listed, rendered and trimmed as the workbook does", "[frontend][hints]") {
  const auto ladders = hints::list_ladders({kLadders, "## M02T1\n### Level 1\n### Level 2\n"});
  REQUIRE(ladders.size() == 3);
  CHECK(ladders[0].task == "M01T1");
  CHECK(ladders[0].levels == 3);
  CHECK(ladders[1].levels == 1);
  CHECK(ladders[2].task == "M02T1");
  CHECK(ladders[2].levels == 2);
  CHECK(hints::levels_of(kLadders, "M01T1") == 3);
  CHECK(hints::levels_of(kLadders, "M01T9") == 0);
  CHECK(hints::task_headings(kLadders) == std::vector<std::string>{"M01T1", "M01T2"});

  CHECK(hints::render(kLadders, "M01T1", 1) == "-- M01T1, level 1 --\nWhere the theory is.\n\nSecond paragraph.\n");
  CHECK(hints::render(kLadders, "M01T1", 2) ==
        "-- M01T1, level 1 --\nWhere the theory is.\n\nSecond paragraph.\n\n-- M01T1, level 2 --\nThe shape.\n");
  CHECK(hints::render(kLadders, "M01T2", 1) == "-- M01T2, level 1 --\nOnly one level here.\n");

  CHECK_FALSE(hints::ceiling(kLadders));
  const std::string trimmed = hints::apply_ceiling(kLadders, 1);
  CHECK(trimmed.find("### Level 2") == std::string::npos);
  CHECK(trimmed.find("The formula") == std::string::npos);
  CHECK(trimmed.find("Only one level here.") != std::string::npos);
  CHECK(trimmed.rfind("# Module 1 hints\n\n<!-- hint-ceiling: 1 -->\n\nOpen them", 0) == 0);
  CHECK(trimmed.find("\n\n\n") == std::string::npos);  // empty lines squeezed
  CHECK(hints::ceiling(trimmed) == 1);
  CHECK(hints::levels_of(trimmed, "M01T1") == 1);

  const std::string opened = hints::with_opened("M01T2 1\nM01T1 1\n", "M01T1", 2);
  CHECK(opened == "M01T2 1\nM01T1 2\n");
  CHECK(hints::opened_level(opened, "M01T1") == 2);
  CHECK(hints::opened_level(opened, "M01T3") == 0);
  CHECK(hints::with_opened(opened, "M01T1", 0) == "M01T2 1\n");
}

namespace {

constexpr const char* kManifest = R"({
  "schema": 3, "source_dir": "/src", "build_dir": "/src/build/student", "grade_driver": "/b/fmbd-grade",
  "instructor": true, "release_policy": "autograder/release_policy.txt",
  "modules": [
    {"number": 1, "id": "M01", "folder": "module01_kinematics",
     "exercises": ["module01_kinematics/src/planar.cpp"], "hints": null,
     "student_library": "/b/libstage01_student.a", "reference_library": null}
  ],
  "graded": [
    {"id": "M01", "kind": "catch", "module": 1, "program": "/b/m01_student", "target": "m01_student",
     "reference_program": null, "reference_target": null, "vet_target": "m01_vet",
     "vet_report": "/b/vet/m01.txt",
     "inputs": [], "needs_identity": false, "links_student_code": true, "classroom": true, "without_reference": "all"},
    {"id": "M01P", "kind": "problems", "module": 1, "program": "/b/m01_problems", "target": "m01_problems",
     "reference_program": null, "reference_target": null, "vet_target": null, "vet_report": null,
     "inputs": ["module01_kinematics/answers.txt"], "needs_identity": true, "links_student_code": true,
     "classroom": false, "without_reference": "format"}
  ],
  "demos": [], "benchmarks": [{"name": "simulate", "target": "fmbd-bench-simulate", "program": "/b/s"}]
})";

std::string manifest_error(const std::string& text) {
  try {
    parse_manifest(text, "course.json");
  } catch (const ManifestError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Manifest: a small course.json is read into its structs", "[frontend][manifest]") {
  const Manifest manifest = parse_manifest(kManifest, "course.json");
  CHECK(manifest.schema == 3);
  CHECK(manifest.source_dir == "/src");
  CHECK(manifest.instructor);
  CHECK(manifest.release_policy == std::optional<std::string>("autograder/release_policy.txt"));
  REQUIRE(manifest.modules.size() == 1);
  CHECK(manifest.module(1)->folder == "module01_kinematics");
  CHECK(manifest.module(2) == nullptr);
  CHECK(manifest.modules[0].exercises == std::vector<std::string>{"module01_kinematics/src/planar.cpp"});
  CHECK_FALSE(manifest.modules[0].hints);
  REQUIRE(manifest.graded.size() == 2);
  CHECK(manifest.graded[0].vet_target == std::optional<std::string>("m01_vet"));
  CHECK(manifest.graded[0].vet_report == std::optional<std::string>("/b/vet/m01.txt"));
  CHECK_FALSE(manifest.graded[0].reference_program);
  // The capabilities, as data.
  const GradedItem& code = manifest.graded[0];
  const GradedItem& problems = manifest.graded[1];
  CHECK(code.inputs.empty());
  CHECK((code.links_student_code && code.classroom && !code.needs_identity && !code.has_personal_problems()));
  CHECK(code.without_reference == WithoutReference::all);
  CHECK(problems.inputs == std::vector<std::string>{"module01_kinematics/answers.txt"});
  CHECK((problems.needs_identity && !problems.classroom && problems.has_personal_problems()));
  CHECK(problems.without_reference == WithoutReference::format);
  // ... and by the names of their fields (./workbook inspect tasks --of).
  CHECK(has_capability(code, "links_student_code") == std::optional<bool>(true));
  CHECK(has_capability(code, "inputs") == std::optional<bool>(false));
  CHECK(has_capability(problems, "inputs") == std::optional<bool>(true));
  CHECK(has_capability(problems, "classroom") == std::optional<bool>(false));
  CHECK_FALSE(has_capability(problems, "problems"));  // a kind, not a capability
  CHECK(manifest.demos.empty());
  CHECK(manifest.benchmarks.at(0).target == "fmbd-bench-simulate");

  std::string text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"module01_kinematics/answers.txt\""), 33, "2")) ==
        "course.json: graded[1].inputs[0]: a string is expected, not a number");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"format\""), 8, "\"some\"")) ==
        "course.json: graded[1].without_reference: \"all\" or \"format\" is expected, not \"some\"");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"needs_identity\": true"), 22, "\"needs_identity\": 1")) ==
        "course.json: graded[1].needs_identity: a boolean is expected, not a number");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"vet_target\""), 12, "\"vet\"")) ==
        "course.json: graded[0].vet_target: missing");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"vet_report\": \"/b/vet/m01.txt\""), 30, "\"vet_report\": null")) ==
        "course.json: graded[0].vet_report: vet_target and vet_report are both null or both given");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"instructor\": true"), 18, "\"instructor\": 1")) ==
        "course.json: instructor: a boolean is expected, not a number");
  text = kManifest;
  CHECK(manifest_error(text.replace(text.find("\"schema\": 3"), 11, "\"schema\": 4")).find("course.json: schema: schema 4 is newer") == 0);
  // A manifest of an older schema says so, with its schema, for the one re-configure.
  int older = 0;
  try {
    parse_manifest(R"({"schema": 1, "modules": [{"inputs": []}]})", "course.json");
  } catch (const OlderManifest& error) {
    older = error.schema();
    CHECK(std::string(error.what()).find("course.json: schema: schema 1 is older than the one this front end reads (3)") == 0);
  }
  CHECK(older == 1);
  CHECK(manifest_error("{\n\"schema\": 1,,}").find("course.json: line 2, column 13: ") == 0);
  CHECK(manifest_error("{\"schema\": 1, \"schema\": 1}") == "course.json: duplicate key \"schema\"");
  CHECK(manifest_error("[]") == "course.json: the document: an object is expected, not an array");
}

TEST_CASE("Manifest: this build's course.json describes the tree", "[frontend][manifest]") {
  const Manifest manifest = read_manifest(FMBD_COURSE_JSON);
  CHECK(fs::equivalent(manifest.source_dir, FMBD_SOURCE_DIR));
  REQUIRE_FALSE(manifest.modules.empty());
  std::set<std::string> exercise_files;
  for (const Module& module : manifest.modules) {
    INFO(module.folder);
    CHECK(module.id == module_id(module.number));
    CHECK(module.folder.rfind("module" + module_id(module.number).substr(1) + "_", 0) == 0);  // module08_...
    CHECK_FALSE(module.exercises.empty());
    std::set<std::string> tasks;  // the TODO(MnnTk) markers of its exercise files
    for (const std::string& file : module.exercises) {
      CHECK(fs::is_regular_file(fs::path(FMBD_SOURCE_DIR) / file));
      CHECK(file.rfind(module.folder + "/src/", 0) == 0);
      exercise_files.insert(file);
      const std::string text = read_file(fs::path(FMBD_SOURCE_DIR) / file);
      for (std::size_t at = text.find("TODO(M"); at != std::string::npos; at = text.find("TODO(M", at + 1)) {
        const std::optional<WrittenTask> task = task_id(text.substr(at + 5, text.find(')', at) - at - 5));
        if (task) tasks.insert(task->id);
      }
    }
    CHECK_FALSE(tasks.empty());
    for (const std::string& task : tasks) CHECK(task_id(task)->task.module == module.number);
    if (module.hints) {
      const std::string ladders = read_file(fs::path(FMBD_SOURCE_DIR) / *module.hints);
      REQUIRE_FALSE(ladders.empty());
      for (const std::string& task : tasks) {
        INFO(task);
        CHECK(hints::levels_of(ladders, task) > 0);
      }
    }
  }
  // The graded programs are those of modules the manifest has, with their targets.
  for (const GradedItem& item : manifest.graded) {
    INFO(item.id);
    CHECK(manifest.module(item.module) != nullptr);
    const bool has_reference = manifest.module(item.module)->reference_library.has_value();
    if (item.kind == "problems") {  // the tutorial problems: one program, its own reference
      CHECK(item.id == module_id(item.module) + "P");
      CHECK(item.target == "m" + item.id.substr(1, 2) + "_problems");
      CHECK(item.inputs == std::vector<std::string>{manifest.module(item.module)->folder + "/answers.txt"});
      CHECK((item.needs_identity && !item.classroom && item.without_reference == WithoutReference::format));
      CHECK(item.links_student_code == !has_reference);  // format-only: built on the student's stages
    } else {
      CHECK(item.kind == "catch");
      CHECK(item.target == "m" + item.id.substr(1) + "_student");
      CHECK((item.inputs.empty() && !item.needs_identity && item.links_student_code && item.classroom));
    }
    CHECK(item.program.find(manifest.build_dir) == 0);
    CHECK(item.reference_program.has_value() == has_reference);
  }
  // No exercise file lies outside the manifest: every moduleNN_*/src/*.cpp but the given ones.
  for (const Module& module : manifest.modules) {
    for (const auto& entry : fs::directory_iterator(fs::path(FMBD_SOURCE_DIR) / module.folder / "src")) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".cpp" || name.find("_given.cpp") != std::string::npos) continue;
      CHECK(exercise_files.count(module.folder + "/src/" + name) == 1);
    }
  }
}

TEST_CASE("Release: the README filters make a README true of the release", "[frontend][release][markdown]") {
  const std::string readme =
      "# Course\n\nIntro.\n<!-- instructor-only -->\nSecret.\n\n\n<!-- /instructor-only -->\n\n\nEnd.\n";
  CHECK(markdown::strip_marked(readme, {"instructor-only"}) == "# Course\n\nIntro.\n\n\nEnd.\n");
  CHECK(markdown::squeeze_blank_lines(markdown::strip_marked(readme, {"instructor-only"})) == "# Course\n\nIntro.\n\nEnd.\n");
  CHECK(markdown::strip_marked(readme, {"extras"}) == readme);  // another mark: unchanged
  // Nested marks of two kinds, each line exactly the mark.
  CHECK(markdown::strip_marked("a\n<!-- extras -->\nb\n <!-- /extras -->\n<!-- /extras -->\nc", {"extras"}) == "a\nc");

  const auto exists = [](const std::string& target) { return target == "module01/README.md" || target == "img.png"; };
  CHECK(markdown::drop_missing_links("See [one](module01/README.md) and [two](module02/README.md#x).\n", exists) ==
        "See [one](module01/README.md) and two.\n");
  CHECK(markdown::drop_missing_links("| [2](module02/README.md) | two |\n| [1](module01/README.md) | one |\n", exists) ==
        "| [1](module01/README.md) | one |\n");
  CHECK(markdown::drop_missing_links("![plot](gone.png) ![ok](img.png)", exists) == "plot ![ok](img.png)");
  // URLs, anchors and absolute paths stay; a target with a space is no link.
  const std::string kept = "[a](https://x.org/y) [b](#section) [c](/abs/path) [d](no such)";
  CHECK(markdown::drop_missing_links(kept, exists) == kept);
}

TEST_CASE("Release: the policy file and its path patterns", "[frontend][release]") {
  const ReleasePolicy policy = parse_policy(
      "# comment\nomit solutions\nomit autograder/module*/hidden\n\nomit-engine extras\nstrip instructor-only\n"
      "strip-engine extras\ngradescope-omit tests\n",
      "policy.txt");
  CHECK(policy.omit == std::vector<std::string>{"solutions", "autograder/module*/hidden"});
  CHECK(policy.omit_engine == std::vector<std::string>{"extras"});
  CHECK(policy.strip == std::vector<std::string>{"instructor-only"});
  CHECK(policy.strip_engine == std::vector<std::string>{"extras"});
  CHECK(policy.gradescope_omit == std::vector<std::string>{"tests"});
  CHECK(usage_error([] { parse_policy("omit a\nkeep b\n", "policy.txt"); }) ==
        "policy.txt:2: no rule 'keep' (omit, omit-engine, strip, strip-engine, gradescope-omit)");
  CHECK(usage_error([] { parse_policy("omit\n", "policy.txt"); }) == "policy.txt:1: write a rule as RULE ARGUMENT");
  CHECK(policy_rule(policy, "omit") == policy.omit);
  CHECK(policy_rule(policy, "gradescope-omit") == std::vector<std::string>{"tests"});
  CHECK(usage_error([&policy] { policy_rule(policy, "keep"); }) ==
        "no rule 'keep' (omit, omit-engine, strip, strip-engine, gradescope-omit)");

  CHECK(excluded("solutions/module01_kinematics/planar.cpp", policy.omit));
  CHECK(excluded("autograder/module03_lagrange/hidden/x.test.cpp", policy.omit));
  CHECK_FALSE(excluded("autograder/module03_lagrange/visible/x.test.cpp", policy.omit));
  CHECK_FALSE(excluded("solutionsX/a.cpp", policy.omit));  // a name, not a prefix of one
  CHECK_FALSE(excluded("autograder/hidden", policy.omit));
  // The real policy keeps the tests and the solutions out of a release, and the grader in it.
  std::string text = read_file(fs::path(FMBD_SOURCE_DIR) / "autograder/release_policy.txt");
  const ReleasePolicy real = parse_policy(text, "release_policy.txt");
  CHECK(excluded("tests/release_check.sh", real.omit));
  CHECK(excluded("autograder/mistakes/m01.mutant", real.omit));
  CHECK(excluded("docs/instructors.md", real.omit));  // the instructor's guides stay out
  CHECK(excluded("docs/tests.md", real.omit));
  CHECK_FALSE(excluded("docs/students.md", real.omit));  // the students' guide goes with the release
  CHECK_FALSE(excluded("docs/lecturers.md", real.omit));
  CHECK_FALSE(excluded("autograder/driver/grade.cpp", real.omit));
  CHECK_FALSE(excluded("module01_kinematics/src/planar.cpp", real.omit));
}

namespace {

// ./workbook inspect ARGS in the folder `scratch`: its exit status and output, or the message of
// the error that ended it with its exit status.
struct Inspected {
  int status = 0;
  std::string out;
};
Inspected inspect(const Scratch& scratch, const std::vector<std::string>& args, const Manifest& manifest = {}) {
  std::ostringstream out;
  const Context context{scratch.path.string(), manifest, out};
  Inspected result;
  try {
    result.status = run_inspect(args, context);
  } catch (const std::exception& error) {
    result.status = exit_status_of(error);
    out << "workbook: " << error.what() << "\n";
  }
  result.out = out.str();
  return result;
}

}  // namespace

TEST_CASE("Inspect: the workbook's files read for scripts; each check can fail", "[frontend][inspect]") {
  const Scratch scratch("inspect");
  const std::string header = "module,task,score,max_score,status\n";
  const std::string full = (scratch.path / "full.csv").string();
  const std::string partial = (scratch.path / "partial.csv").string();
  write_file(full, header + "M01,T1,4,4,passed\nM01,P1,2,2,passed\n");
  write_file(partial, header + "M01,T1,4,4,passed\nM01,T2,1.5,3,failed\nM01,P1,0,2,failed\n");

  CHECK(inspect(scratch, {"tasks", partial, "--sum", "max_score"}).out == "9\n");
  CHECK(inspect(scratch, {"tasks", partial, "--sum", "score"}).out == "5.5\n");
  CHECK(inspect(scratch, {"tasks", partial, "--count"}).out == "3\n");
  const Inspected passed = inspect(scratch, {"tasks", full, "--full"});
  CHECK((passed.status == 0 && passed.out.empty()));
  const Inspected below = inspect(scratch, {"tasks", partial, "--full"});
  CHECK(below.status == 1);
  CHECK(below.out == "M01 T2: 1.5 of 3, failed\nM01 P1: 0 of 2, failed\n"
                     "workbook: 2 of the 3 tasks in " + partial + " scored below their maximum (above)\n");
  write_file(scratch.path / "empty.csv", header);
  CHECK(inspect(scratch, {"tasks", (scratch.path / "empty.csv").string(), "--full"}).status == 1);
  // --of: the tasks of the items with a capability; an item whose lister is not built cannot say.
  const Manifest manifest = parse_manifest(kManifest, "course.json");
  CHECK(inspect(scratch, {"tasks", full, "--full", "--of", "problems"}, manifest).out ==
        "workbook: --of: no capability 'problems' (inputs, needs_identity, links_student_code, classroom)\n");
  const Inspected unbuilt = inspect(scratch, {"tasks", full, "--full", "--of", "links_student_code"}, manifest);
  CHECK(unbuilt.status == 2);
  CHECK(unbuilt.out.find("workbook: --of: the tasks of M01 cannot be listed: ") == 0);
  // No item of FILE's modules has it: no task, which --full does not take for a pass.
  const Inspected none = inspect(scratch, {"tasks", full, "--full", "--of", "needs_identity"}, Manifest{});
  CHECK(none.status == 1);
  CHECK(none.out.find("no task of the items with needs_identity in ") != std::string::npos);

  // The gradebook: its columns add up, or the submission is named.
  const std::string book = "submission,score,max_score,status,M01,M01T1,M01T2\n";
  write_file(scratch.path / "good.csv", book + "alice,5,7,graded,5,4,1\nbob,0,7,build_error:M01,0,0,0\n");
  write_file(scratch.path / "bad.csv", book + "alice,5,7,graded,5,4,2\n");
  CHECK(inspect(scratch, {"gradebook", (scratch.path / "good.csv").string()}).status == 0);
  const Inspected bad = inspect(scratch, {"gradebook", (scratch.path / "bad.csv").string()});
  CHECK(bad.status == 1);
  CHECK(bad.out.find("alice: the tasks of M01 add up to 6, M01 is 5\n") == 0);
  CHECK(inspect(scratch, {"gradebook", partial}).status == 1);  // not a gradebook

  // The timings: the key of each timed test; a line out of the format fails.
  write_file(scratch.path / "timings.txt", "# comment\nM01\tvisible\t0.02\trotation\nM02\thidden\t1\tgamma\n");
  CHECK(inspect(scratch, {"timings", (scratch.path / "timings.txt").string()}).out == "M01\trotation\nM02\tgamma\n");
  write_file(scratch.path / "timings.txt", "M01 0.02 rotation\n");
  CHECK(inspect(scratch, {"timings", (scratch.path / "timings.txt").string()}).status == 1);

  // The policy: a rule's arguments; a rule that is none, or a file out of the format.
  const std::string policy = (scratch.path / "policy.txt").string();
  write_file(policy, "# comment\nomit tests\ngradescope-omit extras\nomit solutions\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "omit"}).out == "tests\nsolutions\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "keep"}).status == 2);
  write_file(policy, "keep tests\n");
  CHECK(inspect(scratch, {"policy", policy, "--rule", "omit"}).status == 1);

  // A wrong command line, or a file that is not there: exit status 2.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"tasks", full},                                // no --sum, --count or --full
           {"tasks", full, "--count", "--full"},           // two
           {"tasks", full, "--sum", "points"},             // no such column
           {"tasks", full, "--rule", "omit", "--count"},   // --rule is policy's
           {"tasks", full, "--count", "--manifest", "c"},  // --manifest goes with --of
           {"policy", policy},                             // no --rule
           {"results", full},                              // no such format
           {"gradebook"},                                  // no file
           {"gradebook", (scratch.path / "missing.csv").string()}}) {
    INFO(args.front());
    CHECK(inspect(scratch, args).status == 2);
  }
}

TEST_CASE("Inspect: a Classroom workflow, a test listing and a benchmark CSV; each check can fail",
          "[frontend][inspect]") {
  const Scratch scratch("inspect-more");
  // A Classroom workflow: its command-grader steps (not the checkout or the reporter).
  const std::string workflow = (scratch.path / "classroom.yml").string();
  const std::string step = "        uses: classroom-resources/autograding-command-grader@v1\n        with:\n";
  write_file(workflow, "    steps:\n      - name: Checkout code\n        uses: actions/checkout@v4\n"
                       "      - name: M01 T1\n        id: m01-t1\n" + step +
                       "          command: ./workbook grade --task M01T1 --strict\n          max-score: 4\n"
                       "      - name: M01 T2\n        id: m01-t2\n" + step +
                       "          command: ./workbook grade --task M01T2 --strict\n          max-score: 1.5\n"
                       "      - name: Autograding Reporter\n        with:\n          runners: m01-t1,m01-t2\n");
  CHECK(inspect(scratch, {"classroom", workflow}).out ==
        "m01-t1\t4\t./workbook grade --task M01T1 --strict\nm01-t2\t1.5\t./workbook grade --task M01T2 --strict\n");
  CHECK(inspect(scratch, {"classroom", workflow, "--count"}).out == "2\n");
  CHECK(inspect(scratch, {"classroom", workflow, "--sum", "max_score"}).out == "5.5\n");
  write_file(workflow, "      - name: M01 T1\n        id: m01-t1\n" + step + "          max-score: 4\n");
  CHECK(inspect(scratch, {"classroom", workflow}).out.find("lacks its id, command or max-score") != std::string::npos);
  write_file(workflow, "      - name: M01 T1\n        id: m01-t1\n" + step + "          command: x\n          max-score: four\n");
  CHECK(inspect(scratch, {"classroom", workflow}).status == 1);

  // A test program's listing, read by the grade driver's reader; a line without tags fails.
  const std::string listing = (scratch.path / "listing.txt").string();
  write_file(listing, "rotation\t[M01][T1]\ngamma [x]\t[M02][T2][points=2][hidden]\nhelper\t[tools]\n");
  CHECK(inspect(scratch, {"listing", listing}).out == "M01\trotation\nM02\tgamma [x]\nother\thelper\n");
  write_file(listing, "rotation [M01][T1]\n");
  const Inspected untagged = inspect(scratch, {"listing", listing});
  CHECK(untagged.status == 1);
  CHECK(untagged.out.find("line 1: expected name<TAB>tags") != std::string::npos);

  // A benchmark CSV: its rows (after the header); a row without five fields or a number fails.
  const std::string bench = (scratch.path / "bench.csv").string();
  write_file(bench, "group,case,quantity,value,unit\nsimulate,pendulum,cost per step,2.5,us\nmodal,n=9,error,1e-12,1\n");
  CHECK(inspect(scratch, {"bench", bench}).out == "2 rows\n");
  for (const char* text : {"simulate,pendulum,2.5,us\n", "simulate,pendulum,cost,fast,us\n",
                                  "simulate,pendulum,cost,nan,us\n", "group,case,quantity,value,unit\n"}) {
    INFO(text);
    write_file(bench, text);
    CHECK(inspect(scratch, {"bench", bench}).status == 1);
  }

  // A wrong command line: exit status 2.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"classroom", workflow, "--sum", "score"},  // classroom has max_score only
           {"classroom", workflow, "--full"},          // --full is tasks'
           {"bench", bench, "--count"},                // --count is tasks' and classroom's
           {"listing"}}) {                             // no file
    INFO(args.front());
    CHECK(inspect(scratch, args).status == 2);
  }
}
