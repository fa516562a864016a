// Refused, though every line is inside namespace fmbd: a function with a C name (extern "C" gives
// it no namespace). The fix says what to do for that case, not "put it inside namespace fmbd".
namespace fmbd {

extern "C" int c_named(int x) { return x + 1; }

int inside_fmbd(int n) { return c_named(n); }

}  // namespace fmbd
