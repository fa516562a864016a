#include "problems.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "build.hpp"
#include "file_io.hpp"
#include "ids.hpp"
#include "json.hpp"
#include "process.hpp"
#include "strings.hpp"

namespace fmbd::frontend {

namespace fs = std::filesystem;
using tools::Command;

namespace {

std::string name_file(const std::string& root) { return root + "/build/student.name"; }

// The items of `manifest` with problems of the student's own (has_personal_problems), with a
// module among `numbers` (empty: all).
std::vector<const GradedItem*> problem_items(const Manifest& manifest, const std::vector<int>& numbers) {
  std::vector<const GradedItem*> items;
  for (const GradedItem& item : manifest.graded) {
    if (!item.has_personal_problems()) continue;
    if (numbers.empty() || std::count(numbers.begin(), numbers.end(), item.module)) items.push_back(&item);
  }
  return items;
}

// Copies the input `file` of `tree` into `staged`, or writes there the model answers of `item`
// (its program's --model-answers) for `identity`; readable by every user.
void stage_input(const GradedItem& item, const std::string& file, const std::string& tree, const std::string& identity,
                 bool model_answers, const StagedAnswers& staged) {
  const fs::perms readable = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec;
  const fs::path target = fs::path(staged.folder()) / file;
  fs::create_directories(target.parent_path());
  fs::permissions(target.parent_path(), readable);
  if (model_answers) {
    Command command{{item.reference_program.value_or(item.program), "--model-answers"}, "", target.string()};
    command.environment = {{"FMBD_STUDENT", identity}};
    if (tools::run(command) != 0) throw BuildError("the model answers of " + item.id + " failed (" + target.string() + ")");
  } else if (fs::is_regular_file(fs::path(tree) / file)) {
    fs::copy_file(fs::path(tree) / file, target, fs::copy_options::overwrite_existing);
  } else {
    return;
  }
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                              fs::perms::others_read);
}

}  // namespace

std::string remembered_student(const std::string& root) {
  std::string name;
  tools::read_file(name_file(root), name);
  return tools::trim(name);
}

void remember_student(const std::string& root, const std::string& name) {
  fs::create_directories(root + "/build");
  std::ofstream(name_file(root), std::ios::trunc) << tools::trim(name) << "\n";
}

std::string gradescope_identity(const std::string& metadata_file) {
  std::string text;
  if (!tools::read_file(metadata_file, text)) throw UsageError("--gradescope-metadata: cannot read " + metadata_file);
  const json::Value metadata = json::parse(text);
  const auto users = metadata.find("users");
  if (users != metadata.end() && users->is_array()) {
    for (const json::Value& user : *users) {
      for (const char* key : {"email", "name"}) {
        const auto value = user.find(key);  // end() where the user is not an object
        if (value != user.end() && value->is_string() && !tools::trim(value->get<std::string>()).empty()) {
          return value->get<std::string>();
        }
      }
    }
  }
  throw UsageError("--gradescope-metadata: " + metadata_file + " names no user");
}

StagedAnswers::StagedAnswers() {
  const char* temporary = std::getenv("TMPDIR");
  std::string pattern = std::string(temporary && *temporary ? temporary : "/tmp") + "/fmbd-answers.XXXXXX";
  if (!::mkdtemp(pattern.data())) throw BuildError("cannot make a folder for the answers in " + pattern);
  folder_ = pattern;
  fs::permissions(folder_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                               fs::perms::others_read | fs::perms::others_exec);
}

StagedAnswers::~StagedAnswers() {
  std::error_code error;
  fs::remove_all(folder_, error);
}

std::vector<std::pair<std::string, std::string>> stage_answers(const std::vector<const GradedItem*>& items,
                                                               const std::string& tree, const std::string& identity,
                                                               bool model_answers, const StagedAnswers& staged) {
  for (const GradedItem* item : items) {
    // The model answers go to its first input; the others are copied.
    for (std::size_t i = 0; i < item->inputs.size(); ++i) {
      stage_input(*item, item->inputs[i], tree, identity, model_answers && i == 0, staged);
    }
  }
  std::vector<std::pair<std::string, std::string>> environment = {{"FMBD_ANSWERS_ROOT", staged.folder()}};
  if (!identity.empty()) environment.emplace_back("FMBD_STUDENT", identity);
  return environment;
}

const CommandSpec& problems_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "problems";
    s.options = {{"--student", OptionKind::value, "NAME", "your name", "whose numbers (remembered)"},
                 {"--worked", OptionKind::flag, "", "", "the worked solutions, where released"}};
    s.positional = "ID";
    s.max_positionals = 1;
    s.too_many = "problems takes one ID, e.g. ./workbook problems M01P2 (or M01 for a module)";
    s.help = {"The tutorial problems (all, a module's, e.g. M01, or one, e.g. M01P2) with your",
              "numbers: they depend on --student NAME, which is remembered (give the name your",
              "instructor grades you by). Write your answers in moduleNN_*/answers.txt (written",
              "for you to fill in); ./workbook grade grades them. --worked: the worked solutions",
              "and your numbers, once the module's solutions are released."};
    return s;
  }();
  return spec;
}

int run_problems(const std::vector<std::string>& args, const Context& context) {
  const ParsedOptions options = parse_options(problems_command(), args);
  if (print_usage_if_asked(options, problems_command(), context.out)) return 0;
  const std::string root = context.source_dir;
  if (options.has("--student")) {
    if (tools::trim(options.value("--student")).empty()) throw UsageError("--student needs your name");
    remember_student(root, options.value("--student"));
  }
  const std::string student = remembered_student(root);
  if (student.empty()) {
    throw UsageError("problems: your numbers depend on your name: ./workbook problems --student \"YOUR NAME\" (it is "
                     "remembered; give the name your instructor grades you by)");
  }

  std::string only;  // a problem id, or ""
  std::vector<int> numbers;
  if (!options.positionals.empty()) {
    std::string id = options.positionals.front();
    for (char& c : id) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    // A tutorial problem is a task of the student's inputs: its kind letter is 'P' (task_id.hpp).
    if (const std::optional<WrittenTask> task = task_id(id); task && task->task.kind == 'P') {
      only = task->id;
      numbers.push_back(task->task.module);
    } else if (id.size() == 3 && id[0] == 'M' && tools::is_digits(id.substr(1))) {
      numbers.push_back(std::stoi(id.substr(1)));
    } else {
      throw UsageError("problems: '" + options.positionals.front() + "' is no problem or module; write it like M01P2 or M01");
    }
  }
  const std::vector<const GradedItem*> items = problem_items(context.manifest, numbers);
  if (items.empty()) {
    throw UsageError(numbers.empty() ? "this copy has no tutorial problems"
                                     : "module " + std::to_string(numbers.front()) + " has no tutorial problems here");
  }

  const std::string& build = context.manifest.build_dir;
  int status = 0;
  for (const GradedItem* item : items) {
    const std::string log = build + "/" + item->target + ".build.log";
    if (!build_target(build, item->target, log)) {
      context.out << first_errors(log, "", {root}) << "\n";
      throw BuildError("the problems of module " + std::to_string(item->module) + " do not build (" + log + ")");
    }
    // Where the answers go: a file to fill in, the first time.
    const std::string& answers = item->inputs.front();  // has_personal_problems: it has one
    const fs::path answers_path = fs::path(root) / answers;
    if (!fs::exists(answers_path)) {
      tools::run(Command{{item->program, "--template"}, "", answers_path.string()});
      context.out << "workbook: wrote " << answers << " for your answers\n";
    }
    std::vector<std::string> argv = {item->program, options.has("--worked") ? "--worked" : "--print"};
    if (!only.empty()) argv.push_back(only);
    argv.insert(argv.end(), {"--student", student});
    context.out << std::flush;
    Command command{argv};
    command.environment = {{"FMBD_STUDENT", ""}};
    if (const int code = tools::run(command); code != 0) status = code;
  }
  context.out << "Your numbers are those of \"" << student << "\" (./workbook problems --student NAME changes it).\n";
  return status == 0 ? 0 : 2;
}

}  // namespace fmbd::frontend
