#pragma once
// What the tests of the tutorial problems share (tests/problems.test.cpp and
// tests/answers_file.test.cpp, both in the program problems_tests):
//
//   kStudents               six identities whose variants the tests grade
//   all_modules()           the problems of modules 1-8, module by module; all_problems() in one list
//   ids_of(problems)        their ids
//   answer_line(p, value)   "MnnPk = VALUE UNIT\n", the value in SI with 12 significant digits
//   grade_value(p, s, v)    the grade of that one line against the solution s
//   run(...)                run_program() in this process, its output captured, FMBD_STUDENT set
//                           (or unset: ""), the token on a pipe when one is given
//   write_file(name, text)  "problems-test-NAME" in the working directory, holding `text`
//   correct_file(p, name)   a correct answers file of the problems for the identity `name`
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "grading.hpp"
#include "modules.hpp"
#include "problems.hpp"

namespace fmbd::problems::testing {

inline const std::vector<std::string> kStudents = {"Ada Lovelace", "Alan Turing", "Emmy Noether", "Leonhard Euler",
                                                   "Sophie Germain", "s1234567"};

inline std::vector<std::vector<Problem>> all_modules() {
  return {module01_problems(), module02_problems(), module03_problems(), module04_problems(),
          module05_problems(), module06_problems(), module07_problems(), module08_problems()};
}

inline std::vector<Problem> all_problems() {
  std::vector<Problem> all;
  for (const auto& module : all_modules()) all.insert(all.end(), module.begin(), module.end());
  return all;
}

inline std::vector<std::string> ids_of(const std::vector<Problem>& problems) {
  std::vector<std::string> ids;
  for (const Problem& p : problems) ids.push_back(p.id);
  return ids;
}

// The answer line of a value in SI, with the problem's unit, 12 significant digits.
inline std::string answer_line(const Problem& p, const Quantity& value, const std::string& unit = "") {
  const std::string u = unit.empty() ? p.unit : unit;
  return p.id + " = " + format_quantity(value, 12) + (u.empty() ? "" : " " + u) + "\n";
}

inline Grade grade_value(const Problem& p, const Solution& s, const Quantity& value, const std::string& unit = "") {
  return grade(p, s, read_answers(answer_line(p, value, unit), {p.id}));
}

// run_program in this process, its output captured, FMBD_STUDENT set (or unset: "").
struct Run {
  int status = 0;
  std::string out;
};

inline Run run(const std::vector<Problem>& problems, const std::vector<std::string>& args, const std::string& student,
               const std::string& answers_path, const std::string& token = "") {
  ProgramConfig config;
  config.module_tag = problems.front().module_tag();
  config.answers_path = answers_path;
  config.worked_path = "/nonexistent/problems.md";
  std::vector<std::string> argv_text = {"mNN_problems"};
  int fds[2] = {-1, -1};
  if (!token.empty()) {
    REQUIRE(::pipe(fds) == 0);
    const std::string line = token + "\n";
    REQUIRE(::write(fds[1], line.data(), line.size()) == static_cast<ssize_t>(line.size()));
    ::close(fds[1]);
    argv_text.push_back("--fmbd-token-fd");
    argv_text.push_back(std::to_string(fds[0]));
  }
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (student.empty()) {
    ::unsetenv("FMBD_STUDENT");
  } else {
    ::setenv("FMBD_STUDENT", student.c_str(), 1);
  }
  std::ostringstream out;
  std::streambuf* old = std::cout.rdbuf(out.rdbuf());
  Run r;
  r.status = run_program(problems, config, static_cast<int>(argv.size()) - 1, argv.data());
  std::cout.rdbuf(old);
  ::unsetenv("FMBD_STUDENT");
  r.out = out.str();
  return r;
}

inline std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = "problems-test-" + name;
  std::ofstream(path) << text;
  return path;
}

// A correct answers file of `problems` for `student`.
inline std::string correct_file(const std::vector<Problem>& problems, const std::string& student) {
  std::string text = "# answers of " + student + "\n\n";
  for (const Problem& p : problems) text += answer_line(p, make_variant(p, student).solve().answer);
  return text;
}

}  // namespace fmbd::problems::testing
