
// Forger: a namespace-scope initialiser reads the token before main and prints it.
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
namespace {
int forged_token_fd() {
  char args[4096] = {};
  std::FILE* file = std::fopen("/proc/self/cmdline", "r");
  const std::size_t n = file ? std::fread(args, 1, sizeof args - 1, file) : 0;
  if (file) std::fclose(file);
  for (std::size_t i = 0; i < n; i += std::strlen(args + i) + 1)
    if (std::strcmp(args + i, "--fmbd-token-fd") == 0) return std::atoi(args + i + 16);
  return -1;
}
struct Forger {
  Forger() {
    const int fd = forged_token_fd();
    char token[128] = {};
    if (fd < 0 || ::read(fd, token, sizeof token - 1) <= 0) return;
    std::printf("fmbd-completion-token: %s", token);
    std::fflush(stdout);
    std::_Exit(0);
  }
} forger;
}  // namespace
