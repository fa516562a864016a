// Exercise file of module 1, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Revolute and prismatic joint constraints (fixture for the studentify tests).
#include "joints.hpp"

#include <cmath>

namespace fmbd {

// TODO(M01T1): return the planar rotation matrix A(phi).
Mat2 rotation(double phi) {
  throw NotImplemented("M01T1 rotation");
}

/* TASK(M01T9) in a block comment is left alone, and so is //TASK(M01T9). */
const char* kNote = "TASK(anything) inside a string is left alone";

// Notes: see TASK(M01T1) above; only a TASK directly after "// " is rewritten.
Vec2 revolute(const Vec2& q, const Vec2& s) {  // TODO(M01T2): r + A(phi) s
	throw NotImplemented("M01T2 revolute"); // TODO(M01T2): remove this line
}

// TODO(M01T3): write prismatic() here, with its declaration in joints.hpp.

int helper() {

      return 0;  // (extra spaces after "STUB: " are kept)
}

}  // namespace fmbd
