#pragma once
// The planar Euler-Bernoulli frame element (module 5, tasks T1 to T3).
//
// Local element frame: x along the element from node a to node b, y turned +90 degrees.
// Local degrees of freedom, in this order:
//
//   u_e = (u_a, v_a, psi_a, u_b, v_b, psi_b)
//
// u axial and v transverse displacements, psi = dv/dx the section rotation. Axial motion uses
// linear shape functions, bending cubic Hermite ones; the two are uncoupled in the local frame.

#include <Eigen/Core>

#include "fmbd/fe_model.hpp"

namespace fmbd {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// M05T1. Local element stiffness matrix k_e (6x6) of an element of length L:
/// axial EA/L [[1, -1], [-1, 1]] on (u_a, u_b) and the Hermite bending matrix
/// EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2], [-12, -6L, 12, -6L], [6L, 2L^2, -6L, 4L^2]]
/// on (v_a, psi_a, v_b, psi_b).
Mat6 beam_stiffness(const Section& section, double L);

/// M05T2. Local element mass matrix m_e (6x6) of an element of length L, mass m = rho A L.
/// consistent: axial m/6 [[2, 1], [1, 2]] and bending
///   m/420 [[156, 22L, 54, -13L], [22L, 4L^2, 13L, -3L^2], [54, 13L, 156, -22L], [-13L, -3L^2, -22L, 4L^2]];
/// lumped (HRZ diagonal scaling of the consistent matrix): diag(m/2, m/2, m L^2/78, m/2, m/2, m L^2/78).
Mat6 beam_mass(const Section& section, double L, MassMatrixType type);

/// M05T3. Transformation T (6x6) from global to local element DOFs, u_local = T u_global, for an
/// element at angle alpha: T = blockdiag(R, R), R = [[c, s, 0], [-s, c, 0], [0, 0, 1]]. Global
/// element matrices are T^T k_e T and T^T m_e T.
Mat6 beam_transformation(double alpha);

}  // namespace fmbd
