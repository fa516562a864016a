// Exercise file of module 6, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 6, task T2: modal truncation on free-free modes, Phi = [Phi_r, Phi_f].
#include <string>

#include "fmbd/errors.hpp"
#include "fmbd/reduction.hpp"

namespace fmbd {

ReducedBasis modal_truncation(const FeModel& fe, const FeMatrices& matrices, int num_elastic) {
  const int n = fe.num_dofs();
  if (num_elastic < 0 || num_elastic > n - 3)
    throw std::invalid_argument("modal_truncation: num_elastic must be between 0 and " + std::to_string(n - 3) +
                                " (3 N - 3), got " + std::to_string(num_elastic));
  // TODO(M06T2): the basis Phi = [Phi_r, Phi_f] of README section 2 with `num_elastic` elastic
  //   free-free modes, num_rigid = 3, and its reduced matrices M_bar and K_bar (README
  //   introduction), modal_truncation.hpp.
  //   Build on rigid_body_modes and modal_analysis. Stuck? ./workbook hint M06T2
  unused(fe, matrices, num_elastic);
  throw NotImplemented("M06T2 modal_truncation");
}

}  // namespace fmbd
