#pragma once
// The full floating frame of reference formulation, nodal form (module 8, tasks T1-T5).
//
// The FE inertia acts on the absolute accelerations of the nodes, expressed in the body frame j
// (u_ddot^{j,o}: relative to the inertial frame o, components in frame j; README section 1
// derives them, in the notation of flexible_body.hpp). Stacked over the nodes in the DOF order
// of the FE model,
//
//   u_ddot^{j,o} = L(q) q_ddot + b(q, q_dot),    b: the velocity bias, what remains at q_ddot = 0,
//
// with L of size 3N x (3 + n_f). Projecting the FE equations M_FE u_ddot^{j,o} + K_FE u = F^j on
// the virtual displacements L dq (virtual work) gives
//
//   M(q) q_ddot = Q_v + Q_e + Q_a,   M(q) = L^T M_FE L,   Q_v = -L^T M_FE b,
//   Q_e = -K_bar q = -(0, 0, 0, K_ff q_f),   Q_a = L^T F^j.
//
// Gravity is module 7's flexible_gravity_force, the exact gradient of the potential of the body's
// first moment, -g^T (m R + A S_f q_f): with a lumped M_FE it equals L^T M_FE g^j (g^j = (A^T g, 0)
// at every node); with a consistent one the two differ (README section 2), and only the first is
// the gradient of the potential that the energy balance counts.

#include "fmbd/flexible_body.hpp"

namespace fmbd {

/// M08T1. The rows L_k of node k in L (3 x (3 + n_f)) into L_k: the absolute acceleration of node
/// k in frame j (translation, then rotation) is L_k q_ddot + b_k (README section 1). L_k takes that
/// size (it keeps its memory if it has it).
void node_acceleration_map(const NodeModes& node, const VecX& q, MatX& L_k);
/// The same as a value (given code, src/ffrf_given.cpp).
MatX node_acceleration_map(const NodeModes& node, const VecX& q);

/// M08T2. The rows b_k of node k in the velocity bias b (3): what remains of the absolute
/// acceleration of node k in frame j at q_ddot = 0 (README section 1).
Vec3 node_acceleration_bias(const NodeModes& node, const VecX& q, const VecX& qd);

/// L (3N x (3 + n_f)): node_acceleration_map of every node, stacked in the DOF order of the FE
/// model (node k at rows 3k .. 3k + 2), at the body's q (3 + n_f). Given code (src/ffrf_given.cpp)
/// for M08T3 to M08T5; the first form writes into L (no heap allocation once L has its size).
void stacked_map(const FlexibleBodyData& data, const VecX& q, MatX& L);
MatX stacked_map(const FlexibleBodyData& data, const VecX& q);

/// b (3N): node_acceleration_bias of every node, stacked like stacked_map. Given code for M08T4.
void stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd, VecX& b);
VecX stacked_bias(const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// Storage for M08T3 and M08T4, kept from call to call so that they allocate nothing once it has
/// the body's sizes (given code): the body's q_j and q_j_dot, L and b (stacked_map, stacked_bias),
/// M_FE L and M_FE b. One per thread: ffrf_workspace() gives this thread's.
struct FfrfWorkspace {
  VecX q_j, qd_j;
  MatX L;    ///< 3N x (3 + n_f)
  VecX b;    ///< 3N
  MatX ML;   ///< M_FE L
  VecX Mb;   ///< M_FE b
  MatX L_k;  ///< one node's rows, for stacked_map
};
FfrfWorkspace& ffrf_workspace();

// The body's terms of the system's equations of motion, corrected: module 7's add_intuitive_mass
// and add_intuitive_forces (intuitive_flexible.hpp) with M_bar replaced by M(q) and Q_v added;
// gravity and the elastic force stay as in module 7. The same contract: they add at the body's
// coordinates at .. at + 3 + n_f of the system's M, Q_a (q, q_dot of the system) and throw
// std::invalid_argument if those do not fit.

/// M08T3. M(q) in M: adds the mass matrix M(q_j) = L^T M_FE L ((3 + n_f) square, symmetric
/// positive definite; L stacked from node_acceleration_map over all nodes at the body's q_j) to
/// the system's M. At q_f = 0 it equals the intuitive M_bar of an M-orthogonal basis; with q_f it
/// couples rotation and deformation.
void add_ffrf_mass(const FlexibleBodyData& data, const VecX& q, int at, MatX& M);

/// The body's own M(q_j) (given code): add_ffrf_mass into a zero matrix, with q_j of size 3 + n_f.
MatX ffrf_mass_matrix(const FlexibleBodyData& data, const VecX& q_j);

/// M08T4. The quadratic velocity vector Q_v = -L^T M_FE b (3 + n_f) of the body's (q_j, q_j_dot):
/// centrifugal and Coriolis forces. Like add_ffrf_forces, it adds at the body's rows at .. at + 3 +
/// n_f of the system's Q_a (q, q_dot of the system); same errors.
void add_quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd, int at, VecX& Q_a);
/// Q_v of the body's own (q_j, q_j_dot) as a value (given code).
VecX quadratic_velocity_vector(const FlexibleBodyData& data, const VecX& q, const VecX& qd);

/// M08T5. Q_v in Q_a: adds the body's own forces of the full FFRF, module 7's gravity
/// (add_flexible_gravity_force) and elastic force -K_bar q_j plus the quadratic velocity vector Q_v at
/// (q_j, q_j_dot), to the system's Q_a.
void add_ffrf_forces(const FlexibleBodyData& data, const VecX& q, const VecX& qd, const Vec2& g, int at,
                     VecX& Q_a);

/// The body's own forces at (q_j, q_j_dot) (given code): add_ffrf_forces into a zero vector.
VecX ffrf_body_forces(const FlexibleBodyData& data, const VecX& q_j, const VecX& qd_j, const Vec2& g);

/// The full FFRF body for the Model (given code): module 7's node kinematics with the mass matrix
/// and forces above (add_ffrf_mass, add_ffrf_forces). Kinetic energy 1/2 q_dot^T M(q) q_dot. It
/// takes any basis (a frame clamped at a node too). The constructor throws
/// std::invalid_argument if data.matrices.M is not 3N x 3N (N nodes).
class FfrfBody : public IntuitiveBody {
 public:
  explicit FfrfBody(std::shared_ptr<const FlexibleBodyData> data);
  void add_mass(const VecX& q, int at, MatX& M) const override;
  void add_forces(const VecX& q, const VecX& qd, const Vec2& g, int at, VecX& Q_a) const override;

 private:
  std::shared_ptr<const FlexibleBodyData> fe_data_;  ///< the same data as data(), with M_FE
};

/// BodyFactory of the full FFRF (flexible_examples.hpp).
std::shared_ptr<const DeformableBody> make_ffrf_body(std::shared_ptr<const FlexibleBodyData> data);

}  // namespace fmbd
