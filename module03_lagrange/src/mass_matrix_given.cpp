// Given code of the mass matrix (declared in fmbd/mass_matrix.hpp): the system's M at q.
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model, const VecX& q) {
  Model::check_size(q, model.num_coordinates(), "q", "mass_matrix");
  MatX M = mass_matrix(model);
  for (int k = 0; k < model.num_bodies(); ++k) {
    const Body& b = model.bodies()[k];
    if (b.is_flexible()) b.deformable->add_mass(q, model.offset(BodyId{k}), M);
  }
  return M;
}

}  // namespace fmbd
