#pragma once
// What every benchmark program of the extras shares (include it from exactly one translation
// unit per program: it defines the counting allocator):
//   row()          one CSV row "group,case,quantity,value,unit" for ./workbook bench;
//   seconds()      the wall time of a call;
//   allocations    heap allocations so far: glibc's malloc, calloc and realloc are wrapped by
//                  counting ones (Eigen's dynamic matrices and the default operator new take
//                  their memory there). Not under AddressSanitizer, which has its own
//                  allocator: there the count stays 0.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace fmbd::bench {

inline std::atomic<long> allocations{0};

inline void row(const char* group, const std::string& name, const char* quantity, double value, const char* unit) {
  std::printf("%s,%s,%s,%.4g,%s\n", group, name.c_str(), quantity, value, unit);
  std::fflush(stdout);
}

template <typename F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fmbd::bench

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* malloc(std::size_t size) noexcept {
  fmbd::bench::allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  fmbd::bench::allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  fmbd::bench::allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
}
#endif
