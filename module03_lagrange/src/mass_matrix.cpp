// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory; ./workbook hint MnnTk opens a task's hints.
// Module 3, task T1: the system's mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

void mass_matrix(const Model& model, const VecX& q, MatX& M) {
  check_mass_storage(model, q, M);
  // TODO(M03T1): the system's mass matrix M (n x n) at q into M (README section 1,
  //   mass_matrix.hpp), which holds an earlier call's entries. Rigid body k has
  //   model.bodies()[k].mass and .inertia; its coordinates start at model.offset(BodyId{k}). A
  //   flexible body (bodies()[k].is_flexible()) adds its own block:
  //   bodies()[k].deformable->add_mass(q, offset, M) (from module 7 on). Stuck? ./workbook hint M03T1
  unused(model, q, M);
  throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
