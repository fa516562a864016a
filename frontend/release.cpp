#include "release.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <ostream>
#include <sstream>

#include "build.hpp"
#include "file_io.hpp"
#include "hints.hpp"
#include "ids.hpp"
#include "layout.hpp"
#include "markdown.hpp"
#include "process.hpp"
#include "strings.hpp"
#include "tables.hpp"

namespace fmbd::frontend {
namespace {

namespace fs = std::filesystem;

// Never copied: the builds, the demos' output, the repository and its CI.
const std::vector<std::string> kNeverCopied{"build", "out", ".git", ".ci", ".github"};

std::vector<std::string> names_of(const std::string& path) {
  std::vector<std::string> names;
  std::istringstream in(path);
  for (std::string name; std::getline(in, name, '/');) {
    if (!name.empty() && name != ".") names.push_back(name);
  }
  return names;
}

// The files of the tree to copy, relative: those git tracks where it tracks this tree (a log, a
// submission or a note in the tree is not part of the course; they are named), else all.
std::vector<std::string> tree_files(const std::string& root, std::ostream& out) {
  int status = 0;
  tools::capture(tools::Command({"git", "-C", root, "ls-files", "--error-unmatch", "workbook"}), status);
  std::vector<std::string> files;
  if (status == 0) {
    const std::string tracked = tools::capture(
        tools::Command({"git", "-C", root, "-c", "core.quotePath=false", "ls-files"}), status);
    for (const std::string& file : tools::split_lines(tracked)) {
      if (fs::exists(fs::symlink_status(root + "/" + file))) files.push_back(file);
    }
    const std::string others = tools::capture(
        tools::Command({"git", "-C", root, "-c", "core.quotePath=false", "ls-files", "--others", "--exclude-standard"}),
        status);
    std::vector<std::string> untracked;
    for (const std::string& file : tools::split_lines(others)) {
      if (!tools::starts_with(file, "out/")) untracked.push_back(file);
    }
    if (!untracked.empty()) {
      out << "workbook: left out of the copy, not tracked by git (" << untracked.size() << " files): ";
      for (std::size_t i = 0; i < untracked.size() && i < 10; ++i) out << untracked[i] << " ";
      out << "\n";
    }
    return files;
  }
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(root, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    const std::string relative = it->path().lexically_relative(root).generic_string();
    if (it.depth() == 0 && it->is_directory() &&
        std::count(kNeverCopied.begin(), kNeverCopied.end(), relative) > 0) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_directory()) files.push_back(relative);
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Copies the tree's files to `destination`, but those under `patterns` (and kNeverCopied),
// keeping their permissions.
void copy_tree(const std::string& root, const std::string& destination, std::vector<std::string> patterns,
               std::ostream& out) {
  patterns.insert(patterns.end(), kNeverCopied.begin(), kNeverCopied.end());
  for (const std::string& file : tree_files(root, out)) {
    if (excluded(file, patterns)) continue;
    const fs::path source = fs::path(root) / file;
    const fs::path target = fs::path(destination) / file;
    fs::create_directories(target.parent_path());
    if (fs::is_symlink(source)) {
      fs::copy_symlink(source, target);
    } else {
      fs::copy_file(source, target, fs::copy_options::overwrite_existing);
    }
  }
}

int number_option(const ParsedOptions& options, const std::string& name, int fallback) {
  if (!options.has(name)) return fallback;
  const std::string value = options.value(name);
  if (!tools::is_digits(value) || value.size() > 6) throw UsageError(name + " needs a number, got '" + value + "'");
  return std::stoi(value);
}


// The release policy of the manifest's copy (at `root`); a UsageError where it has none.
ReleasePolicy read_policy(const std::string& root, const Manifest& manifest) {
  if (!manifest.release_policy) throw UsageError("this copy has no release policy (the course manifest names none)");
  const std::string path = root + "/" + *manifest.release_policy;
  std::string text;
  if (!tools::read_file(path, text)) throw UsageError("cannot read the release policy " + path);
  return parse_policy(text, path);
}

std::string read_text(const fs::path& path) {
  std::string text;
  tools::read_file(path.string(), text);
  return text;
}

void write_text(const fs::path& path, const std::string& text) {
  if (!tools::write_if_changed(path.string(), text)) throw BuildError("cannot write " + path.string());
}

}  // namespace

namespace {

// The rules of the policy file, each with the member that holds its arguments.
using PolicyRules = std::vector<std::pair<std::string, std::vector<std::string> ReleasePolicy::*>>;
const PolicyRules& policy_rules() {
  static const PolicyRules rules = {{"omit", &ReleasePolicy::omit},
                                    {"omit-engine", &ReleasePolicy::omit_engine},
                                    {"strip", &ReleasePolicy::strip},
                                    {"strip-engine", &ReleasePolicy::strip_engine},
                                    {"gradescope-omit", &ReleasePolicy::gradescope_omit}};
  return rules;
}

// "no rule 'keep' (omit, omit-engine, strip, strip-engine, gradescope-omit)"
std::string no_rule(const std::string& rule) {
  std::string names;
  for (const auto& known : policy_rules()) names += (names.empty() ? "" : ", ") + known.first;
  return "no rule '" + rule + "' (" + names + ")";
}

}  // namespace

ReleasePolicy parse_policy(const std::string& text, const std::string& origin) {
  ReleasePolicy policy;
  int number = 0;
  for (const std::string& line : tools::split_lines(text)) {
    ++number;
    std::istringstream fields(line);
    std::string rule;
    std::string argument;
    std::string more;
    if (!(fields >> rule) || rule[0] == '#') continue;
    const std::string where = origin + ":" + std::to_string(number) + ": ";
    if (!(fields >> argument) || (fields >> more)) throw UsageError(where + "write a rule as RULE ARGUMENT");
    const auto known = std::find_if(policy_rules().begin(), policy_rules().end(),
                                    [&rule](const auto& entry) { return entry.first == rule; });
    if (known == policy_rules().end()) throw UsageError(where + no_rule(rule));
    (policy.*known->second).push_back(argument);
  }
  return policy;
}

const std::vector<std::string>& policy_rule(const ReleasePolicy& policy, const std::string& rule) {
  for (const auto& [name, arguments] : policy_rules()) {
    if (name == rule) return policy.*arguments;
  }
  throw UsageError(no_rule(rule));
}

bool excluded(const std::string& path, const std::vector<std::string>& patterns) {
  const std::vector<std::string> names = names_of(path);
  for (const std::string& pattern : patterns) {
    const std::vector<std::string> parts = names_of(pattern);
    if (parts.empty() || parts.size() > names.size()) continue;
    bool match = true;
    for (std::size_t i = 0; i < parts.size() && match; ++i) {
      match = ::fnmatch(parts[i].c_str(), names[i].c_str(), 0) == 0;
    }
    if (match) return true;
  }
  return false;
}

const CommandSpec& release_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "release";
    s.options = {{"--out", OptionKind::value, "DIR", "a directory", "the release"},
                 {"--through", OptionKind::value, "N", "a number", "modules 1..N"},
                 {"--solutions-through", OptionKind::value, "M", "a number", "the solutions of modules 1..M"},
                 {"--hint-ceiling", OptionKind::value, "L", "a number", "the hint levels up to L"}};
    s.help = {"Write a student copy to DIR: modules 1..N (default all) as skeletons with their",
              "visible tests, the hint ladders up to level L (0: none; level 3, the worked formula,",
              "by default only for modules 1..M), the reference solutions of modules 1..M (default",
              "none), the grader and the build files; no hidden tests, no mistake catalogue, no",
              "project tests, no maintainer tools; the engine (extras/, examples/) only when M",
              "covers every module."};
    s.synopsis = "--out DIR [--through N] [--solutions-through M] [--hint-ceiling L]";
    return s;
  }();
  return spec;
}

const CommandSpec& gradescope_command() {
  static const CommandSpec spec = [] {
    CommandSpec s;
    s.name = "gradescope";
    s.options = {{"--out", OptionKind::value, "FILE.zip", "a file name", "the zip"},
                 {"--module", OptionKind::repeatable, "N", "a number", "grade module N"},
                 {"--hidden-visibility", OptionKind::value, "V", "a value", "Gradescope visibility of hidden tests"}};
    s.synopsis = "--out FILE.zip [--module N]... [--hidden-visibility V]";
    s.help = {"Write a Gradescope autograder zip (setup.sh, run_autograder, this tree with its",
              "hidden tests and solutions) that grades modules N (default all)."};
    return s;
  }();
  return spec;
}

namespace {

// A page the release filters: a README.md anywhere, or a guide of docs/ (docs/NAME.md).
bool is_guide(const fs::path& release, const fs::path& file) {
  if (file.filename() == "README.md") return true;
  return file.extension() == ".md" && file.parent_path() == release / "docs";
}

// The READMEs and guides without their instructor-only parts, without their pointers to the
// extras where the release has none, then without their links to what the release lacks.
void strip_readmes(const std::string& release, const ReleasePolicy& policy) {
  std::vector<std::string> marks = policy.strip;
  if (!fs::exists(release + "/extras")) marks.insert(marks.end(), policy.strip_engine.begin(), policy.strip_engine.end());
  std::vector<fs::path> readmes;
  for (const auto& entry : fs::recursive_directory_iterator(release)) {
    if (entry.is_regular_file() && is_guide(release, entry.path())) readmes.push_back(entry.path());
  }
  for (const fs::path& readme : readmes) {
    const std::string text = markdown::squeeze_blank_lines(markdown::strip_marked(read_text(readme), marks));
    const fs::path folder = readme.parent_path();
    write_text(readme, markdown::drop_missing_links(
                           text, [&folder](const std::string& target) { return fs::exists(folder / target); }));
  }
}

// The timings of the hidden tests name them: a release keeps those of the visible ones (read and
// written by the driver's own code for the format, tables.hpp).
void keep_visible_timings(const std::string& release) {
  const fs::path timings = timings_path(release);
  if (!fs::exists(timings)) return;
  std::vector<grade::Timing> kept = grade::parse_timings(read_text(timings), timings.string());
  kept.erase(std::remove_if(kept.begin(), kept.end(), [](const grade::Timing& timing) { return timing.hidden; }),
             kept.end());
  write_text(timings, grade::timings_text(kept));
}

// The hint ladders stop at the instructor's ceiling; by default, a module whose solutions the
// release does not carry stops at level 2 (level 3 is the worked formula). Ceiling 0: none.
void cap_hints(const std::string& release, const std::vector<Module>& modules, int through,
               const std::optional<int>& hint_ceiling, int solutions_through) {
  for (const Module& module : modules) {
    if (module.number > through || !module.hints) continue;
    const fs::path hints = fs::path(release) / *module.hints;
    if (!fs::exists(hints)) continue;
    std::optional<int> ceiling = hint_ceiling;
    if (!ceiling && module.number > solutions_through) ceiling = 2;
    if (!ceiling) continue;
    if (*ceiling == 0) {
      fs::remove(hints);
      continue;
    }
    write_text(hints, hints::apply_ceiling(read_text(hints), *ceiling));
  }
}

// The tree copied without what the policy omits, the engine's files where the release does not
// carry every reference, and the modules after --through with their tests.
void copy_release_tree(const std::string& root, const std::string& release, const ReleasePolicy& policy,
                       const std::vector<Module>& modules, int through, int solutions_through, std::ostream& out) {
  const bool engine = std::all_of(modules.begin(), modules.end(),
                                  [&](const Module& module) { return module.number <= solutions_through; });
  std::vector<std::string> patterns = policy.omit;
  if (!engine) patterns.insert(patterns.end(), policy.omit_engine.begin(), policy.omit_engine.end());
  for (const Module& module : modules) {
    if (module.number > through) {
      patterns.push_back(module.folder);
      patterns.push_back("autograder/" + module.folder);
    }
  }
  copy_tree(root, release, patterns, out);
}

}  // namespace

int run_release(const std::vector<std::string>& args, const Context& context) {
  const std::string& root = context.source_dir;
  const Manifest& manifest = context.manifest;
  std::ostream& out = context.out;
  const std::vector<Module>& modules = manifest.modules;
  const ParsedOptions options = parse_options(release_command(), args);
  if (print_usage_if_asked(options, release_command(), out)) return 0;
  const int through = number_option(options, "--through", 99);
  const int solutions_through = number_option(options, "--solutions-through", 0);
  const std::optional<int> hint_ceiling =
      options.has("--hint-ceiling") ? std::optional<int>(number_option(options, "--hint-ceiling", 0)) : std::nullopt;
  if (!options.has("--out")) throw UsageError("release needs --out DIR");
  const std::string release = tools::absolute_path(options.value("--out"), fs::current_path().string());
  if (!manifest.instructor) {
    throw UsageError("release needs the instructor's copy (solutions/, autograder/mistakes/)");
  }
  if (solutions_through > through) {
    throw UsageError("--solutions-through (" + std::to_string(solutions_through) + ") is beyond --through (" +
                     std::to_string(through) + ")");
  }
  if (fs::exists(release) && !fs::is_empty(release)) throw UsageError("--out: '" + release + "' exists and is not empty");
  if (tools::starts_with(release + "/", root + "/") && !tools::starts_with(release + "/", root + "/build/")) {
    throw UsageError("--out: '" + release + "' is inside this tree (build/ is fine)");
  }
  fs::create_directories(release);
  const ReleasePolicy policy = read_policy(root, manifest);
  copy_release_tree(root, release, policy, modules, through, solutions_through, out);
  strip_readmes(release, policy);
  keep_visible_timings(release);
  cap_hints(release, modules, through, hint_ceiling, solutions_through);
  int released = 0;
  int carried = 0;
  for (const Module& module : modules) {
    carried += module.number <= through;
    const std::string solution = "/solutions/" + module.folder;
    if (module.number > solutions_through || !fs::is_directory(root + solution)) continue;
    fs::create_directories(release + "/solutions");
    fs::copy(root + solution, release + solution, fs::copy_options::recursive);
    ++released;
  }
  out << "workbook: wrote a student release to " << release << " (" << carried << " modules, the reference of "
      << released << ")\n";
  return 0;
}

int run_gradescope(const std::vector<std::string>& args, const Context& context) {
  const std::string& root = context.source_dir;
  const Manifest& manifest = context.manifest;
  std::ostream& out = context.out;
  const ParsedOptions options = parse_options(gradescope_command(), args);
  if (print_usage_if_asked(options, gradescope_command(), out)) return 0;
  std::string module_args;
  for (const std::string& module : options.all("--module")) {
    if (!tools::is_digits(module)) throw UsageError("--module needs a number, got '" + module + "'");
    module_args += " --module " + module;
  }
  const std::string visibility = options.value("--hidden-visibility", "after_published");
  check_visibility(visibility);
  const std::string zip =
      options.has("--out") ? tools::absolute_path(options.value("--out"), fs::current_path().string()) : "";
  if (!tools::ends_with(zip, ".zip")) throw UsageError("gradescope needs --out FILE.zip");
  if (!manifest.instructor) {
    throw UsageError("gradescope needs the instructor's copy (solutions/, autograder/mistakes/)");
  }
  const std::string stage = root + "/build/gradescope/zip";
  fs::remove_all(stage);
  fs::create_directories(stage);
  fs::create_directories(fs::path(zip).parent_path());
  copy_tree(root, stage, read_policy(root, manifest).gradescope_omit, out);
  for (const char* script : {"setup.sh", "run_autograder"}) {
    fs::copy_file(root + "/autograder/gradescope/" + script, stage + "/" + script, fs::copy_options::overwrite_existing);
  }
  write_text(stage + "/gradescope.conf", "# Written by ./workbook gradescope.\nMODULE_ARGS=\"" +
                                             (module_args.empty() ? "" : module_args.substr(1)) +
                                             "\"\nHIDDEN_VISIBILITY=" + visibility + "\n");
  fs::remove(zip);
  std::vector<std::string> argv{cmake_program(), "-E", "tar", "cf", zip, "--format=zip", "--"};
  std::vector<std::string> entries;
  for (const auto& entry : fs::directory_iterator(stage)) entries.push_back(entry.path().filename().string());
  std::sort(entries.begin(), entries.end());
  argv.insert(argv.end(), entries.begin(), entries.end());
  if (tools::run(tools::Command(argv, stage)) != 0) throw BuildError("packing " + zip + " failed");
  out << "workbook: wrote the Gradescope autograder " << zip << " (modules:" << (module_args.empty() ? " all" : module_args)
      << "; hidden tests: " << visibility << ")\n";
  return 0;
}

}  // namespace fmbd::frontend
