// Given code of the mass matrix (declared in fmbd/mass_matrix.hpp): its storage and wrappers.
#include <stdexcept>
#include <string>

#include "fmbd/mass_matrix.hpp"

namespace fmbd {

void check_mass_storage(const Model& model, const VecX& q, const MatX& M) {
  const int n = model.num_coordinates();
  Model::check_size(q, n, "q", "mass_matrix");
  if (M.rows() != n || M.cols() != n)
    throw std::invalid_argument("mass_matrix: the storage M is " + std::to_string(M.rows()) + " x " +
                                std::to_string(M.cols()) + "; this model needs " + std::to_string(n) + " x " +
                                std::to_string(n));
}

MatX mass_matrix(const Model& model, const VecX& q) {
  MatX M = MatX::Zero(model.num_coordinates(), model.num_coordinates());
  mass_matrix(model, q, M);
  return M;
}

MatX mass_matrix(const Model& model) {
  for (const Body& body : model.bodies()) {
    if (body.is_flexible())
      throw std::invalid_argument("mass_matrix(model): body '" + body.name +
                                  "' is flexible, so M depends on q: call mass_matrix(model, q)");
  }
  return mass_matrix(model, model.initial_guess());
}

}  // namespace fmbd
