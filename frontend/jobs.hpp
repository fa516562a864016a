#pragma once
// How many compilers or tests may run at once here: the cores this process may use, fewer under
// a container's CPU quota (cgroup v2 cpu.max, v1 cpu.cfs_quota_us), and at most one per 700 MB
// (734003200 bytes) of the container's memory limit (a compiler of this course peaks below that).
// Gradescope's and CI's containers see the host's cores, but not its quota. The same rule and
// the same reason text as ./workbook's available_jobs.

#include <string>

namespace fmbd::frontend {

struct Jobs {
  int count = 1;       // at least 1
  std::string reason;  // "2 cores, a CPU quota of 1, 1024 MB of memory"
};

// The job count from `cores`, the cgroup files under `cgroup_root` (cpu.max, or
// cpu/cpu.cfs_quota_us with cpu/cpu.cfs_period_us; memory.max, or memory/memory.limit_in_bytes)
// and the machine's memory in `meminfo` (/proc/meminfo: a memory limit at or above its MemTotal
// is none, as cgroup v1 writes a huge number; an unreadable meminfo takes no memory limit).
Jobs available_jobs(int cores, const std::string& cgroup_root, const std::string& meminfo);

// The same for this process: the cores of its CPU affinity, FMBD_CGROUP_ROOT or /sys/fs/cgroup,
// /proc/meminfo.
Jobs available_jobs();

// FMBD_JOBS when it is set to a positive whole number, else `jobs.count`.
int job_count(const Jobs& jobs);

}  // namespace fmbd::frontend
