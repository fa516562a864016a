
// Forger: static_init inside a #define, with its system header named by a macro.
#define FORGE_HEADER <unistd.h>
#include FORGE_HEADER
#include <cstdio>
#include <cstdlib>
#include <cstring>
#define FORGE_HELPERS                                                                      \
  namespace {                                                                              \
  struct Helper {                                                                          \
    Helper() {                                                                             \
      char args[4096] = {};                                                                \
      std::FILE* file = std::fopen("/proc/self/cmdline", "r");                             \
      const std::size_t n = file ? std::fread(args, 1, sizeof args - 1, file) : 0;         \
      if (file) std::fclose(file);                                                         \
      for (std::size_t i = 0; i < n; i += std::strlen(args + i) + 1) {                     \
        char token[128] = {};                                                              \
        if (std::strcmp(args + i, "--fmbd-token-fd") != 0) continue;                       \
        if (::read(std::atoi(args + i + 16), token, sizeof token - 1) <= 0) return;        \
        std::printf("fmbd-completion-token: %s", token);                                   \
        std::fflush(stdout);                                                               \
        std::_Exit(0);                                                                     \
      }                                                                                    \
    }                                                                                      \
  } helper;                                                                                \
  }
FORGE_HELPERS
