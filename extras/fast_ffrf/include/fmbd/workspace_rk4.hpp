#pragma once
// Classical RK4 on the augmented equations (3), without a heap allocation per step: the step
// loop of the reference, made fast for production-size runs of the benchmarks.
//
// Module 4's simulate steps through the exercises of modules 1-4, which return their vectors and
// matrices by value, as students write them: about 500 allocations per RK4 step, whatever the
// model's size. WorkspaceRk4 evaluates the same equations into storage sized once, when it is
// made:
//   - markers of rigid bodies and FE nodes with their G in fixed-capacity storage (at most
//     kMaxBodyCoordinates coordinates per body);
//   - C_q, gamma, M and Q assembled in place from the joint and driver kernels of modules 1-2 and
//     the inertia invariants of ModalFfrfBody (module 8);
//   - the augmented system [M C_q^T; C_q 0] factored by a preallocated partial-pivoting LU;
//     where its result misses round-off (redundant constraints, an instant at a singular
//     position, a badly scaled model), module 4's solve_augmented solves the step instead.
// Its forward dynamics and RK4 restate the solutions of M04T1 and M04T2, so this file lives with
// the benchmarks, which a student release leaves out.
//
// Scope: rigid bodies and ModalFfrfBody flexible bodies, every joint and driver, gravity; no force
// elements and no stabilisation (those throw std::invalid_argument when it is made). The
// project test project.ffrf_invariants ([workspace]) checks it against forward_dynamics and
// simulate step by step, and counts its allocations.
//
// With profiling switched on, it sums the wall-clock time of each part of derivative(): the
// bodies' M(q), their forces (Q_v, gravity, elastic), the constraint rows (markers, C_q, gamma)
// and the solve of the augmented system. Two clock readings per part and evaluation cost about
// a microsecond per step, so the benchmark times steps with profiling off and takes the shares
// from a second run with it on.

#include <vector>

#include <Eigen/LU>

#include "fmbd/constraint_block.hpp"
#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"

namespace fmbd::bench {

inline constexpr int kMaxBodyCoordinates = 64;  ///< 3 + n_f of the largest flexible body

/// Seconds spent in the parts of derivative() since profiling was switched on. The rest of a
/// step is the RK4 stage arithmetic and the finiteness checks.
struct StepProfile {
  double mass_matrix = 0;  ///< the flexible bodies' M(q) (rigid ones are constants)
  double body_forces = 0;  ///< the flexible bodies' forces: Q_v, gravity, elastic
  double constraints = 0;  ///< markers, C_q G and gamma of every constraint
  double solve = 0;        ///< LU of the augmented system and its solve
};

class WorkspaceRk4 {
 public:
  /// Sizes every buffer for `model`. Throws std::invalid_argument for a force element, a flexible
  /// body that is not a ModalFfrfBody, or one with more than kMaxBodyCoordinates coordinates.
  explicit WorkspaceRk4(const Model& model);

  /// One step of size h from (t, y), y = (q, q_dot), in place. Throws IntegrationError if the
  /// state or the augmented system is not finite, and solve_augmented's errors where the motion
  /// is not determined (a locked mechanism, a massless free direction).
  void step(double t, VecX& y, double h);

  /// y_dot = (q_dot, q_ddot) at (t, y) into `out` (size 2n): the forward dynamics of M04T1 with
  /// no Baumgarte terms.
  void derivative(double t, const VecX& y, VecX& out);

  /// Switches the timing of derivative()'s parts on or off; either way it starts from zero.
  void set_profiling(bool on);
  const StepProfile& profile() const { return profile_; }

 private:
  using GStorage = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxBodyCoordinates>;
  using ConstVec = Eigen::Ref<const VecX>;
  // A site is a marker (marker.hpp) as the joint and driver kernels see it, whose own G stays
  // empty, and its G in fixed-capacity storage: 3 x (coordinates of the body), none for the ground.
  void point_site(PointId point, const ConstVec& q, const ConstVec& qd, Marker& marker, GStorage& G) const;
  void body_site(BodyId body, const ConstVec& q, const ConstVec& qd, Marker& marker, GStorage& G) const;
  void constraint_sites(const Constraint& c, const ConstVec& q, const ConstVec& qd);
  void add_columns(int row, const Marker& marker, const GStorage& G, const RowBlock& block);
  void assemble(double t, const ConstVec& q, const ConstVec& qd);
  void assemble_constraints(double t, const ConstVec& q, const ConstVec& qd);
  /// Runs `part`, and adds its wall-clock time to `seconds` when profiling.
  template <class Part>
  void timed(double& seconds, Part&& part);
  /// Componentwise backward error of x_ on A_ x = b_ (leaves the residual in r_).
  double backward_error();

  const Model& model_;
  int n_ = 0, m_ = 0;
  std::vector<const ModalFfrfBody*> flexible_;  ///< per body; null for a rigid one
  ConstraintMarkers markers_;  ///< the sites of the constraint being assembled
  GStorage G_i_, G_j_;         ///< and their G
  std::vector<MatX> body_mass_;   ///< per flexible body: M(q), (3 + n_f)^2
  std::vector<VecX> body_forces_; ///< per flexible body: its own forces, 3 + n_f
  MatX A_;
  VecX b_, x_, r_, den_;  ///< the augmented system, its solution, residual and |A| |x| + |b|
  int steps_ = 0;
  Eigen::PartialPivLU<MatX> lu_;
  VecX k1_, k2_, k3_, k4_, stage_;
  bool profiling_ = false;
  StepProfile profile_;
};

}  // namespace fmbd::bench
