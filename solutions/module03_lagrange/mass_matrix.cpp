// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model) {
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  // TASK(M03T1): the mass matrix M (n x n) of eq. (3) in centroidal coordinates (README
  //   section 1, mass_matrix.hpp). Rigid body k has model.bodies()[k].mass and .inertia; its
  //   coordinates start at model.offset(BodyId{k}). Skip flexible bodies
  //   (bodies()[k].is_flexible()): from module 7 on they add their own blocks (in
  //   mass_matrix(model, q)). Return M. Stuck? ./workbook hint M03T1
  // BEGIN SOLUTION
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    if (b.is_flexible()) continue;
    M.diagonal().segment<3>(model.offset(BodyId{k})) << b.mass, b.mass, b.inertia;
  }
  return M;
  // END SOLUTION
  // STUB: unused(model);
  // STUB: throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
