// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model) {
  // TASK(M03T1): M is n x n and block diagonal: body k contributes diag(m_k, m_k, J_k) at rows
  //   and columns 3k .. 3k+2 (model.bodies()[k].mass and .inertia). Centroidal coordinates make
  //   it constant and diagonal: no coupling between translation and rotation.
  // BEGIN SOLUTION
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    M.diagonal().segment<3>(3 * k) << b.mass, b.mass, b.inertia;
  }
  return M;
  // END SOLUTION
  // STUB: throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
