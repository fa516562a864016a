// The program of a module (problems.hpp: run_program): the grade driver's list/token protocol,
// the format check, the statements, the worked solutions, the model answers and the template.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <new>
#include <optional>

#include "cli.hpp"
#include "problems.hpp"
#include "grading_protocol.hpp"
#include "problem_text.hpp"

namespace fmbd::problems {

namespace {

using text::trim;
using text::upper;

// The notes of the answers file that a run prints; the rest are counted.
constexpr std::size_t kNotesShown = 10;

// "module01_kinematics" of ".../module01_kinematics/answers.txt".
std::string parent_folder_name(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos || slash == 0) return "";
  const std::size_t before = path.rfind('/', slash - 1);
  return path.substr(before == std::string::npos ? 0 : before + 1, slash - (before == std::string::npos ? 0 : before + 1));
}

std::string read_token(int fd) {
  std::string token;
  char c = 0;
  while (::read(fd, &c, 1) == 1 && c != '\n') token += c;
  ::close(fd);
  return token;
}

std::string points_text(double points) { return format_value(points, 6); }

// The section "## ID ..." of problems.md up to the next "## ", or "" when absent.
std::string worked_section(const std::string& path, const std::string& id) {
  std::ifstream in(path);
  std::string out;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) {
      inside = line.rfind("## " + id, 0) == 0;
      if (!inside && !out.empty()) break;
    }
    if (inside) out += line + "\n";
  }
  return out;
}

// "VALUE m", "[x1, x2] m", "[[a11, a12], [a21, a22]]": the form of an answer line's value.
std::string answer_template(const Problem& p) {
  std::string out;
  if (p.kind == Kind::number) {
    out = "VALUE";
  } else if (p.kind == Kind::vector) {
    for (int r = 0; r < p.rows; ++r) out += (r ? ", x" : "[x") + std::to_string(r + 1);
    out += "]";
  } else {
    for (int r = 0; r < p.rows; ++r) {
      out += r ? ", [" : "[[";
      for (int c = 0; c < p.cols; ++c) out += (c ? ", a" : "a") + std::to_string(r + 1) + std::to_string(c + 1);
      out += "]";
    }
    out += "]";
  }
  if (!p.unit.empty()) out += " " + p.unit + (p.unit_optional ? " (or no unit: SI)" : "");
  return out;
}

const char* kNoIdentity =
    "no student identity: grade with --student NAME (./workbook), or set FMBD_STUDENT; your numbers "
    "depend on it";

// The program's command line: its mode, the problem asked for, and where things are.
struct Invocation {
  std::string mode = "grade";  // grade, list, check, template, model-answers, print, worked, help
  std::string only;            // --print ID, --worked ID
  std::string spec;            // the test to grade: "MnnPk: title" or MnnPk
  std::string answers_path;
  std::string student;  // --student NAME (for --print, --worked, --model-answers)
  bool have_student = false;
  int token_fd = -1;
};

// The command line's table: the modes, the protocol's options, and the Catch options that the
// grade driver passes to every program (taken and ignored).
cli::Command command_line() {
  using cli::Kind;
  cli::Command command = cli::program("", {{protocol::kListOption, Kind::flag, "", "", ""},
                                          {"--check", Kind::flag, "", "", ""},
                                          {"--model-answers", Kind::flag, "", "", ""},
                                          {"--template", Kind::flag, "", "", ""},
                                          {"--print", Kind::flag, "", "", ""},
                                          {"--worked", Kind::flag, "", "", ""},
                                          {protocol::kTokenFdOption, Kind::value, "N", "a file descriptor", ""},
                                          {"--answers", Kind::value, "FILE", "a file name", ""},
                                          {"--student", Kind::value, "NAME", "a name", ""},
                                          {protocol::kTimeLimitOption, Kind::value, "S", "seconds", ""},
                                          {"--use-colour", Kind::value, "yes|no", "a value", ""},
                                          {"--warn", Kind::value, "WHAT", "a value", ""},
                                          {"--reporter", Kind::value, "NAME", "a value", ""}},
                                      "SPEC", -1, "");
  command.unknown_hint = " (--help lists them)";
  return command;
}

// The invocation of a parsed command line: the last mode given wins; an ID right after --print
// or --worked is the problem asked for, any other positional the test to grade.
void read_sequence(const cli::Parsed& parsed, Invocation& call) {
  static const std::map<std::string, std::string> modes = {
      {protocol::kListOption, "list"}, {"--check", "check"},  {"--model-answers", "model-answers"},
      {"--template", "template"},      {"--print", "print"}, {"--worked", "worked"}};
  bool after_variant = false;  // the previous item was --print or --worked
  for (const auto& [name, value] : parsed.sequence) {
    if (modes.count(name)) call.mode = modes.at(name);
    if (name == protocol::kTokenFdOption) call.token_fd = std::atoi(value.c_str());
    if (name == "--answers") call.answers_path = value;
    if (name == "--student") {
      call.student = value;
      call.have_student = true;
    }
    if (name == "SPEC" && after_variant) call.only = upper(value);
    if (name == "SPEC" && !after_variant) call.spec = value;
    after_variant = name == "--print" || name == "--worked";
  }
}

// Reads the command line; returns 2 for an unknown option (after saying so), else -1.
int read_invocation(int argc, char** argv, const ProgramConfig& config, Invocation& call) {
  call.answers_path = config.answers_path;
  // The front end hands the answers over in a folder of its own (readable by the unprivileged
  // user the tests may run as): ROOT/<module folder>/answers.txt.
  if (const char* root = std::getenv("FMBD_ANSWERS_ROOT"); root != nullptr && *root != '\0') {
    call.answers_path = std::string(root) + "/" + parent_folder_name(config.answers_path) + "/answers.txt";
  }
  cli::Parsed parsed;
  try {
    parsed = cli::parse(command_line(), std::vector<std::string>(argv + std::min(argc, 1), argv + argc));
  } catch (const cli::UsageError& error) {
    std::cout << error.what() << "\n";
    return 2;
  }
  read_sequence(parsed, call);
  if (parsed.help) call.mode = "help";
  return -1;
}

int print_help(const ProgramConfig& config, const char* program) {
  std::cout << "usage: " << program
            << " [--answers FILE] (--fmbd-list | --check | --print [ID] | --worked [ID] | --model-answers |\n"
               "  \"MnnPk: title\")\n"
               "Tutorial problems of module "
            << config.module_tag
            << ": lists them, checks the answers file's format, prints your variant's statements\n"
               "(--student NAME or FMBD_STUDENT), its worked solution, or grades one problem\n"
               "(identity from FMBD_STUDENT only). Answers: "
            << config.answers_path << "\n";
  return 0;
}

std::vector<std::string> problem_ids(const std::vector<Problem>& problems) {
  std::vector<std::string> ids;
  for (const Problem& p : problems) ids.push_back(p.id);
  return ids;
}

// The answers file, with its first notes printed and the others counted.
AnswerFile read_answers_noted(const std::string& path, const std::vector<std::string>& ids) {
  AnswerFile file = read_answers_file(path, ids);
  if (!file.found) std::cout << path << ": note: no such file\n";
  for (std::size_t k = 0; k < file.notes.size() && k < kNotesShown; ++k)
    std::cout << path << ": note: " << file.notes[k] << "\n";
  if (file.notes.size() > kNotesShown)
    std::cout << path << ": note: " << file.notes.size() - kNotesShown
              << " more lines name no problem of this module (ignored)\n";
  return file;
}

int list_problems(const std::vector<Problem>& problems) {
  for (const Problem& p : problems)
    std::cout << protocol::listing_line(p.name(), protocol::task_tags(*protocol::parse_task_id(p.id), points_text(p.points)));
  return 0;
}

int check_answers(const std::vector<Problem>& problems, const Invocation& call) {
  const AnswerFile file = read_answers_noted(call.answers_path, problem_ids(problems));
  if (!file.not_text.empty()) {  // one message, not one per problem
    std::cout << file.not_text << "\n";
    return 1;
  }
  int bad = 0;
  for (const Problem& p : problems) {
    const std::optional<Grade> failure = check_format(p, file);
    if (failure) ++bad;
    std::cout << p.id << ": " << (failure ? failure->message : std::string("format OK")) << "\n";
  }
  return bad ? 1 : 0;
}

// An answers file to fill in (./workbook problems writes it).
int print_template(const std::vector<Problem>& problems, const ProgramConfig& config) {
  std::cout << "# Your answers to the tutorial problems of module " << std::stoi(config.module_tag.substr(1))
            << " (./workbook problems " << config.module_tag << " prints them).\n"
               "# One line per problem, ID = VALUE UNIT, e.g. M01P2 = [0.1, -0.25] m; '#' starts a comment.\n";
  for (const Problem& p : problems) std::cout << "# " << p.id << " = " << answer_template(p) << "\n";
  return 0;
}

// --student NAME, else FMBD_STUDENT.
std::string identity_of(const Invocation& call) {
  const char* env = std::getenv("FMBD_STUDENT");
  return !call.have_student && env ? std::string(env) : call.student;
}

// A correct answers file of the variant (./workbook grade --solutions).
int print_model_answers(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  const std::string student = identity_of(call);
  if (normalise_identity(student).empty() || !config.has_reference) {
    std::cout << "--model-answers needs the reference and a student identity (--student NAME or FMBD_STUDENT)\n";
    return 2;
  }
  for (const Problem& p : problems) {
    const Solution s = make_variant(p, student).solve();
    std::cout << p.id << " = " << format_quantity(s.answer, 12) << (p.unit.empty() ? "" : " " + p.unit) << "\n";
  }
  return 0;
}

// One problem's worked solution: its derivation (solutions/) and the variant's numbers.
void print_worked(const Problem& p, const Variant& v, const ProgramConfig& config) {
  const std::string text = worked_section(config.worked_path, p.id);
  const std::size_t body = text.find('\n');  // without the heading, printed above
  const std::string derivation = trim(text.substr(body == std::string::npos ? text.size() : body + 1));
  if (!derivation.empty()) std::cout << derivation << "\n\n";
  std::cout << "Your variant:\n" << v.statement << "\n\nYour numbers:\n";
  const Solution s = v.solve();
  for (const std::string& step : s.steps) std::cout << "  " << step << "\n";
  std::cout << "  answer: " << p.id << " = " << format_quantity(s.answer) << (p.unit.empty() ? "" : " " + p.unit)
            << "\n\n";
}

// --print and --worked: the statements, or the worked solutions, of the variant.
int print_variant(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  const std::string student = identity_of(call);
  if (normalise_identity(student).empty()) {
    std::cout << "no student identity: pass --student NAME (or set FMBD_STUDENT); your numbers depend on it\n";
    return 2;
  }
  if (call.mode == "worked" && !config.has_reference) {
    std::cout << "worked solutions come with the module's released solutions; this copy has none for "
              << config.module_tag << "\n";
    return 2;
  }
  bool any = false;
  for (const Problem& p : problems) {
    if (!call.only.empty() && p.id != call.only) continue;
    any = true;
    const Variant v = make_variant(p, student);
    std::cout << "## " << p.name() << " (" << points_text(p.points) << " points)\n\n";
    if (call.mode == "print") {
      std::cout << v.statement << "\n\nAnswer as: " << p.id << " = " << answer_template(p) << "\n\n";
    } else {
      print_worked(p, v, config);
    }
  }
  if (!any) {
    std::cout << "no problem " << call.only << " in " << config.module_tag << "\n";
    return 2;
  }
  return 0;
}

// The grade of one problem: its value with the identity of FMBD_STUDENT where the copy has the
// reference, else its format only.
Grade grade_one(const Problem& p, const AnswerFile& file, const ProgramConfig& config) {
  const char* env = std::getenv("FMBD_STUDENT");
  const std::string identity = env ? env : "";
  if (!normalise_identity(identity).empty() && config.has_reference) return grade(p, make_variant(p, identity).solve(), file);
  Grade g;
  const std::optional<Grade> failure = check_format(p, file);
  if (failure) return *failure;
  g.line = file.answers.at(p.id).front().line;
  g.message = config.has_reference ? kNoIdentity : kFormatOnly;
  return g;
}

// A failure in Catch's compact form, which the driver reads: FILE:LINE: failed: ID with 1 message:
// 'hint: ...'. A quote that the driver could read as the end of the message becomes ": an
// apostrophe inside a word ("instructor's") stays.
void print_failure(const std::string& file, int line, const std::string& id, std::string message) {
  for (std::size_t i = 0; i < message.size(); ++i) {
    if (message[i] == '\'' && !(i + 1 < message.size() && std::isalpha(static_cast<unsigned char>(message[i + 1]))))
      message[i] = '"';
  }
  std::cout << file << ":" << line << ": failed: " << id << " with 1 message: 'hint: " << message << "'\n";
}

// Grades the problem named by the driver, in its protocol: the completion token after a pass, the
// feedback in Catch's compact form after a failure.
int grade_problem(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call) {
  std::string token;
  if (call.token_fd >= 0) token = read_token(call.token_fd);
  const std::string name = protocol::test_name_of_spec(call.spec);
  for (const Problem& p : problems) {
    if (p.name() != name && p.id != upper(name)) continue;
    const AnswerFile file = read_answers_noted(call.answers_path, problem_ids(problems));
    if (call.have_student)
      std::cout << "note: --student sets the identity of --print and --worked; a grade reads FMBD_STUDENT only\n";
    const Grade g = grade_one(p, file, config);
    if (!g.passed) {
      print_failure(call.answers_path, g.line, p.id, g.message);
      return 1;
    }
    std::cout << p.id << ": correct\n";
    if (call.token_fd >= 0) std::cout << protocol::kCompletionTokenPrefix << token << std::endl;
    return 0;
  }
  std::cout << "No test cases matched '" << name << "'\n";
  return 1;
}

// The mode of `call`.
int run_mode(const std::vector<Problem>& problems, const ProgramConfig& config, const Invocation& call, char** argv) {
  if (call.mode == "help") return print_help(config, argv[0]);
  if (call.mode == "list") return list_problems(problems);
  if (call.mode == "check") return check_answers(problems, call);
  if (call.mode == "template") return print_template(problems, config);
  if (call.mode == "model-answers") return print_model_answers(problems, config, call);
  if (call.mode == "print" || call.mode == "worked") return print_variant(problems, config, call);
  return grade_problem(problems, config, call);
}

// An exception that ended a mode, said through the protocol: a grade fails with it as its
// feedback (the driver shows that rather than an exit status); another mode prints it.
int report_exception(const Invocation& call, const std::string& what) {
  const std::string message = "the program of the problems failed: " + what + "; tell your instructor";
  std::cout.clear();
  if (call.mode != "grade") {
    std::cout << "error: " << message << std::endl;
    return 2;
  }
  const std::string name = protocol::test_name_of_spec(call.spec);
  print_failure(call.answers_path, 0, name.substr(0, name.find(':')), message);
  std::cout.flush();
  return 1;
}

}  // namespace

int run_program(const std::vector<Problem>& problems, const ProgramConfig& config, int argc, char** argv) {
  Invocation call;
  if (const int status = read_invocation(argc, argv, config, call); status >= 0) return status;
  try {
    return run_mode(problems, config, call, argv);
  } catch (const std::bad_alloc&) {
    return report_exception(call, "out of memory");
  } catch (const std::exception& e) {
    return report_exception(call, e.what());
  } catch (...) {
    return report_exception(call, "an unknown exception");
  }
}

}  // namespace fmbd::problems
