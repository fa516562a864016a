// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model) {
  // Given: n x n, with the blocks of flexible bodies (module 7 on) and zeros elsewhere.
  MatX M = flexible_mass(model);
  // TASK(M03T1): M is n x n and block diagonal: rigid body k contributes diag(m_k, m_k, J_k)
  //   (model.bodies()[k].mass and .inertia) at rows and columns model.offset(BodyId{k}) + 0, 1, 2.
  //   Centroidal coordinates make it constant and diagonal: no coupling between translation and
  //   rotation. Skip flexible bodies (bodies()[k].is_flexible(), module 7): flexible_mass(model)
  //   above has their blocks already. Return M.
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
