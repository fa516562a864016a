// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model) {
  // Given: n x n, with the blocks of flexible bodies (module 7 on) and zeros elsewhere.
  MatX M = flexible_mass(model);
  // TODO(M03T1): M is n x n and block diagonal: rigid body k contributes diag(m_k, m_k, J_k)
  //   (model.bodies()[k].mass and .inertia) at rows and columns model.offset(BodyId{k}) + 0, 1, 2.
  //   Centroidal coordinates make it constant and diagonal: no coupling between translation and
  //   rotation. Skip flexible bodies (bodies()[k].is_flexible(), module 7): flexible_mass(model)
  //   above has their blocks already. Return M.
  unused(model);
  throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
