// Given code of the mass matrix (declared in fmbd/mass_matrix.hpp): the blocks of flexible bodies.
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX flexible_mass(const Model& model) {
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    if (!b.is_flexible()) continue;
    const int at = model.offset(BodyId{k}), n = b.num_coordinates();
    M.block(at, at, n, n) = b.deformable->reference_mass_matrix();
  }
  return M;
}

MatX mass_matrix(const Model& model, const VecX& q) {
  Model::check_size(q, model.num_coordinates(), "q", "mass_matrix");
  MatX M = mass_matrix(model);
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    if (!b.is_flexible()) continue;
    const int at = model.offset(BodyId{k}), n = b.num_coordinates();
    M.block(at, at, n, n) = b.deformable->mass_matrix(q.segment(at, n));
  }
  return M;
}

}  // namespace fmbd
