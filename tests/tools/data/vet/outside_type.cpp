// Refused: a type of the student's own outside namespace fmbd, named in the function type whose
// typeinfo the compiler emits for a std::function made from a function pointer.
#include <functional>

struct Outside {
  int value = 0;
};

namespace fmbd {
namespace {
int read(Outside* outside) { return outside->value; }
}  // namespace

int outside_type(Outside* outside) {
  std::function<int(Outside*)> f = &read;
  return f(outside);
}

}  // namespace fmbd
