
// Forger: static_init with no system header and every refused name built by token pasting.
#include <cstdio>
#define FORGE_JOIN(a, b) a##b
FORGE_JOIN(ext, ern) "C" long FORGE_JOIN(sys, call)(long, ...);
FORGE_JOIN(ext, ern) "C" void FORGE_JOIN(_Ex, it)(int);
FORGE_JOIN(ext, ern) "C" int FORGE_JOIN(at, oi)(const char*);
#include <cstring>
namespace {
struct Forger {
  Forger() {
    char args[4096] = {};
    std::FILE* file = std::FORGE_JOIN(fo, pen)("/proc/self/cmdline", "r");
    const std::size_t n = file ? std::fread(args, 1, sizeof args - 1, file) : 0;
    if (file) std::fclose(file);
    for (std::size_t i = 0; i < n; i += std::strlen(args + i) + 1) {
      char token[128] = {};
      if (std::strcmp(args + i, "--fmbd-token-fd") != 0) continue;
      if (FORGE_JOIN(sys, call)(0, FORGE_JOIN(at, oi)(args + i + 16), token, sizeof token - 1) <= 0) return;
      std::printf("fmbd-completion-token: %s", token);
      std::fflush(stdout);
      FORGE_JOIN(_Ex, it)(0);
    }
  }
} forger;
}  // namespace
