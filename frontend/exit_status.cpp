#include "exit_status.hpp"

#include "build.hpp"
#include "manifest.hpp"
#include "options.hpp"

namespace fmbd::frontend {

int exit_status_of(const std::exception& error) {
  if (dynamic_cast<const UsageError*>(&error)) return kExitUsage;
  if (dynamic_cast<const BuildError*>(&error) || dynamic_cast<const ManifestError*>(&error)) return kExitBuild;
  if (dynamic_cast<const StepFailed*>(&error)) return kExitFailed;
  return kExitError;
}

const char* exit_status_help() {
  return "Exit status: 0 done; 1 a step failed (tests, grade --strict, a demo, a benchmark); 2 a wrong command\n"
         "line or a command that cannot go on here; 3 configuring or building failed; 4 any other error.\n";
}

}  // namespace fmbd::frontend
