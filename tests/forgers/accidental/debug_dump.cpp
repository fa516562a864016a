
// Not a forger: a correct solution with a debug dump to a file left in, which the source check
// refuses with a clear message.
#include <fstream>
namespace fmbd {
void dump_rotation(double phi) {
  std::ofstream("rotation.txt") << rotation(phi) << "\n";
}
}  // namespace fmbd
