#pragma once
// Mechanical energy of a model (given code, module 3): the oracle of power balances and the
// monitor of the integrators.

#include "fmbd/model.hpp"

namespace fmbd {

/// T = 1/2 sum_k (m_k |R_dot_k|^2 + J_k phi_dot_k^2) of a rigid model. Throws
/// std::invalid_argument for a model with a flexible body, whose T depends on q (next one).
double kinetic_energy(const Model& model, const VecX& qd);
/// The same with each flexible body's own kinetic energy at (q_j, q_dot_j) (DeformableBody).
double kinetic_energy(const Model& model, const VecX& q, const VecX& qd);

/// V = -sum_k m_k g^T R_k - sum over global point forces F^T r_P
///     + the strain energy and gravity potential of each flexible body
///     + sum over spring-dampers 1/2 k (L - L0)^2 + sum over rotational ones 1/2 k (theta - theta0)^2.
double potential_energy(const Model& model, const VecX& q);

/// Power of the applied forces that V does not cover: dampers, actuators, torques and point
/// forces in the body frame. With the drivers' power P_d = lambda^T C_t (module 3),
/// d(T + V)/dt = P_d + nonconservative_power.
double nonconservative_power(const Model& model, const VecX& q, const VecX& qd, double t);

/// The drivers' power P_d = lambda^T C_t (given code), lambda the multipliers (m). Only the
/// drivers are evaluated: a joint does not depend on time, its C_t is zero.
double driver_power(const Model& model, const VecX& q, const VecX& lambda, double t);

}  // namespace fmbd
