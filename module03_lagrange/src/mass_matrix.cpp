// Exercise file of module 3, yours to edit: replace each NotImplemented below a TODO
// with your code. The module README has the theory and the hints.
// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

namespace {

// The constant mass blocks of flexible bodies (module 7 on).
void add_flexible_mass(const Model& model, MatX& M) {
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    if (!b.is_flexible()) continue;
    const int at = model.offset(BodyId{k}), n = b.num_coordinates();
    M.block(at, at, n, n) = b.deformable->reference_mass_matrix();
  }
}

}  // namespace

MatX mass_matrix(const Model& model) {
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  // TODO(M03T1): M is n x n and block diagonal: rigid body k contributes diag(m_k, m_k, J_k)
  //   (model.bodies()[k].mass and .inertia) at rows and columns model.offset(BodyId{k}) + 0, 1, 2.
  //   Centroidal coordinates make it constant and diagonal: no coupling between translation and
  //   rotation. Skip flexible bodies (bodies()[k].is_flexible(), module 7): the line after this
  //   task adds their blocks.
  throw NotImplemented("M03T1 mass_matrix");
  add_flexible_mass(model, M);
  return M;
}

}  // namespace fmbd
