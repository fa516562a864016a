#pragma once
// Exceptions of the workbook. Every error names its culprit: the body, joint, constraint
// row, iteration or time step that caused it.

#include <cstdio>
#include <stdexcept>
#include <string>

namespace fmbd {

/// Thrown by every exercise stub until the student fills it in. The message names the
/// task, e.g. "not implemented yet: M01T2 revolute".
class NotImplemented : public std::logic_error {
 public:
  explicit NotImplemented(const std::string& task) : std::logic_error("not implemented yet: " + task) {}
};

/// Marks the parameters of an exercise stub as unused on purpose: the stub compiles without a
/// warning, and a finished function that ignores one of its inputs gets the compiler's
/// unused-parameter warning. Delete the call together with the stub's throw.
template <typename... Args>
constexpr void unused(const Args&... /*parameters*/) noexcept {}

/// A number as a message shows it: four significant digits, "-1e-07", "0.25", "76.92", "inf" (never
/// std::to_string's "-0.000000").
inline std::string readable(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

/// A malformed model: unknown body or point, zero-length axis, duplicate driver, bad mass...
/// Derives from std::invalid_argument, like every argument check of the library.
class ModelError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace fmbd
