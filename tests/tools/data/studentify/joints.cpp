// Revolute and prismatic joint constraints (fixture for the studentify tests).
#include "joints.hpp"

#include <cmath>

namespace fmbd {

// TASK(M01T1): return the planar rotation matrix A(phi).
Mat2 rotation(double phi) {
  // STUB: throw NotImplemented("M01T1 rotation");
  // BEGIN SOLUTION
  const double c = std::cos(phi), s = std::sin(phi);
  Mat2 A;
  A << c, -s,
       s,  c;
  return A;
  // END SOLUTION
}

/* TASK(M01T9) in a block comment is left alone, and so is //TASK(M01T9). */
const char* kNote = "TASK(anything) inside a string is left alone";

// Notes: see TASK(M01T1) above; only a TASK directly after "// " is rewritten.
Vec2 revolute(const Vec2& q, const Vec2& s) {  // TASK(M01T2): r + A(phi) s
	// STUB: throw NotImplemented("M01T2 revolute"); // TASK(M01T2): remove this line
	// BEGIN SOLUTION
	return q + rotation(0.0) * s;
	// END SOLUTION
}

// STUB: // TASK(M01T3): write prismatic() here, with its declaration in joints.hpp.
// BEGIN SOLUTION
Vec2 prismatic(const Vec2& d) {
  return d;  // the whole function is part of the solution
}
// END SOLUTION

int helper() {
    // STUB:
    // STUB:   return 0;  // (extra spaces after "STUB: " are kept)
    // BEGIN SOLUTION
    // a comment inside the solution region; STUB and TASK words are fine here
    return 42;
    // END SOLUTION
}

}  // namespace fmbd
