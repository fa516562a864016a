#pragma once
// The independent kinematics, the models and the checks that the project tests of flexible
// bodies share (flexible.test.cpp, flexible_models.test.cpp).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "fmbd/applied_forces.hpp"
#include "fmbd/constraints.hpp"
#include "fmbd/energy.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_body.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/intuitive_flexible.hpp"
#include "fmbd/gamma.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/mass_matrix.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reduction.hpp"
#include "fmbd/simulation.hpp"
#include "fmbd/statics.hpp"
#include "grading.hpp"


namespace fmbd::flexible_testing {

using fmbd::testing::Random;
using fmbd::testing::Tolerance;
using fmbd::testing::finite_difference_jacobian;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr Tolerance kTight{1e-12, 1e-12};
inline const Section kSteel = square_section(210e9, 7850.0, 0.01);

using DataPtr = std::shared_ptr<const FlexibleBodyData>;

// ---- independent kinematics ------------------------------------------------------------------

inline Mat2 rot(double a) { return (Mat2() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished(); }
inline const Mat2 kTilde = (Mat2() << 0.0, -1.0, 1.0, 0.0).finished();

inline DataPtr beam_data(double length, int elements, MassMatrixType type, int modes, const Section& s = kSteel,
                  const Vec2& start = Vec2::Zero(), double angle = 0.0) {
  return std::make_shared<const FlexibleBodyData>(
      flexible_body_data(straight_beam(length, elements, s, start, angle), type, modes));
}

inline const ModalBodyData& data_of(const Model& m, BodyId b) {
  const auto* body = dynamic_cast<const IntuitiveBody*>(m.body(b).deformable.get());
  if (!body) throw std::logic_error("test: body '" + m.body(b).name + "' is not an IntuitiveBody");
  return body->data();
}

// The data of a flexible body with its beam FE model: every flexible body of these tests is made
// from a FlexibleBodyData (flexible_body_data or the example builders).
inline const FlexibleBodyData& beam_data_of(const Model& m, BodyId b) {
  return static_cast<const FlexibleBodyData&>(data_of(m, b));
}

// Global position and angle of a point: on a rigid body R + A s_bar and phi; at node k of a
// flexible body R + A(theta) (x_k + Phi_f[3k..3k+1] q_f) and theta + Phi_f[3k+2] q_f, with x_k the
// centred FE node; on the ground s_bar and 0.
struct Pose {
  Vec2 r;
  double phi;
};
inline Pose point_pose(const Model& m, PointId P, const VecX& q) {
  const Point& p = m.point(P);
  if (p.body.is_ground()) return {p.s_bar, 0.0};
  const int at = m.offset(p.body);
  const Vec2 R = q.segment<2>(at);
  const double theta = q(at + 2);
  if (p.node < 0) return {R + rot(theta) * p.s_bar, theta};
  const FlexibleBodyData& d = beam_data_of(m, p.body);
  const VecX q_f = q.segment(at + 3, d.Phi_f.cols());
  const Vec2 x = d.fe.nodes()[p.node];
  const Vec2 u = d.Phi_f.middleRows(3 * p.node, 2) * q_f;
  return {R + rot(theta) * (x + u), theta + d.Phi_f.row(3 * p.node + 2).dot(q_f)};
}
inline double frame_angle(const Model& m, BodyId b, const VecX& q) { return b.is_ground() ? 0.0 : q(m.offset(b) + 2); }

// dr_P/dq (2 x n) by central differences of point_pose.
inline MatX position_jacobian(const Model& m, PointId P, const VecX& q) {
  return finite_difference_jacobian([&](const VecX& x) { return VecX(point_pose(m, P, x).r); }, q);
}

// C from the definitions in model.hpp, evaluated on the poses above.
inline VecX constraint_oracle(const Model& m, const VecX& q, double t) {
  VecX C(m.num_constraints());
  for (const Constraint& c : m.constraints()) {
    const VecX rows = std::visit(
        [&](const auto& k) -> VecX {
          using T = std::decay_t<decltype(k)>;
          if constexpr (std::is_same_v<T, Revolute>) {
            return point_pose(m, k.P_i, q).r - point_pose(m, k.P_j, q).r;
          } else if constexpr (std::is_same_v<T, Translational>) {
            const Pose i = point_pose(m, k.P_i, q), j = point_pose(m, k.P_j, q);
            const Vec2 n = rot(i.phi) * kTilde * k.axis_i;
            return Vec2(n.dot(j.r - i.r), j.phi - i.phi - k.phi0);
          } else if constexpr (std::is_same_v<T, Fixed>) {
            const Pose i = point_pose(m, k.P_i, q), j = point_pose(m, k.P_j, q);
            const Vec2 d = i.r - j.r;
            return Vec3(d.x(), d.y(), j.phi - i.phi - k.phi0);
          } else if constexpr (std::is_same_v<T, AbsoluteAngleDriver>) {
            return VecX::Constant(1, frame_angle(m, k.body, q) - k.f(t).f);
          } else if constexpr (std::is_same_v<T, RelativeAngleDriver>) {
            return VecX::Constant(1, frame_angle(m, k.body_j, q) - frame_angle(m, k.body_i, q) - k.f(t).f);
          } else if constexpr (std::is_same_v<T, PointCoordinateDriver>) {
            return VecX::Constant(1, point_pose(m, k.P, q).r(static_cast<int>(k.axis)) - k.f(t).f);
          } else {
            const Vec2 d = point_pose(m, k.P_j, q).r - point_pose(m, k.P_i, q).r;
            const double f = k.f(t).f;
            return VecX::Constant(1, 0.5 * (d.squaredNorm() - f * f));
          }
        },
        c.type);
    C.segment(c.first_row, c.rows) = rows;
  }
  return C;
}

// Fourth-order central second derivative of g at t.
inline VecX second_derivative(const std::function<VecX(double)>& g, double t, double h = 2.5e-4) {
  return (-g(t + 2 * h) + 16 * g(t + h) - 30 * g(t) + 16 * g(t - h) - g(t - 2 * h)) / (12 * h * h);
}
inline VecX first_derivative(const std::function<VecX(double)>& g, double t, double h = 1e-4) {
  return (-g(t + 2 * h) + 8 * g(t + h) - 8 * g(t - h) + g(t - 2 * h)) / (12 * h);
}

// A state near the initial guess: frames moved by up to `spread`, elastic coordinates up to `q_f`.
inline VecX random_state(const Model& m, Random& rnd, double spread, double q_f) {
  VecX q = m.initial_guess();
  for (int b = 0; b < m.num_bodies(); ++b) {
    const int at = m.offset(BodyId{b}), n = m.bodies()[b].num_coordinates();
    q.segment<3>(at) += rnd.vector(3, -spread, spread);
    if (n > 3 && q_f > 0) q.segment(at + 3, n - 3) = rnd.vector(n - 3, -q_f, q_f);
  }
  return q;
}

// The three checks of the assembly on one model: C against the definitions, C_q and C_t against
// central differences of C, gamma against the second time derivative of C along
// q(t) = q0 + v (t - t0) + a (t - t0)^2 / 2.
inline void check_assembly(const Model& m, const VecX& q0, const VecX& v, const VecX& a, double t0) {
  INFO("C at the node poses");
  CHECK_CLOSE(constraints(m, q0, t0), constraint_oracle(m, q0, t0), (Tolerance{1e-12, 1e-12}),
              "C is not the definition of model.hpp at the poses of the nodes");
  const ConstraintEvaluation e = evaluate_constraints(m, q0, t0);
  const MatX Cq_fd = finite_difference_jacobian([&](const VecX& x) { return constraints(m, x, t0); }, q0);
  CHECK_CLOSE(e.Cq, Cq_fd, (Tolerance{1e-7, 1e-7}), "C_q is not dC/dq (marker chain rule B G)");
  const VecX Ct_fd = first_derivative([&](double t) { return constraints(m, q0, t); }, t0);
  CHECK_CLOSE(e.Ct, Ct_fd, (Tolerance{1e-8, 1e-8}), "C_t is not dC/dt");

  auto C_along = [&](double t) {
    const double s = t - t0;
    return constraints(m, VecX(q0 + v * s + 0.5 * a * s * s), t);
  };
  const VecX expected = e.Cq * a - second_derivative(C_along, t0);
  CHECK_CLOSE(constraint_gamma(m, q0, v, t0), expected, (Tolerance{1e-6, 1e-7}),
              "gamma is not C_q q_ddot - d2C/dt2 (the marker's convective term?)");
}

// ---- models ------------------------------------------------------------------------------------

// Rigid "A", flexible "rod" (6 elements), rigid "B", flexible "bar" (3 elements), joined by every
// joint and driver type with points at nodes, on both sides of a joint.
struct Mixed {
  Model m;
  BodyId A, rod, B, bar;
  DataPtr rod_data, bar_data;
  Mixed(const BodyFactory& make_body, MassMatrixType type) {
    rod_data = beam_data(1.0, 6, type, 4);
    bar_data = beam_data(0.5, 3, type, 3, kSteel, Vec2(0.2, 0.1), 0.4);
    A = m.add_body("A", 2.0, 0.3, Vec3(0.1, 0.2, 0.3));
    rod = m.add_flexible_body("rod", make_body(rod_data), Vec3(0.8, 0.1, 0.2));
    B = m.add_body("B", 1.5, 0.2, Vec3(1.6, 0.3, -0.1));
    bar = m.add_flexible_body("bar", make_body(bar_data), Vec3(1.2, -0.4, 1.1));
    const PointId O = m.add_point(ground, Vec2(0.0, 0.0), "O");
    const PointId O2 = m.add_point(ground, Vec2(2.0, -1.0), "O2");
    const PointId a0 = m.add_point(A, Vec2(-0.2, 0.05), "A hub");
    const PointId a1 = m.add_point(A, Vec2(0.25, -0.1), "A tip");
    const PointId b0 = m.add_point(B, Vec2(0.1, 0.2), "B pin");
    const PointId b1 = m.add_point(B, Vec2(-0.3, 0.0), "B guide");
    const PointId b2 = m.add_point(B, Vec2(0.0, -0.15), "B hook");
    std::vector<PointId> r;
    for (int k = 0; k <= 6; ++k) r.push_back(m.add_node_point(rod, k, "rod " + std::to_string(k)));
    std::vector<PointId> s;
    for (int k = 0; k <= 3; ++k) s.push_back(m.add_node_point(bar, k, "bar " + std::to_string(k)));
    m.add_revolute("hinge", O, a0);
    m.add_fixed("weld", a1, r[0], 0.2);
    m.add_translational("slide", r[6], b0, Vec2(0.6, 0.8), 0.1);
    m.add_translational("guide", b1, r[4], Vec2(1.0, 0.0), -0.3);
    m.add_revolute("elbow", r[1], s[0]);
    m.add_fixed("clamp", s[3], O2, 0.5);
    m.add_distance_driver("reach", r[2], b2, DriveFunction::harmonic(0.6, 0.1, 3.0, 0.2));
    m.add_distance_driver("span", r[5], s[2], DriveFunction::polynomial({0.3, 0.2, -0.4}));
    m.add_point_coordinate_driver("lift", r[3], Axis::y, DriveFunction::harmonic(0.1, 0.05, 2.0));
    m.add_point_coordinate_driver("shift", s[1], Axis::x, DriveFunction::polynomial({1.0, 0.5, 0.25}));
    m.add_relative_angle_driver("bend", A, rod, DriveFunction::harmonic(0.0, 0.3, 1.5));
    m.add_absolute_angle_driver("tilt", bar, DriveFunction::polynomial({1.0, -0.2, 0.3}));
  }
};

inline void check_mixed_assembly(const BodyFactory& make_body, MassMatrixType type, unsigned seed) {
  Mixed x(make_body, type);
  Random rnd(seed);
  const int n = x.m.num_coordinates();
  REQUIRE(n == 3 + 7 + 3 + 6);
  REQUIRE(x.m.num_constraints() == 2 + 3 + 2 + 2 + 2 + 3 + 1 + 1 + 1 + 1 + 1 + 1);
  for (int trial = 0; trial < 3; ++trial) {
    CAPTURE(trial);
    const VecX q = random_state(x.m, rnd, 0.3, 0.03);
    check_assembly(x.m, q, rnd.vector(n, -2.0, 2.0), rnd.vector(n, -3.0, 3.0), rnd.uniform(0.0, 2.0));
  }
}

// The slider-crank of module 7 at a random state (not consistent: the checks hold anywhere).
inline void check_slider_crank_assembly(const BodyFactory& make_body, unsigned seed) {
  FlexibleSliderCrankParameters p;
  p.elements = 6;
  const FlexibleExample ex = flexible_slider_crank(p, make_body);
  Random rnd(seed);
  const int n = ex.model.num_coordinates();
  const VecX q = random_state(ex.model, rnd, 0.05, 1e-3);
  check_assembly(ex.model, q, rnd.vector(n, -5.0, 5.0), rnd.vector(n, -50.0, 50.0), rnd.uniform(0.0, 0.1));
}

// Q of the force elements alone by virtual work: a force F at P does F^T dr_P, so Q = J_P^T F with
// J_P from finite differences of the point's position; torques and rotational springs act on the
// frame angles. Gravity must be zero.
inline VecX forces_by_virtual_work(const Model& m, const VecX& q, const VecX& qd, double t) {
  VecX Q = VecX::Zero(m.num_coordinates());
  for (const Force& force : m.forces()) {
    std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, PointForce>) {
            const Vec2 F = e.frame == Frame::global ? e.F : Vec2(rot(point_pose(m, e.P, q).phi) * e.F);
            Q += position_jacobian(m, e.P, q).transpose() * F;
          } else if constexpr (std::is_same_v<T, Torque>) {
            Q(m.offset(e.body) + 2) += e.T(t).f;
          } else if constexpr (std::is_same_v<T, Tsda>) {
            const MatX Ji = position_jacobian(m, e.P_i, q), Jj = position_jacobian(m, e.P_j, q);
            const Vec2 d = point_pose(m, e.P_j, q).r - point_pose(m, e.P_i, q).r;
            const Vec2 u = d / d.norm();
            const double L_dot = u.dot(Jj * qd - Ji * qd);
            const double f = e.k * (d.norm() - e.L0) + e.c * L_dot + e.actuator(t).f;
            Q += Ji.transpose() * (f * u) - Jj.transpose() * (f * u);
          } else {
            const double theta = frame_angle(m, e.body_j, q) - frame_angle(m, e.body_i, q);
            const double theta_dot = frame_angle(m, e.body_j, qd) - frame_angle(m, e.body_i, qd);
            const double T = e.k * (theta - e.theta0) + e.c * theta_dot + e.actuator(t).f;
            if (!e.body_i.is_ground()) Q(m.offset(e.body_i) + 2) += T;
            if (!e.body_j.is_ground()) Q(m.offset(e.body_j) + 2) -= T;
          }
        },
        force.element);
  }
  return Q;
}

// The flexible bodies' own forces (elastic, quadratic velocity), to take out of applied_forces.
inline VecX own_body_forces(const Model& m, const VecX& q, const VecX& qd) {
  VecX Q = VecX::Zero(m.num_coordinates());
  for (int b = 0; b < m.num_bodies(); ++b) {
    const Body& body = m.bodies()[b];
    if (!body.is_flexible()) continue;
    body.deformable->add_forces(q, qd, m.gravity(), m.offset(BodyId{b}), Q);
  }
  return Q;
}

// A basis whose elastic columns are not M-orthogonal to the rigid modes (S_f != 0): an axial
// stretch u_x = x and a parabolic bend u_y = x^2 (psi = 2x), with any rigid columns in front.
inline DataPtr skewed_beam_data(MassMatrixType type) {
  const FeModel fe = straight_beam(1.0, 5, kSteel);
  const int n = fe.num_dofs();
  ReducedBasis b;
  b.num_rigid = 3;
  b.Phi = MatX::Zero(n, 5);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const double x = fe.nodes()[k].x(), y = fe.nodes()[k].y();
    b.Phi(3 * k, 0) = 1.0;
    b.Phi(3 * k + 1, 1) = 1.0;
    b.Phi.block<3, 1>(3 * k, 2) << -y, x, 1.0;
    b.Phi(3 * k, 3) = x;
    b.Phi(3 * k + 1, 4) = x * x;
    b.Phi(3 * k + 2, 4) = 2 * x;
  }
  return std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, b));
}

// Only conservative elements: gravity, global point forces, springs (no damping, no actuator),
// a rotational spring, the elastic forces.
inline Model conservative_model(const BodyFactory& make_body, const DataPtr& data) {
  Model m;
  m.set_gravity(Vec2(0.7, -9.81));
  const BodyId A = m.add_body("A", 2.0, 0.3, Vec3(-0.4, 0.2, 0.3));
  const BodyId rod = m.add_flexible_body("rod", make_body(data), Vec3(0.5, 0.1, 0.2));
  const BodyId B = m.add_body("B", 1.5, 0.2, Vec3(1.4, 0.3, -0.1));
  const int last = data->fe.num_nodes() - 1;
  const PointId r0 = m.add_node_point(rod, 0, "rod start"), r1 = m.add_node_point(rod, 1, "rod 1");
  const PointId r2 = m.add_node_point(rod, 2, "rod 2"), rl = m.add_node_point(rod, last, "rod end");
  const PointId a = m.add_point(A, Vec2(0.2, 0.1), "A tip"), b = m.add_point(B, Vec2(-0.1, 0.1), "B hook");
  m.add_revolute("pin", a, r0);
  m.add_point_force("load", r2, Vec2(3.0, -2.0));
  m.add_point_force("rigid load", b, Vec2(-1.0, 0.5));
  m.add_tsda("coil", a, r1, 40.0, 0.2, 0.0);
  m.add_tsda("cord", rl, b, 25.0, 0.1, 0.0);
  m.add_rsda("twist", ground, rod, 6.0, 0.3, 0.0);
  m.add_rsda("knee", A, B, 3.0, -0.2, 0.0);
  return m;
}

inline void check_potential_gradient(const BodyFactory& make_body, const DataPtr& data, unsigned seed) {
  const Model m = conservative_model(make_body, data);
  Random rnd(seed);
  const VecX zero = VecX::Zero(m.num_coordinates());
  for (int trial = 0; trial < 3; ++trial) {
    CAPTURE(trial);
    const VecX q = random_state(m, rnd, 0.5, 0.01);
    const MatX dV = finite_difference_jacobian([&](const VecX& x) { return VecX::Constant(1, potential_energy(m, x)); }, q);
    CHECK_CLOSE(applied_forces(m, q, zero, 0.3), VecX(-dV.row(0).transpose()), (Tolerance{1e-5, 1e-7}),
                "Q_a at rest is not -dV/dq for conservative forces");
  }
}

// The FE kinetic energy 1/2 w^T M_FE w of a flexible body, w the absolute nodal velocities in
// frame j (A^T r_k_dot, phi_k_dot), from finite differences of the node poses in time.
inline double fe_kinetic_energy(const Model& m, BodyId body, const VecX& q, const VecX& qd) {
  const FlexibleBodyData& d = beam_data_of(m, body);
  const int N = d.fe.num_nodes();
  const Mat2 At = rot(q(m.offset(body) + 2)).transpose();
  // Poses of the nodes along q + qd s, through node points added to a copy of the model.
  Model probe = m;
  std::vector<PointId> nodes;
  for (int k = 0; k < N; ++k) nodes.push_back(probe.add_node_point(body, k, "probe node " + std::to_string(k)));
  VecX w(3 * N);
  for (int k = 0; k < N; ++k) {
    const VecX rate = first_derivative(
        [&](double s) {
          const Pose p = point_pose(probe, nodes[k], VecX(q + qd * s));
          return VecX(Vec3(p.r.x(), p.r.y(), p.phi));
        },
        0.0);
    w.segment<2>(3 * k) = At * rate.head<2>();
    w(3 * k + 2) = rate(2);
  }
  return 0.5 * w.dot(d.matrices.M * w);
}

}  // namespace fmbd::flexible_testing
