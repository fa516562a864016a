// Exercise file generated from solutions/module03_lagrange/mass_matrix.cpp; this copy is yours to edit.
// Fill in every TODO(MnnTk) block; see the module README for the theory and hints.
// Module 3, task T1: the mass matrix.
#include "fmbd/errors.hpp"
#include "fmbd/mass_matrix.hpp"

namespace fmbd {

MatX mass_matrix(const Model& model) {
  // TODO(M03T1): M is n x n and block diagonal: body k contributes diag(m_k, m_k, J_k) at rows
  //   and columns 3k .. 3k+2 (model.bodies()[k].mass and .inertia). Centroidal coordinates make
  //   it constant and diagonal: no coupling between translation and rotation.
  throw NotImplemented("M03T1 mass_matrix");
}

}  // namespace fmbd
