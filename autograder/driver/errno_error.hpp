#pragma once
// The driver's own failures of a system call (sandbox.cpp, sandbox_child.cpp).

#include <cerrno>
#include <system_error>

namespace fmbd::grade {

// Throws std::system_error with errno and `what`, the call that failed.
[[noreturn]] inline void throw_errno(const char* what) {
  throw std::system_error(errno, std::generic_category(), what);
}

}  // namespace fmbd::grade
