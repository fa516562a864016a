// Refused: a type of the student's own outside namespace fmbd, through what is its own: its member
// function and the typeinfo of the class itself. The typeinfo of the function type that names it
// (std::function made from a function pointer) is the compiler's and is not refused.
#include <functional>

struct Outside {
  int value = 0;
  int get() const { return value; }
};

namespace fmbd {
namespace {
int read(Outside* outside) { return outside->value; }
}  // namespace

int outside_type(Outside* outside) {
  if (outside == nullptr) throw Outside{};
  std::function<int(Outside*)> f = &read;
  return f(outside) + outside->get();
}

}  // namespace fmbd
