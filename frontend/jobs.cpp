#include "jobs.hpp"

#ifdef __linux__
#include <sched.h>
#endif

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <thread>

#include "file_io.hpp"
#include "strings.hpp"

namespace fmbd::frontend {
namespace {

using fmbd::tools::read_file;

// Digits only, not empty (the shell's case of '' | max | -* | *[!0-9]*).
using fmbd::tools::is_digits;

std::string without_trailing_newlines(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

Jobs available_jobs(int cores, const std::string& cgroup_root, const std::string& meminfo) {
  Jobs jobs;
  jobs.count = cores;
  jobs.reason = std::to_string(cores) + " cores";

  std::string quota;
  std::string period;
  std::string text;
  if (read_file(cgroup_root + "/cpu.max", text)) {
    std::istringstream fields(first_line(text));
    fields >> quota >> period;
  } else if (read_file(cgroup_root + "/cpu/cpu.cfs_quota_us", text)) {
    quota = without_trailing_newlines(text);
    if (read_file(cgroup_root + "/cpu/cpu.cfs_period_us", text)) period = without_trailing_newlines(text);
  }
  if (is_digits(quota) && is_digits(period) && std::stoull(period) > 0) {
    const unsigned long long cpus = std::stoull(quota) / std::stoull(period);
    jobs.reason += ", a CPU quota of " + std::to_string(cpus);
    if (cpus < static_cast<unsigned long long>(jobs.count)) jobs.count = static_cast<int>(cpus);
  }

  std::string memory = "max";
  if (read_file(cgroup_root + "/memory.max", text) || read_file(cgroup_root + "/memory/memory.limit_in_bytes", text)) {
    memory = without_trailing_newlines(text);
  }
  std::string info;
  if (is_digits(memory) && read_file(meminfo, info)) {
    long double total = 0;  // bytes; 0 when meminfo names none
    std::istringstream lines(info);
    std::string line;
    while (std::getline(lines, line)) {
      if (line.rfind("MemTotal:", 0) == 0) total = std::strtold(line.c_str() + 9, nullptr) * 1024;
    }
    const long double limit = std::strtold(memory.c_str(), nullptr);
    if (total == 0 || limit < total) {
      const auto by_memory = static_cast<long long>(limit / 734003200.0L);
      jobs.reason += ", " + std::to_string(static_cast<long long>(limit / 1048576.0L)) + " MB of memory";
      if (by_memory < jobs.count) jobs.count = static_cast<int>(by_memory);
    }
  }
  jobs.count = std::max(jobs.count, 1);
  return jobs;
}

Jobs available_jobs() {
  int cores = 0;
#ifdef __linux__
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) cores = CPU_COUNT(&set);  // as nproc
#endif
  if (cores <= 0) cores = static_cast<int>(std::thread::hardware_concurrency());
  if (cores <= 0) cores = 2;
  const char* root = std::getenv("FMBD_CGROUP_ROOT");
  return available_jobs(cores, root != nullptr && *root != '\0' ? root : "/sys/fs/cgroup", "/proc/meminfo");
}

int job_count(const Jobs& jobs) {
  const char* value = std::getenv("FMBD_JOBS");
  if (value != nullptr && is_digits(value) && std::stoi(value) > 0) return std::stoi(value);
  return jobs.count;
}

}  // namespace fmbd::frontend
