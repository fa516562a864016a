// fmbd-workbook: the typed front end of ./workbook: every command (commands.hpp).
//
//   fmbd-workbook [--source DIR] [--manifest FILE] COMMAND [ARGS...]
//
//   --source DIR     the workbook's tree; paths of the manifest are relative to it (default: the
//                    manifest's source_dir, or the current folder when no --manifest is given)
//   --manifest FILE  the course manifest (default: DIR/build/student/course.json)
//
// Its own options are read by the option layer of common/cli.hpp (-h or --help: the
// workbook's help). ./workbook runs it as `fmbd-workbook --source ROOT --manifest build/student/course.json
// COMMAND ARGS...` after configuring and building build/student. Exit status (exit_status.hpp):
// the command's; for an error that ends it ("workbook: ..." on stderr) 2 a wrong command line or a
// command that cannot go on, 3 a failed configure or build, 1 a failed step, 4 anything else; 2
// for no COMMAND (the workbook's help on stderr).

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "build.hpp"
#include "layout.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "jobs.hpp"

namespace fs = std::filesystem;
using namespace fmbd::frontend;
namespace cli = fmbd::cli;

namespace {

// fmbd-workbook's own options; the first word that is none of them is the command.
const cli::Command& program_options() {
  static const cli::Command spec = [] {
    cli::Command s;
    s.name = "fmbd-workbook";
    s.is_program = true;
    s.stops_at_positional = true;
    s.unknown_hint = " (./workbook help lists the commands)";
    s.options = {{"--source", cli::Kind::value, "DIR", "a path", "the workbook's tree"},
                 {"--manifest", cli::Kind::value, "FILE", "a path", "the course manifest"}};
    return s;
  }();
  return spec;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const cli::Parsed options = cli::parse(program_options(), std::vector<std::string>(argv + 1, argv + argc));
    std::string source = options.value("--source");
    std::string manifest_path = options.value("--manifest");
    const std::string command = options.help ? "help" : options.rest.empty() ? "" : options.rest.front();
    const std::vector<std::string> command_args(options.rest.begin() + (options.rest.empty() ? 0 : 1), options.rest.end());
    if (manifest_path.empty()) manifest_path = BuildLayout::of_preset(source.empty() ? "." : source, "student").course_json();
    Manifest manifest = read_manifest(manifest_path);
    if (source.empty()) source = manifest.source_dir;
    Context context{fs::absolute(source).lexically_normal().string(), std::move(manifest), std::cout};
    if (context.source_dir.size() > 1 && context.source_dir.back() == '/') context.source_dir.pop_back();
    if (command.empty()) {  // ./workbook alone: the help, as a wrong command line
      std::cerr << help_text(context.source_dir, context.manifest.instructor);
      return kExitUsage;
    }
    // Builds and tests run as many jobs at once as this machine allows (jobs.hpp), whichever of
    // them starts them: CMake, CTest, the grade driver, the tests' own ./workbook.
    const std::string jobs = std::to_string(job_count(available_jobs()));
    ::setenv("FMBD_JOBS", jobs.c_str(), 0);
    ::setenv("CMAKE_BUILD_PARALLEL_LEVEL", jobs.c_str(), 0);
    return run_command(command, command_args, context);
  } catch (const std::exception& error) {
    std::cout.flush();
    const bool manifest = dynamic_cast<const ManifestError*>(&error) != nullptr;
    std::cerr << "workbook: " << (manifest ? "the course manifest: " : "") << error.what() << "\n";
    return exit_status_of(error);
  }
}
