// The front end's library (frontend/): JSON, CSV, option tables and the build's layout
// (frontend_grade.test.cpp: the grade plan and the driver's invocation, bench tables, ids and the
// grading protocol; frontend_files.test.cpp: the job count, hint ladders, the course manifest,
// releases and the inspection of the tree).

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
#include "frontend_support.hpp"

namespace fs = std::filesystem;
using namespace fmbd::frontend;
namespace json = fmbd::json;
namespace csv = fmbd::csv;

using namespace fmbd::frontend_testing;


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

