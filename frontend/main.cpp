// fmbd-workbook: the typed front end of ./workbook, for the commands ported to it (commands.hpp).
//
//   fmbd-workbook [--source DIR] [--manifest FILE] COMMAND [ARGS...]
//
//   --source DIR     the workbook's tree; paths of the manifest are relative to it (default: the
//                    manifest's source_dir, or the current folder when no --manifest is given)
//   --manifest FILE  the course manifest (default: DIR/build/student/course.json)
//
// ./workbook runs it as `fmbd-workbook --source ROOT --manifest build/student/course.json
// COMMAND ARGS...` after configuring and building build/student. Exit status: the command's; 2
// for a wrong command line or a command that cannot go on ("workbook: ..." on stderr).

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fmbd::frontend;

void usage(std::ostream& out) {
  out << "usage: fmbd-workbook [--source DIR] [--manifest FILE] COMMAND [ARGS...]\n\ncommands:\n";
  for (const CommandSpec* spec : commands()) out << usage_text(*spec);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string source;
  std::string manifest_path;
  std::size_t i = 0;
  try {
    for (; i < args.size() && args[i].rfind("--", 0) == 0; ++i) {
      if (args[i] == "--help") {
        usage(std::cout);
        return 0;
      }
      if ((args[i] == "--source" || args[i] == "--manifest") && i + 1 < args.size()) {
        (args[i] == "--source" ? source : manifest_path) = args[i + 1];
        ++i;
        continue;
      }
      if (args[i] == "--source" || args[i] == "--manifest") throw UsageError(args[i] + " needs a path");
      throw UsageError("fmbd-workbook: unknown option '" + args[i] + "'");
    }
    if (i >= args.size()) {
      usage(std::cerr);
      return 2;
    }
    const std::string command = args[i];
    const std::vector<std::string> command_args(args.begin() + static_cast<std::ptrdiff_t>(i) + 1, args.end());
    if (manifest_path.empty()) manifest_path = (fs::path(source.empty() ? "." : source) / "build/student/course.json").string();
    Manifest manifest = read_manifest(manifest_path);
    if (source.empty()) source = manifest.source_dir;
    Context context{fs::absolute(source).lexically_normal().string(), std::move(manifest), std::cout};
    if (context.source_dir.size() > 1 && context.source_dir.back() == '/') context.source_dir.pop_back();
    return run_command(command, command_args, context);
  } catch (const UsageError& error) {
    std::cout.flush();
    std::cerr << "workbook: " << error.what() << "\n";
    return 2;
  } catch (const ManifestError& error) {
    std::cerr << "workbook: the course manifest: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "workbook: " << error.what() << "\n";
    return 2;
  }
}
