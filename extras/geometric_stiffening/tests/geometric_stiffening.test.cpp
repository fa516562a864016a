// Project tests (not graded) of module 8's geometric stiffening (geometric_stiffening.hpp, the
// reference of M08T7 and M08T8); the geometric stiffness of the centrifugal tension, energy
// conservation in a free spin and the Kane beam's peak lag are graded tests of M08T8.
//
// Oracles, each independent of the code under test: the published element geometric stiffness
// matrix (closed form); finite differences of the node poses along a motion; the Southwell coefficient of the first cantilever
// mode, integrated here from the exact Euler-Bernoulli mode shape; module 8's linear FFRF at a low
// spin rate.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/geometric_stiffening.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/simulation.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::Tolerance;

namespace {

// A uniform beam along x from the origin, EI = 1 and rho A = 1 with L = 1: its first cantilever
// frequency is 1.8751^2 = 3.516 rad/s. EA = 10^4 puts the axial modes far above (157 rad/s).
Section unit_section() { return Section{1e4, 1.0, 1.0, 1e-4}; }

std::shared_ptr<const FlexibleBodyData> cantilever(int elements, int modes, MassMatrixType type) {
  return std::make_shared<FlexibleBodyData>(
      clamped_frame_body_data(straight_beam(1.0, elements, unit_section()), type, 0, modes));
}

// The state of a beam whose frame is clamped at node 0, spinning at Omega about that node (at the
// origin), at q_f and q_f_dot; theta = 0. R is the centroid, at -x_bar_0 from the node.
struct Spin {
  VecX q, qd, qdd_rigid;
};
Spin spinning(const FlexibleBodyData& data, double Omega, const VecX& q_f, const VecX& qd_f) {
  const int n_f = data.num_modes();
  Spin s;
  s.q = VecX::Zero(3 + n_f);
  s.q.head<2>() = -data.nodes[0].x_bar;
  s.q.tail(n_f) = q_f;
  s.qd = VecX::Zero(3 + n_f);
  s.qd.head<2>() = Omega * I_tilde() * s.q.head<2>();
  s.qd(2) = Omega;
  s.qd.tail(n_f) = qd_f;
  s.qdd_rigid = VecX::Zero(3 + n_f);  // R_ddot = -Omega^2 R, theta_ddot = 0
  s.qdd_rigid.head<2>() = -Omega * Omega * s.q.head<2>();
  return s;
}

// The elastic equations with the frame's motion prescribed: M_ff q_f_ddot = F(q_f, q_f_dot),
// F = Q_f - M_fr q_r_ddot.
VecX elastic_force(const DeformableBody& body, const FlexibleBodyData& data, double Omega, const VecX& q_f,
                   const VecX& qd_f) {
  const Spin s = spinning(data, Omega, q_f, qd_f);
  const int n_f = data.num_modes();
  return body.body_forces(s.q, s.qd, Vec2::Zero()).tail(n_f) -
         body.mass_matrix(s.q).bottomRows(n_f) * s.qdd_rigid;
}

// -dF/dq_f and -dF/dq_f_dot at rest in the rotating frame, by central differences.
void linearise(const DeformableBody& body, const FlexibleBodyData& data, double Omega, MatX& K, MatX& C) {
  const int n_f = data.num_modes();
  const double h = 1e-6;
  K.resize(n_f, n_f);
  C.resize(n_f, n_f);
  const VecX zero = VecX::Zero(n_f);
  for (int j = 0; j < n_f; ++j) {
    const VecX e = VecX::Unit(n_f, j) * h;
    K.col(j) = -(elastic_force(body, data, Omega, e, zero) - elastic_force(body, data, Omega, -e, zero)) / (2 * h);
    C.col(j) = -(elastic_force(body, data, Omega, zero, e) - elastic_force(body, data, Omega, zero, -e)) / (2 * h);
  }
}

// The lowest squared frequency of M q_ddot + C q_dot + K q = 0 about the spinning state: the
// smallest eigenvalue of M^-1 K when C = 0 (negative: the state is unstable).
double lowest_omega_squared(const DeformableBody& body, const FlexibleBodyData& data, double Omega) {
  MatX K, C;
  linearise(body, data, Omega, K, C);
  const int n_f = data.num_modes();
  const MatX M = body.mass_matrix(spinning(data, Omega, VecX::Zero(n_f), VecX::Zero(n_f)).q).bottomRightCorner(n_f, n_f);
  INFO("gyroscopic coupling of bending modes of a straight beam should vanish: |C| = " << C.norm());
  CHECK(C.norm() <= 1e-6 * (1.0 + K.norm()));
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(0.5 * (K + K.transpose()), M);
  return eig.eigenvalues()(0);
}

// Southwell coefficient of the first mode of a uniform cantilever spinning about its root (hub
// radius 0): alpha = int N phi'^2 / int rho A phi^2 per Omega^2, N = rho A (L^2 - x^2)/2, with the
// exact mode phi = cosh bx - cos bx - sigma (sinh bx - sin bx), bL = 1.875104 (L = 1, rho A = 1).
double southwell_coefficient() {
  const double b = 1.8751040687;
  const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  const int n = 2000;
  double num = 0.0, den = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);  // Simpson
    const double phi = std::cosh(b * x) - std::cos(b * x) - sigma * (std::sinh(b * x) - std::sin(b * x));
    const double dphi = b * (std::sinh(b * x) + std::sin(b * x) - sigma * (std::cosh(b * x) - std::cos(b * x)));
    num += w * 0.5 * (1.0 - x * x) * dphi * dphi;
    den += w * phi * phi;
  }
  return num / den;
}

}  // namespace

TEST_CASE("hermite_slope_matrix is the published element geometric stiffness per unit axial force",
          "[extras][geometric_stiffening]") {
  // Closed form (e.g. Przemieniecki, Theory of Matrix Structural Analysis, 1968): N/(30 l) times
  // [36 3l -36 3l; 3l 4l^2 -3l -l^2; -36 -3l 36 -3l; 3l -l^2 -3l 4l^2].
  const double l = 0.7;
  Mat4 expected;
  expected << 36, 3 * l, -36, 3 * l, 3 * l, 4 * l * l, -3 * l, -l * l, -36, -3 * l, 36, -3 * l, 3 * l, -l * l, -3 * l,
      4 * l * l;
  expected /= 30 * l;
  CHECK_CLOSE(hermite_slope_matrix(l), expected, (Tolerance{1e-13, 1e-12}),
              "int N'^T N' ds of the cubic Hermite functions: check dN/ds (the 1/l factors)");
  CHECK_THROWS_MENTIONING(hermite_slope_matrix(0.0), ModelError, "length 0");
}

TEST_CASE("node markers and kinetic energy follow the foreshortened node positions",
          "[extras][geometric_stiffening]") {
  const auto data = cantilever(4, 3, MassMatrixType::lumped);
  const StiffenedFfrfBody body(data);
  const int n = 3 + data->num_modes();
  VecX q0(n), v(n), a(n);
  q0 << 0.3, -0.2, 0.4, 0.05, -0.02, 0.01;
  v << 0.7, 0.1, 1.3, -0.4, 0.3, 0.2;
  a << -0.2, 0.5, 0.8, 0.6, -0.9, 0.4;
  auto q_at = [&](double t) -> VecX { return q0 + t * v + 0.5 * t * t * a; };
  const double h = 1e-4;
  double kinetic = 0.0;
  const MatX M_FE(data->matrices.M);
  for (int k = 0; k < body.num_nodes(); ++k) {
    const NodeMarker m = body.node_marker(k, q0, v);
    const Vec3 pose_dot = (body.node_marker(k, q_at(h), v).pose - body.node_marker(k, q_at(-h), v).pose) / (2 * h);
    CHECK_CLOSE(m.velocity, pose_dot, (Tolerance{1e-7, 1e-7}), "G_k q_dot should be d/dt of the node pose");
    // d2/dt2 pose = G q_ddot + c along q(t).
    const Vec3 pose_ddot = (body.node_marker(k, q_at(h), v).pose - 2 * m.pose + body.node_marker(k, q_at(-h), v).pose) / (h * h);
    CHECK_CLOSE(m.G * a + m.convective, pose_ddot, (Tolerance{1e-5, 1e-5}),
                "the convective term should hold every velocity term of the foreshortening");
    kinetic += 0.5 * (M_FE(3 * k, 3 * k) * pose_dot.head<2>().squaredNorm() + M_FE(3 * k + 2, 3 * k + 2) *
                                                                                     pose_dot(2) * pose_dot(2));
  }
  CHECK_NEAR(body.kinetic_energy(q0, v), kinetic, (Tolerance{1e-9, 1e-6}),
             "1/2 q_dot^T M(q) q_dot should be the nodal kinetic energy (lumped mass)");
  // At the anchor (the clamped root) nothing moves relative to the frame.
  CHECK_CLOSE(body.node_marker(0, q0, v).G.rightCols(3), MatX::Zero(3, 3), (Tolerance{1e-12, 0}),
              "node 0 is the anchor: no elastic motion");
}

TEST_CASE("the first in-plane frequency of a rotating cantilever rises by the Southwell coefficient",
          "[extras][geometric_stiffening]") {
  // In-plane bending of a beam spinning about its root: omega^2 = omega_0^2 + (alpha - 1) Omega^2
  // + O(Omega^4), alpha the Southwell coefficient (-1: the centrifugal softening of in-plane
  // motion). The linear FFRF has only the -1.
  const auto data = cantilever(10, 3, MassMatrixType::consistent);
  const StiffenedFfrfBody stiff(data);
  const FfrfBody linear(data);
  const double alpha = southwell_coefficient();
  CHECK(alpha == Approx(1.193).margin(0.001));  // the value usually tabulated for hub radius 0
  const double Omega = 0.3;  // omega_0 = 3.516: Omega^2 / omega_0^2 = 0.007
  const double w0 = lowest_omega_squared(stiff, *data, 0.0);
  CHECK(std::sqrt(w0) == Approx(1.8751040687 * 1.8751040687).epsilon(1e-3));
  const double slope_stiff = (lowest_omega_squared(stiff, *data, Omega) - w0) / (Omega * Omega);
  const double slope_linear = (lowest_omega_squared(linear, *data, Omega) - w0) / (Omega * Omega);
  INFO("d omega^2 / d Omega^2: stiffened " << slope_stiff << ", linear " << slope_linear << ", expected "
                                           << alpha - 1 << " (stiffened) and -1 (linear)");
  CHECK(slope_stiff == Approx(alpha - 1).epsilon(0.02));
  CHECK(slope_linear == Approx(-1.0).epsilon(0.01));
  // Above the first frequency the linear form has lost its stiffness; the stiffened one has not.
  const double fast = 2 * std::sqrt(w0);
  CHECK(lowest_omega_squared(linear, *data, fast) < 0.0);
  CHECK(lowest_omega_squared(stiff, *data, fast) > w0);
}

TEST_CASE("the stiffened spin-up agrees with module 8 at a slow rate and stays bounded at a fast one",
          "[extras][geometric_stiffening]") {
  // The unit beam (first cantilever frequency 3.5 rad/s), frame clamped at the hub, an 8 s spin-up
  // (omega_1 T = 28, as for the aluminium section of SpinUpBeamParameters at 10 m spun up in the
  // 15 s of Kane, Ryan and Banerjee's profile; their own beam has omega_1 T = 57), to t = 9 s.
  auto peak = [](double rate, const BodyFactory& make) {
    SpinUpBeamParameters p;
    p.length = 1.0;
    p.A = p.rho = 1.0;
    p.E = 1e4;
    p.I = 1e-4;
    p.spin_rate = rate;
    p.spin_up_time = 8.0;
    p.elements = 4;
    p.modes = 2;
    p.basis = BodyBasis::clamped_frame;
    const FlexibleExample ex = spin_up_beam(p, make);
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = 1e-7;
    o.atol = 1e-9;
    o.max_step = 0.02;
    o.stabilisation = Stabilisation::projection;
    o.output_interval = 0.05;
    // In pieces of 0.5 s, stopping once the tip leaves the hub's radial line by 1 m (a run-away).
    VecX q = ex.q0, qd = ex.qd0;
    double worst = 0.0;
    for (int piece = 0; piece < 18 && worst <= 1.0; ++piece) {
      const Trajectory run = simulate(ex.model, q, qd, 0.5 * piece, 0.5 * (piece + 1), o);
      for (const VecX& qi : run.q) {
        const Vec2 tip = point_position(ex.model, ex.model.find_point("beam tip"), qi);
        const double hub = ex.model.body_coordinates(qi, ex.model.find_body("hub"))(2);
        worst = std::max(worst, std::abs((rotation(hub).transpose() * tip).y()));
      }
      q = run.q.back();
      qd = run.qd.back();
    }
    return worst;
  };
  const double slow_linear = peak(0.3, make_ffrf_body), slow_stiff = peak(0.3, make_stiffened_ffrf_body);
  INFO("peak tip deflection at 0.3 rad/s: linear " << slow_linear << " m, stiffened " << slow_stiff << " m");
  // The two differ by the stiffness ratio, (omega_0^2 + 0.19 Omega^2) / (omega_0^2 - Omega^2) - 1 = 0.9 %.
  CHECK(slow_stiff == Approx(slow_linear).epsilon(0.02));
  CHECK(slow_stiff < slow_linear);
  const double fast_linear = peak(7.0, make_ffrf_body), fast_stiff = peak(7.0, make_stiffened_ffrf_body);
  INFO("peak tip deflection at 7 rad/s (twice the first frequency): linear " << fast_linear << " m, stiffened "
                                                                              << fast_stiff << " m");
  CHECK(fast_stiff < 0.2);
  CHECK(fast_linear > 1.0);  // the run stopped: the linear form ran away
}

TEST_CASE("bad input names its culprit", "[extras][geometric_stiffening]") {
  const auto data = cantilever(3, 2, MassMatrixType::lumped);
  CHECK_THROWS_MENTIONING(StiffenedFfrfBody(data, 7), ModelError, "anchor node 7");
  FeModel ring;
  ring.add_node(Vec2(0, 0));
  ring.add_node(Vec2(1, 0));
  ring.add_node(Vec2(0, 1));
  ring.add_element(0, 1, unit_section());
  ring.add_element(1, 2, unit_section());
  ring.add_element(2, 0, unit_section());
  const FlexibleBodyData ring_data = flexible_body_data(ring, MassMatrixType::lumped, 2);
  CHECK_THROWS_MENTIONING(foreshortening(ring_data, 0), ModelError, "tree");
  const Foreshortening fs = foreshortening(*data, 0);
  CHECK_THROWS_MENTIONING(node_shortening(fs, VecX::Zero(3), VecX::Zero(2)), ModelError, "q_f has size 3");
}
