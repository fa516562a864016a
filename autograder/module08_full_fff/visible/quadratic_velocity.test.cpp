// Module 8, task T4: the quadratic velocity vector Q_v = -L^T M_FE b (visible tests).
// The oracles: with a lumped (isotropic) mass matrix the nodal form is Lagrangian, so Q_v equals
// 1/2 d/dq (q_dot^T M q_dot) - (dM/dt) q_dot with M built here from the nodal velocities
// (ffrf_checks.hpp) and both derivatives by central differences; Q_v is quadratic in q_dot; and a
// free beam spinning at a constant rate stands still in its frame at the static FE stretch under
// the centrifugal load, solved here in the same reduced basis.

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "ffrf_checks.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/forward_dynamics.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"
#include "linear_algebra.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

GRADED_TEST("quadratic_velocity_vector lumped mass equals the velocity terms of the Lagrange equations",
            "[M08][T4][points=2]") {
  Random rnd(8401);
  const FlexibleBodyData beam = flexible_body_data(
      straight_beam(1.0, 8, square_section(2.1e11, 7850.0, 0.02), Vec2(0.2, -0.3), 0.7), MassMatrixType::lumped, 4);
  const FlexibleBodyData frame = flexible_body_data(l_frame(), MassMatrixType::lumped, 5);
  for (const FlexibleBodyData* data : {&beam, &frame}) {
    REQUIRE(isotropic_lumped(data->matrices.M));
    const int n_f = data->num_modes();
    for (int trial = 0; trial < 3; ++trial) {
      const VecX q = random_q(rnd, n_f, modal_scale(*data, 0.1));
      VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
      qd(2) = (trial == 1 ? -1.0 : 1.0) * rnd.uniform(1.0, 4.0);
      qd.tail(n_f) *= modal_scale(*data, 0.5);
      CAPTURE(q.transpose(), qd.transpose());
      const VecX Qv = quadratic_velocity_vector(*data, q, qd);
      const VecX expected = lagrangian_qv(*data, q, qd);
      CHECK_CLOSE_NAMED("your Q_v", Qv, expected, (Tolerance{1e-6 * expected.cwiseAbs().maxCoeff(), 1e-6}),
                        qv_hint(Qv, expected, *data, q, qd));
    }
  }
}

GRADED_TEST("quadratic_velocity_vector zero at rest and for a translating body and quadratic in q_dot",
            "[M08][T4][points=1]") {
  Random rnd(8402);
  const FlexibleBodyData frame = flexible_body_data(l_frame(Vec2(1.0, 2.0)), MassMatrixType::consistent, 4);
  const int n_f = frame.num_modes();
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_q(rnd, n_f, modal_scale(frame, 0.1));
    VecX qd = rnd.vector(3 + n_f, -1.0, 1.0);
    qd(2) = rnd.uniform(1.0, 3.0);
    qd.tail(n_f) *= modal_scale(frame, 0.5);
    CAPTURE(q.transpose(), qd.transpose());
    const VecX Qv = quadratic_velocity_vector(frame, q, qd);
    REQUIRE(Qv.size() == 3 + n_f);
    const double scale = Qv.cwiseAbs().maxCoeff();
    CHECK(scale > 0.0);
    const VecX zero = VecX::Zero(3 + n_f);
    CHECK_CLOSE_NAMED("your Q_v at rest", quadratic_velocity_vector(frame, q, zero), zero,
                      (Tolerance{1e-14 * scale, 0.0}),
                      "Q_v = 0 at rest: b holds only velocity terms (theta_dot^2 and theta_dot q_f_dot)");
    VecX translating = zero;
    translating.head<2>() = qd.head<2>();
    CHECK_CLOSE_NAMED("your Q_v of a frame that only translates", quadratic_velocity_vector(frame, q, translating),
                      zero, (Tolerance{1e-12 * scale, 0.0}),
                      "Q_v = 0 for a body that only translates: R_dot does not enter b");
    for (double s : {-1.0, 2.5}) {
      const VecX scaled = quadratic_velocity_vector(frame, q, VecX(s * qd));
      CHECK_CLOSE_NAMED("your Q_v at s times the velocities", scaled, VecX(s * s * Qv),
                        (Tolerance{1e-10 * s * s * scale, 1e-10}),
                        "Q_v is quadratic in q_dot: theta_dot^2 and theta_dot q_f_dot terms only");
    }
  }
}

namespace {

// The FE static solution of a free beam spinning at Omega, in the rotating frame and in the same
// basis (Ritz): the centrifugal load Omega^2 M (x + u) on the translational DOFs with
// u = Phi_f q_f, balanced by K u:
//   (K_ff - Omega^2 Phi_f^T M P Phi_f) q_f = Omega^2 Phi_f^T M X.
// Also the load, q_f_linear (K_ff q_f = load, without the u in it) and the stretch: the right
// end's x displacement minus the left end's.
struct CentrifugalStretch {
  VecX load, q_f, q_f_linear;
  double stretch = 0;
};

CentrifugalStretch centrifugal_stretch(const FlexibleBodyData& data, double Omega) {
  const int N = static_cast<int>(data.nodes.size());
  const MatX& M_FE = data.matrices.M;
  MatX P = MatX::Zero(3 * N, 3 * N);
  for (int k = 0; k < N; ++k) P.block<2, 2>(3 * k, 3 * k).setIdentity();
  const MatX& Phi_f = data.Phi_f;
  CentrifugalStretch out;
  out.load = Omega * Omega * Phi_f.transpose() * (M_FE * stacked_positions(data));
  const MatX K_ff = Phi_f.transpose() * data.matrices.K * Phi_f;
  out.q_f = solve_general(K_ff - Omega * Omega * Phi_f.transpose() * M_FE * P * Phi_f, out.load);
  out.q_f_linear = solve_general(K_ff, out.load);
  const VecX u = Phi_f * out.q_f;
  out.stretch = u(dof_index(N - 1, NodeDof::ux)) - u(dof_index(0, NodeDof::ux));
  return out;
}

// Dormand-Prince with tight tolerances, for a few spin periods of the beam.
SimulationOptions spin_options() {
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.step = 1e-3;
  o.max_step = 5e-3;
  return o;
}

// The largest drift along a trajectory of the elastic coordinates from q_f (norm) and of the spin
// rate from Omega.
std::pair<double, double> spin_drift(const Trajectory& s, const VecX& q_f, double Omega) {
  const int n_f = static_cast<int>(q_f.size());
  double worst = 0, worst_spin = 0;
  for (std::size_t i = 0; i < s.q.size(); ++i) {
    worst = std::max(worst, (s.q[i].tail(n_f) - q_f).norm());
    worst_spin = std::max(worst_spin, std::abs(s.qd[i](2) - Omega));
  }
  return {worst, worst_spin};
}

}  // namespace

GRADED_TEST("quadratic_velocity_vector spinning free beam holds the static FE centrifugal stretch",
            "[M08][T4][points=2]") {
  // A short thick beam (length / side = 10), so that the first axial free-free mode is among the
  // six kept modes, lumped mass (point masses: the centrifugal force is exactly m_k Omega^2 r_k).
  const double length = 1.0, side = 0.1, Omega = 40.0;
  const auto data = shared(
      flexible_body_data(straight_beam(length, 10, square_section(2e7, 1000.0, side)), MassMatrixType::lumped, 6));
  const int n_f = data->num_modes();
  // The FE static solution in the rotating frame, in the same basis (centrifugal_stretch above).
  const auto [load, q_f, q_f_linear, stretch] = centrifugal_stretch(*data, Omega);
  // The basis stretches: the right end moves out along +x, the left end along -x.
  CAPTURE(stretch, q_f.transpose(), q_f_linear.transpose());
  REQUIRE(stretch > 1e-4 * length);
  REQUIRE((q_f - q_f_linear).norm() < 0.05 * q_f.norm());  // Omega^2 well below the axial omega^2

  Model ffrf;
  const BodyId body = ffrf.add_flexible_body("beam", make_ffrf_body(data));
  VecX q0 = VecX::Zero(3 + n_f), qd0 = VecX::Zero(3 + n_f);
  q0(2) = 0.3;
  q0.tail(n_f) = q_f;
  qd0(2) = Omega;
  REQUIRE(ffrf.offset(body) == 0);
  const double qdd_scale = Omega * Omega * q_f.norm();
  {
    // At the stretch, nothing accelerates: M(q) q_ddot = Q_v - K q_f = 0.
    const Accelerations a = forward_dynamics(ffrf, q0, qd0, 0.0);
    const VecX Qv = quadratic_velocity_vector(*data, q0, qd0);
    const VecX elastic = elastic_rows(*data, q0);
    CAPTURE(a.qdd.transpose(), Qv.transpose(), elastic.transpose());
    const VecX zero = VecX::Zero(3 + n_f);
    CHECK_CLOSE_NAMED("your q_ddot", a.qdd, zero, (Tolerance{1e-7 * qdd_scale, 0.0}),
                diagnose(Qv, elastic,
                         {{"your centrifugal force points inward: the sign of the centripetal term in your b, or of your "
                           "Q_v, is wrong",
                           VecX(-elastic)},
                          {"your centrifugal force is missing: at the stretch, Q_v balances the elastic force "
                           "K_ff q_f",
                           zero}},
                         "a free beam spinning at Omega rests in its frame at the FE centrifugal stretch: Q_v = "
                         "(0, 0, 0, K_ff q_f) there; check your b's centripetal term and Q_v = -L^T M_FE b",
                         Tolerance{1e-5, 1e-5}));
  }
  {
    // And it stays there: simulate a few spin periods.
    const Trajectory s = simulate(ffrf, q0, qd0, 0.0, 0.4, spin_options());
    const auto [worst, worst_spin] = spin_drift(s, q_f, Omega);
    const std::string stretch_error = sci(worst / q_f.norm()), spin_error = sci(worst_spin / Omega);
    CAPTURE(stretch_error, spin_error, s.steps);
    CHECK_NEAR_NAMED("the largest drift of your spinning beam from the stretch, relative", worst / q_f.norm(), 0.0,
                     (Tolerance{1e-6, 0.0}),
                     with_formula("a free beam spinning at Omega stays at the centrifugal stretch: your Q_v should "
                                  "balance K_ff q_f (check your b's centripetal term and Q_v = -L^T M_FE b)",
                                  "the centripetal term of b_k is -theta_dot^2 (x_bar + u_bar)"));
    CHECK_NEAR_NAMED("the largest change of your spin rate, relative", worst_spin / Omega, 0.0, (Tolerance{1e-8, 0.0}),
                     "the spin rate of the stretched beam stays constant: no torque from Q_v at the stretch");
  }
  {
    // Module 7 has no centrifugal force: the same body spins at q_f = 0 without any stretch.
    Model intuitive;
    intuitive.add_flexible_body("beam", make_intuitive_body(data));
    VecX q_rest = q0;
    q_rest.tail(n_f).setZero();
    const Accelerations a7 = forward_dynamics(intuitive, q_rest, qd0, 0.0);
    const Accelerations a8 = forward_dynamics(ffrf, q_rest, qd0, 0.0);
    const VecX zero = VecX::Zero(3 + n_f);
    CHECK_CLOSE_NAMED(
        "module 7's q_ddot of the spinning beam", a7.qdd, zero, (Tolerance{1e-9 * qdd_scale, 0.0}),
        "module 7 (intuitive body) has no centrifugal force: a spinning unstretched beam does not accelerate "
        "(if this fails, check module 7)");
    // Module 8 pulls it out: M(q) q_ddot = Q_v at q_f = 0, where Q_v is the Omega^2 M X load.
    VecX Q = zero;
    Q.tail(n_f) = load;
    const VecX expected = solve_symmetric(rotated_reduced_mass(*data, q_rest(2)), Q);
    CHECK_CLOSE_NAMED("your q_ddot", a8.qdd, expected, (Tolerance{1e-6 * expected.norm(), 1e-6}),
                      with_formula("centrifugal force: a spinning unstretched beam accelerates into the stretch, "
                                   "M_ff q_f_ddot = Omega^2 Phi_f^T M_FE x (Q_v = -L^T M_FE b)",
                                   "the centripetal term of b_k is -theta_dot^2 (x_bar + u_bar)"));
  }
}
