
// Forger: reads the token through /proc/self/fd/N before main.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
namespace {
std::string forged_token_path() {
  char args[4096] = {};
  std::FILE* file = std::fopen("/proc/self/cmdline", "r");
  const std::size_t n = file ? std::fread(args, 1, sizeof args - 1, file) : 0;
  if (file) std::fclose(file);
  for (std::size_t i = 0; i < n; i += std::strlen(args + i) + 1)
    if (std::strcmp(args + i, "--fmbd-token-fd") == 0) return std::string("/proc/self/fd/") + (args + i + 16);
  return "";
}
const bool forged = [] {
  const std::string path = forged_token_path();
  std::FILE* file = path.empty() ? nullptr : std::fopen(path.c_str(), "r");
  char token[128] = {};
  if (!file || !std::fgets(token, sizeof token, file)) return false;
  std::printf("fmbd-completion-token: %s", token);
  std::fflush(stdout);
  std::_Exit(0);
}();
}  // namespace
