// Module 3, task T1: the system's mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

void mass_matrix(const Model& model, const VecX& q, MatX& M) {
  check_mass_storage(model, q, M);
  // TASK(M03T1): the system's mass matrix M (n x n) at q into M (README section 1,
  //   mass_matrix.hpp), which holds an earlier call's entries. Rigid body k has
  //   model.bodies()[k].mass and .inertia; its coordinates start at model.offset(BodyId{k}). A
  //   flexible body (bodies()[k].is_flexible()) adds its own block:
  //   bodies()[k].deformable->add_mass(q, offset, M) (from module 7 on). Stuck? ./workbook hint M03T1
  // BEGIN SOLUTION
  M.setZero();
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    const int at = model.offset(BodyId{k});
    if (b.is_flexible()) {
      b.deformable->add_mass(q, at, M);
    } else {
      M.diagonal().segment<3>(at) << b.mass, b.mass, b.inertia;
    }
  }
  // END SOLUTION
  // STUB: unused(model, q, M);
  // STUB: throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
