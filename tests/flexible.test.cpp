// Project tests (not graded) of the given code for flexible bodies (modules 1 to 4 through the
// DeformableBody plug-in, modules 7 and 8): the model's coordinate bookkeeping with rigid and
// flexible bodies mixed, the node markers and the assembly of C, C_q, C_t, gamma, Q_a, the
// energies and the mass matrices through them, flexible_body_data and frame_for_placement, the
// example builders and spin_up_profile, static_equilibrium, and simulate on a flexible model.
//
// The oracles are independent of the marker code: node positions are computed here from the
// centred FE nodes and the rows of Phi_f, derivatives by finite differences, forces by virtual
// work, masses and inertias in closed form. The given code calls exercise functions (node_pose,
// the FFRF mass matrix, the integrators, ...), so this program links the reference stages.
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

using namespace fmbd;
using fmbd::testing::Random;
using fmbd::testing::Tolerance;
using fmbd::testing::finite_difference_jacobian;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr Tolerance kTight{1e-12, 1e-12};
const Section kSteel = square_section(210e9, 7850.0, 0.01);

using DataPtr = std::shared_ptr<const FlexibleBodyData>;

// ---- independent kinematics ------------------------------------------------------------------

Mat2 rot(double a) { return (Mat2() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished(); }
const Mat2 kTilde = (Mat2() << 0.0, -1.0, 1.0, 0.0).finished();

DataPtr beam_data(double length, int elements, MassMatrixType type, int modes, const Section& s = kSteel,
                  const Vec2& start = Vec2::Zero(), double angle = 0.0) {
  return std::make_shared<const FlexibleBodyData>(
      flexible_body_data(straight_beam(length, elements, s, start, angle), type, modes));
}

const ModalBodyData& data_of(const Model& m, BodyId b) {
  const auto* body = dynamic_cast<const IntuitiveBody*>(m.body(b).deformable.get());
  if (!body) throw std::logic_error("test: body '" + m.body(b).name + "' is not an IntuitiveBody");
  return body->data();
}

// The data of a flexible body with its beam FE model: every flexible body of these tests is made
// from a FlexibleBodyData (flexible_body_data or the example builders).
const FlexibleBodyData& beam_data_of(const Model& m, BodyId b) {
  return static_cast<const FlexibleBodyData&>(data_of(m, b));
}

// Global position and angle of a point: on a rigid body R + A s_bar and phi; at node k of a
// flexible body R + A(theta) (x_k + Phi_f[3k..3k+1] q_f) and theta + Phi_f[3k+2] q_f, with x_k the
// centred FE node; on the ground s_bar and 0.
struct Pose {
  Vec2 r;
  double phi;
};
Pose point_pose(const Model& m, PointId P, const VecX& q) {
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
double frame_angle(const Model& m, BodyId b, const VecX& q) { return b.is_ground() ? 0.0 : q(m.offset(b) + 2); }

// dr_P/dq (2 x n) by central differences of point_pose.
MatX position_jacobian(const Model& m, PointId P, const VecX& q) {
  return finite_difference_jacobian([&](const VecX& x) { return VecX(point_pose(m, P, x).r); }, q);
}

// C from the definitions in model.hpp, evaluated on the poses above.
VecX constraint_oracle(const Model& m, const VecX& q, double t) {
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
VecX second_derivative(const std::function<VecX(double)>& g, double t, double h = 2.5e-4) {
  return (-g(t + 2 * h) + 16 * g(t + h) - 30 * g(t) + 16 * g(t - h) - g(t - 2 * h)) / (12 * h * h);
}
VecX first_derivative(const std::function<VecX(double)>& g, double t, double h = 1e-4) {
  return (-g(t + 2 * h) + 8 * g(t + h) - 8 * g(t - h) + g(t - 2 * h)) / (12 * h);
}

// A state near the initial guess: frames moved by up to `spread`, elastic coordinates up to `q_f`.
VecX random_state(const Model& m, Random& rnd, double spread, double q_f) {
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
void check_assembly(const Model& m, const VecX& q0, const VecX& v, const VecX& a, double t0) {
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

void check_mixed_assembly(const BodyFactory& make_body, MassMatrixType type, unsigned seed) {
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
void check_slider_crank_assembly(const BodyFactory& make_body, unsigned seed) {
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
VecX forces_by_virtual_work(const Model& m, const VecX& q, const VecX& qd, double t) {
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
VecX own_body_forces(const Model& m, const VecX& q, const VecX& qd) {
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
DataPtr skewed_beam_data(MassMatrixType type) {
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
Model conservative_model(const BodyFactory& make_body, const DataPtr& data) {
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

void check_potential_gradient(const BodyFactory& make_body, const DataPtr& data, unsigned seed) {
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
double fe_kinetic_energy(const Model& m, BodyId body, const VecX& q, const VecX& qd) {
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

}  // namespace

// ---- the model ---------------------------------------------------------------------------------

TEST_CASE("flexible model: offsets, sizes, initial guess and body states with bodies in any order", "[flexible]") {
  const DataPtr two = beam_data(1.0, 3, MassMatrixType::lumped, 2);
  const DataPtr three = beam_data(0.6, 4, MassMatrixType::consistent, 3);
  Model m;
  const BodyId x = m.add_flexible_body("x", make_intuitive_body(two), Vec3(1, 2, 3));
  const BodyId a = m.add_body("a", 1.0, 0.1, Vec3(4, 5, 6));
  const BodyId rod = m.add_flexible_body("rod", make_ffrf_body(three), Vec3(7, 8, 9));
  const BodyId y = m.add_flexible_body("y", make_intuitive_body(two), Vec3(10, 11, 12));
  const BodyId b = m.add_body("b", 2.0, 0.2, Vec3(13, 14, 15));
  REQUIRE(m.num_bodies() == 5);
  CHECK(m.offset(x) == 0);
  CHECK(m.offset(a) == 5);
  CHECK(m.offset(rod) == 8);
  CHECK(m.offset(y) == 14);
  CHECK(m.offset(b) == 19);
  CHECK(m.num_coordinates() == 22);
  CHECK(m.body(rod).num_coordinates() == 6);
  CHECK(m.body(a).num_coordinates() == 3);
  CHECK(m.body(rod).is_flexible());
  CHECK_FALSE(m.body(b).is_flexible());
  // Mass and inertia of a flexible body come from its data.
  CHECK(m.body(rod).mass == three->mass);
  CHECK(m.body(rod).inertia == three->inertia);

  VecX q0(22);
  q0 << 1, 2, 3, 0, 0, 4, 5, 6, 7, 8, 9, 0, 0, 0, 10, 11, 12, 0, 0, 13, 14, 15;
  CHECK_CLOSE(m.initial_guess(), q0, kTight, "frame q0 at each offset, elastic coordinates zero");

  VecX q(22);
  for (int k = 0; k < 22; ++k) q(k) = 100 + k;
  CHECK_CLOSE(m.body_state(q, rod), (VecX(6) << 108, 109, 110, 111, 112, 113).finished(), kTight, "body_state");
  CHECK_CLOSE(m.body_state(q, b), Vec3(119, 120, 121), kTight, "body_state of a rigid body");
  CHECK_CLOSE(m.body_coordinates(q, y), Vec3(114, 115, 116), kTight, "body_coordinates: the frame");
  CHECK_CLOSE(m.body_coordinates(q, ground), Vec3::Zero(), kTight, "the ground");
  CHECK_THROWS_AS(m.body_state(VecX::Zero(21), rod), std::invalid_argument);
  CHECK_THROWS_AS(m.body_coordinates(VecX::Zero(23), rod), std::invalid_argument);
  CHECK_THROWS_AS(m.body_state(q, ground), std::invalid_argument);

  CHECK(m.describe_coordinate(0) == "x of body 'x'");
  CHECK(m.describe_coordinate(3) == "q_f 1 of body 'x'");
  CHECK(m.describe_coordinate(4) == "q_f 2 of body 'x'");
  CHECK(m.describe_coordinate(7) == "phi of body 'a'");
  CHECK(m.describe_coordinate(10) == "phi of body 'rod'");
  CHECK(m.describe_coordinate(12) == "q_f 2 of body 'rod'");
  CHECK(m.describe_coordinate(13) == "q_f 3 of body 'rod'");
  CHECK(m.describe_coordinate(14) == "x of body 'y'");
  CHECK(m.describe_coordinate(21) == "phi of body 'b'");
  CHECK(m.describe_coordinate(22) == "coordinate 22 (out of range)");
}

TEST_CASE("flexible model: points on flexible bodies sit at nodes, and the builder says why it refuses", "[flexible]") {
  const DataPtr data = beam_data(1.0, 3, MassMatrixType::lumped, 2);
  Model m;
  const BodyId a = m.add_body("crank", 1.0, 0.1);
  const BodyId rod = m.add_flexible_body("rod", make_intuitive_body(data));
  const PointId end = m.add_node_point(rod, 3, "rod end");
  CHECK(m.point(end).node == 3);
  CHECK(m.point(end).body == rod);
  CHECK_CLOSE(m.point(end).s_bar, Vec2(0.5, 0.0), kTight, "a node point's s_bar is the centred node position");
  CHECK(m.point(m.add_point(a, Vec2(0.1, 0), "crank tip")).node == -1);

  CHECK_THROWS_MENTIONING(m.add_point(rod, Vec2(0.1, 0.0), "loose"), ModelError,
                          "point 'loose': body 'rod' is flexible; attach points to its FE nodes with add_node_point");
  CHECK_THROWS_MENTIONING(m.add_node_point(a, 0, "bad"), ModelError,
                          "point 'bad': body 'crank' is not flexible; use add_point");
  CHECK_THROWS_MENTIONING(m.add_node_point(ground, 0, "bad"), ModelError, "body 'ground' is not flexible");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, 4, "bad"), ModelError, "body 'rod' has no node 4 (nodes 0 .. 3)");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, -1, "bad"), ModelError, "has no node -1");
  CHECK_THROWS_MENTIONING(m.add_node_point(BodyId{7}, 0, "bad"), ModelError, "body 7 does not exist");
  CHECK_THROWS_MENTIONING(m.add_node_point(rod, 0, "rod end"), ModelError, "duplicate point name 'rod end'");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("empty", nullptr), ModelError,
                          "flexible body 'empty': no deformable part given");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("rod", make_intuitive_body(data)), ModelError,
                          "duplicate body name 'rod'");
  CHECK_THROWS_MENTIONING(m.add_flexible_body("nan", make_intuitive_body(data), Vec3(0, std::nan(""), 0)),
                          ModelError, "initial guess q0 is not finite");
  // Nothing was added by the refused calls.
  CHECK(m.num_bodies() == 2);
  CHECK(m.points().size() == 2);
  CHECK(m.num_coordinates() == 3 + 5);
}

// ---- markers -------------------------------------------------------------------------------

TEST_CASE("markers: a node marker is the node's pose, G its Jacobian and c its convective acceleration", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Mixed x(make_body, MassMatrixType::consistent);
    Random rnd(11);
    const int n = x.m.num_coordinates();
    const VecX q = random_state(x.m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2, 2), qdd = rnd.vector(n, -3, 3);
    const PointId P = x.m.find_point("rod 4");
    const Marker mk = point_marker(x.m, P, q, qd);
    const MatX G = mk.node_kinematics().G;  // the node's kept marker: the finite differences below replace it
    const int at = x.m.offset(x.rod), nb = 3 + 4;
    CHECK(mk.body == x.rod);
    CHECK(mk.offset == at);
    CHECK_CLOSE(mk.s_bar, Vec2::Zero(), kTight, "a node is a point at s_bar = 0 of its marker");
    auto pose = [&](const VecX& qq) {
      const Pose p = point_pose(x.m, P, qq);
      return VecX(Vec3(p.r.x(), p.r.y(), p.phi));
    };
    CHECK_CLOSE(mk.q, pose(q), kTight, "the marker's q is the node pose");
    const MatX G_fd = finite_difference_jacobian(pose, q).middleCols(at, nb);
    CHECK_CLOSE(G, G_fd, (Tolerance{1e-8, 1e-8}), "G = dp/dq_body");
    CHECK_CLOSE(mk.qd, VecX(G_fd * qd.segment(at, nb)), (Tolerance{1e-8, 1e-8}), "qd = G q_body_dot");
    const VecX pdd =
        second_derivative([&](double t) { return pose(VecX(q + qd * t + 0.5 * qdd * t * t)); }, 0.0);
    CHECK_CLOSE(mk.convective, VecX(pdd - G_fd * qdd.segment(at, nb)), (Tolerance{1e-6, 1e-6}),
                "c = p_ddot - G q_ddot");

    const Marker frame = body_marker(x.m, x.rod, q, qd);
    CHECK_CLOSE(frame.q, VecX(q.segment<3>(at)), kTight, "a body marker of a flexible body is its frame");
    CHECK_FALSE(frame.on_node());  // its block takes the frame's 3 columns: G = [I 0], implied
    CHECK(frame.kinematics == nullptr);
    CHECK_CLOSE(frame.convective, Vec3::Zero(), kTight, "frame marker: no convective term");

    const Marker g = point_marker(x.m, x.m.find_point("O2"), q, qd);
    CHECK(g.body.is_ground());
    CHECK_CLOSE(g.s_bar, Vec2(2.0, -1.0), kTight, "a ground point's s_bar is its global position");

    VecX target = VecX::Zero(n);
    add_generalised_force(target, mk, Vec3(1.0, -2.0, 0.5));
    VecX expected = VecX::Zero(n);
    expected.segment(at, nb) = G_fd.transpose() * Vec3(1.0, -2.0, 0.5);
    CHECK_CLOSE(target, expected, (Tolerance{1e-8, 1e-8}), "G^T Q in the columns of the body");
    add_generalised_force(target, g, Vec3(5.0, 5.0, 5.0));
    CHECK_CLOSE(target, expected, (Tolerance{1e-8, 1e-8}), "nothing on the ground");
  }
}

// ---- assembly of C, C_q, C_t and gamma ----------------------------------------------------

TEST_CASE("assembly on a mixed model (intuitive bodies): C, C_q, C_t and gamma through node markers", "[flexible]") {
  check_mixed_assembly(make_intuitive_body, MassMatrixType::consistent, 21);
  check_mixed_assembly(make_intuitive_body, MassMatrixType::lumped, 22);
}

TEST_CASE("assembly on a mixed model (FFRF bodies): C, C_q, C_t and gamma through node markers", "[flexible]") {
  check_mixed_assembly(make_ffrf_body, MassMatrixType::consistent, 23);
  check_mixed_assembly(make_ffrf_body, MassMatrixType::lumped, 24);
}

TEST_CASE("assembly on the flexible slider-crank: C, C_q, C_t and gamma for both formulations", "[flexible]") {
  check_slider_crank_assembly(make_intuitive_body, 31);
  check_slider_crank_assembly(make_ffrf_body, 32);
}

// ---- applied forces and energies --------------------------------------------------------------

TEST_CASE("applied_forces: point forces, torques and spring-dampers at nodes do their virtual work", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Mixed x(make_body, MassMatrixType::consistent);
    Model& m = x.m;
    m.add_point_force("push", m.find_point("rod 2"), Vec2(3.0, -2.0));
    m.add_point_force("follower", m.find_point("rod 5"), Vec2(1.0, 4.0), Frame::body);
    m.add_point_force("bar follower", m.find_point("bar 3"), Vec2(-2.0, 0.5), Frame::body);
    m.add_point_force("rigid follower", m.find_point("B pin"), Vec2(0.5, 1.0), Frame::body);
    m.add_tsda("coil", m.find_point("A tip"), m.find_point("rod 4"), 50.0, 0.3, 2.0,
               DriveFunction::harmonic(0.5, 1.0, 2.0));
    m.add_tsda("link", m.find_point("rod 6"), m.find_point("bar 1"), 20.0, 0.1, 1.5);
    m.add_tsda("tether", m.find_point("O"), m.find_point("bar 2"), 10.0, 0.5, 0.7);
    m.add_rsda("twist", x.A, x.rod, 5.0, 0.1, 0.5, DriveFunction::constant(0.2));
    m.add_rsda("root", ground, x.bar, 3.0, -0.2, 0.4);
    m.add_torque("motor", x.bar, DriveFunction::linear(1.0, 2.0));
    Random rnd(41);
    const int n = m.num_coordinates();
    for (int trial = 0; trial < 3; ++trial) {
      CAPTURE(trial);
      const VecX q = random_state(m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2.0, 2.0);
      const double t = rnd.uniform(0.0, 1.0);
      const VecX Q = applied_forces(m, q, qd, t) - own_body_forces(m, q, qd);
      CHECK_CLOSE(Q, forces_by_virtual_work(m, q, qd, t), (Tolerance{1e-7, 1e-7}),
                  "a force element on a node must act through G^T (virtual work of the physical force)");
    }
  }
}

TEST_CASE("potential_energy: its gradient is -Q_a at rest for conservative forces on flexible bodies", "[flexible]") {
  // Exact for both bodies with either mass matrix: module 8 keeps module 7's gravity, the exact
  // gradient of -g^T (m R + A S_f q_f) (the FE load L^T M_FE g^j is not, with a consistent M_FE).
  const DataPtr lumped = beam_data(1.0, 6, MassMatrixType::lumped, 4);
  const DataPtr consistent = beam_data(1.0, 6, MassMatrixType::consistent, 4);
  const DataPtr skewed_lumped = skewed_beam_data(MassMatrixType::lumped);
  const DataPtr skewed_consistent = skewed_beam_data(MassMatrixType::consistent);
  REQUIRE(skewed_lumped->S_f.norm() > 0.01);  // gravity couples to q_f in these
  REQUIRE(skewed_consistent->S_f.norm() > 0.01);
  SECTION("intuitive") {
    check_potential_gradient(make_intuitive_body, lumped, 51);
    check_potential_gradient(make_intuitive_body, consistent, 52);
    // The intuitive form refuses a basis with S_f != 0, and says what to use instead.
    for (const DataPtr& skewed : {skewed_lumped, skewed_consistent})
      CHECK_THROWS_MENTIONING(make_intuitive_body(skewed), IntuitiveBasisError, "M-orthogonal");
    CHECK_THROWS_MENTIONING(make_intuitive_body(skewed_lumped), IntuitiveBasisError, "make_ffrf_body");
  }
  SECTION("FFRF: gravity is module 7's, for any basis and either mass matrix") {
    check_potential_gradient(make_ffrf_body, lumped, 55);
    check_potential_gradient(make_ffrf_body, skewed_lumped, 56);
    check_potential_gradient(make_ffrf_body, consistent, 53);
    check_potential_gradient(make_ffrf_body, skewed_consistent, 54);
  }
}

TEST_CASE("potential_energy of a flexible body with lumped mass: gravity on the nodal masses and strain energy", "[flexible]") {
  for (const DataPtr& data : {beam_data(1.0, 6, MassMatrixType::lumped, 4), skewed_beam_data(MassMatrixType::lumped)}) {
    Model m;
    const Vec2 g(0.7, -9.81);
    m.set_gravity(g);
    const BodyId rod = m.add_flexible_body("rod", make_ffrf_body(data), Vec3(0.5, 0.1, 0.2));
    Random rnd(57);
    const VecX q = random_state(m, rnd, 0.5, 0.01);
    // -g^T sum_k m_k r_k over the lumped nodal masses, plus 1/2 u^T K_FE u with u = Phi_f q_f.
    double V = 0;
    for (int k = 0; k < data->fe.num_nodes(); ++k) {
      const PointId P = m.add_node_point(rod, k, "n" + std::to_string(k));
      V -= data->matrices.M.coeff(3 * k, 3 * k) * g.dot(point_pose(m, P, q).r);
    }
    const VecX u = data->Phi_f * q.tail(data->num_modes());
    V += 0.5 * u.dot(data->matrices.K * u);
    CHECK_NEAR(potential_energy(m, q), V, (Tolerance{1e-10, 1e-10}), "V of a flexible body");
  }
}

TEST_CASE("mass matrices and kinetic energies: constant for intuitive bodies, M(q) for FFRF bodies", "[flexible]") {
  Random rnd(61);
  SECTION("intuitive") {
    Mixed x(make_intuitive_body, MassMatrixType::consistent);
    const int n = x.m.num_coordinates();
    const VecX q = random_state(x.m, rnd, 0.3, 0.03), qd = rnd.vector(n, -2, 2);
    const MatX M = mass_matrix(x.m, VecX::Zero(n));
    CHECK_CLOSE(mass_matrix(x.m, q), M, kTight, "the intuitive M_bar does not depend on q");
    const int at = x.m.offset(x.rod);
    CHECK_CLOSE(MatX(M.block(at, at, 7, 7)), x.rod_data->basis.M_bar, kTight, "the body's block is M_bar");
    CHECK_CLOSE(Vec3(M.diagonal().segment<3>(x.m.offset(x.B))), Vec3(1.5, 1.5, 0.2), kTight, "rigid block");
    CHECK_THROWS_MENTIONING(mass_matrix(x.m), std::invalid_argument, "mass_matrix(model, q)");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), 0.5 * qd.dot(M * qd), kTight, "T = 1/2 qd^T M qd");
    CHECK_THROWS_MENTIONING(kinetic_energy(x.m, qd), std::invalid_argument, "kinetic_energy(model, q, q_dot)");
  }
  SECTION("FFRF") {
    Mixed x(make_ffrf_body, MassMatrixType::consistent);
    const int n = x.m.num_coordinates();
    VecX q = random_state(x.m, rnd, 0.3, 0.0);
    const VecX qd = rnd.vector(n, -2, 2);
    Mixed intuitive(make_intuitive_body, MassMatrixType::consistent);
    const MatX M = mass_matrix(intuitive.m, q);
    CHECK_CLOSE(mass_matrix(x.m, q), M, (Tolerance{1e-9, 1e-9}), "at q_f = 0 M(q) = M_bar");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), kinetic_energy(intuitive.m, q, qd), (Tolerance{1e-9, 1e-9}), "at q_f = 0");
    q = random_state(x.m, rnd, 0.3, 0.05);
    const MatX Mq = mass_matrix(x.m, q);
    CHECK((Mq - M).norm() > 1e-3 * M.norm());
    CHECK_CLOSE(Mq, MatX(Mq.transpose()), kTight, "M(q) is symmetric");
    CHECK_CLOSE(MatX(Mq.block(x.m.offset(x.B), x.m.offset(x.B), 3, 3)), MatX(Vec3(1.5, 1.5, 0.2).asDiagonal()),
                kTight, "rigid blocks stay");
    CHECK_NEAR(kinetic_energy(x.m, q, qd), 0.5 * qd.dot(Mq * qd), (Tolerance{1e-10, 1e-10}), "T = 1/2 qd^T M(q) qd");
    CHECK_NEAR(kinetic_energy(intuitive.m, q, qd), 0.5 * qd.dot(M * qd), (Tolerance{1e-10, 1e-10}), "T with M_bar");
    CHECK(std::abs(kinetic_energy(x.m, q, qd) - kinetic_energy(intuitive.m, q, qd)) > 1e-6);
    // Against the FE kinetic energy of the absolute nodal velocities.
    auto rigid = [&](BodyId b, double m, double J) {
      const Vec3 v = qd.segment<3>(x.m.offset(b));
      return 0.5 * (m * v.head<2>().squaredNorm() + J * v(2) * v(2));
    };
    const double T = rigid(x.A, 2.0, 0.3) + rigid(x.B, 1.5, 0.2) + fe_kinetic_energy(x.m, x.rod, q, qd) +
                     fe_kinetic_energy(x.m, x.bar, q, qd);
    CHECK_NEAR(kinetic_energy(x.m, q, qd), T, (Tolerance{1e-8, 1e-8}), "the FE kinetic energy of the nodes");
  }
}

// Module 8 README section 2 shows the change from module 7 as a diff; its claims hold.
TEST_CASE("module 8's node rows are module 7's marker in frame j, and L is Phi at the reference state", "[flexible]") {
  Random rnd(62);
  const FeModel fe = straight_beam(0.9, 5, square_section(7e10, 2700, 0.02), Vec2(0.3, -0.1), 0.4);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, 3);
  const int n = 3 + d.num_modes();
  VecX q = rnd.vector(n, -1, 1), qd = rnd.vector(n, -2, 2);
  MatX turn = MatX::Identity(3, 3);  // diag(A^T, 1)
  turn.topLeftCorner(2, 2) = rotation(q(2)).transpose();
  for (const NodeModes& node : d.nodes) {
    CHECK_CLOSE(node_acceleration_map(node, q), MatX(turn * node_jacobian(node, q)), kTight, "L_k = diag(A^T, 1) G_k");
    CHECK_CLOSE(node_acceleration_bias(node, q, qd), Vec3(turn * node_convective_acceleration(node, q, qd)), kTight,
                "b_k = diag(A^T, 1) c_k");
  }
  const VecX rest = VecX::Zero(n);
  CHECK_CLOSE(stacked_map(d, rest), d.basis.Phi, kTight, "L = Phi at theta = 0 and q_f = 0");
  CHECK_CLOSE(ffrf_mass_matrix(d, rest), MatX(d.basis.Phi.transpose() * d.matrices.M * d.basis.Phi),
              (Tolerance{1e-12, 1e-12}), "M(q) = M_bar at theta = 0 and q_f = 0");
}

// ---- flexible_body_data, frame_for_placement ---------------------------------------------------

TEST_CASE("flexible_body_data: centred nodes, mass and inertia of a straight beam at any placement", "[flexible]") {
  const Section s{70e9, 2700.0, 4e-4, 2e-8};
  const double L = 2.0;
  const int N = 5;
  const double h = L / N, m = s.rho * s.A * L;
  const Vec2 start(1.3, -0.7);
  const double angle = 0.9;
  const Vec2 mid = start + 0.5 * L * Vec2(std::cos(angle), std::sin(angle));
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    CAPTURE(type == MassMatrixType::lumped);
    const FeModel fe = straight_beam(L, N, s, start, angle);
    const FlexibleBodyData d = flexible_body_data(fe, type, 4);
    REQUIRE(d.fe.num_nodes() == N + 1);
    REQUIRE(d.fe.num_elements() == N);
    for (int k = 0; k <= N; ++k) {
      CAPTURE(k);
      CHECK_CLOSE(d.fe.nodes()[k], Vec2(fe.nodes()[k] - mid), kTight, "nodes moved so that the centroid is the origin");
      CHECK_CLOSE(d.nodes[k].x_bar, d.fe.nodes()[k], kTight, "x_bar is the centred node");
      CHECK_CLOSE(d.nodes[k].Phi_t, MatX(d.Phi_f.middleRows(3 * k, 2)), kTight, "Phi_t rows");
      CHECK_CLOSE(d.nodes[k].Phi_psi, MatX(d.Phi_f.middleRows(3 * k + 2, 1)), kTight, "Phi_psi row");
    }
    // First moments of the mass about the new origin vanish: t^T M r_o = 0 for both translations.
    const int n = d.fe.num_dofs();
    MatX T = MatX::Zero(n, 3);  // t_x, t_y, unit rotation about the origin
    for (int k = 0; k <= N; ++k) {
      T(3 * k, 0) = 1.0;
      T(3 * k + 1, 1) = 1.0;
      T.block<3, 1>(3 * k, 2) << -d.fe.nodes()[k].y(), d.fe.nodes()[k].x(), 1.0;
    }
    const MatX rigid = T.transpose() * d.matrices.M * T;
    CHECK_NEAR(rigid(0, 2), 0.0, (Tolerance{1e-12 * m * L, 0}), "sum of m_k y_k");
    CHECK_NEAR(rigid(1, 2), 0.0, (Tolerance{1e-12 * m * L, 0}), "sum of m_k x_k");
    CHECK_NEAR(d.mass, m, (Tolerance{0, 1e-12}), "m = rho A L");
    const double J = type == MassMatrixType::consistent
                         ? m * L * L / 12
                         : [&] {
                             double sum = 2 * N * (s.rho * s.A * h) * h * h / 78;  // rotary terms
                             for (int k = 0; k <= N; ++k) {
                               const double mk = s.rho * s.A * h * ((k == 0 || k == N) ? 0.5 : 1.0);
                               sum += mk * std::pow(k * h - L / 2, 2);
                             }
                             return sum;
                           }();
    CHECK_NEAR(d.inertia, J, (Tolerance{0, 1e-11}), "J about the centroid");
    // The elastic columns: mass-normalised, M-orthogonal to the rigid modes, matrices that match.
    CHECK(d.num_modes() == 4);
    CHECK_CLOSE(MatX(T.transpose() * d.matrices.M * d.Phi_f), MatX::Zero(3, 4), (Tolerance{1e-9, 0}),
                "Phi_f is M-orthogonal to the rigid modes");
    CHECK_CLOSE(d.M_ff, MatX::Identity(4, 4), (Tolerance{1e-10, 1e-10}), "M_ff = I (mass-normalised modes)");
    CHECK_CLOSE(d.K_ff, MatX(d.Phi_f.transpose() * d.matrices.K * d.Phi_f), kTight, "K_ff = Phi_f^T K Phi_f");
    CHECK_CLOSE(d.S_f, MatX::Zero(2, 4), (Tolerance{1e-9, 0}), "S_f = 0");
    CHECK_CLOSE(MatX(d.K_ff - MatX(d.K_ff.diagonal().asDiagonal())), MatX::Zero(4, 4), (Tolerance{1e-9 * d.K_ff.norm(), 0}),
                "K_ff diagonal");
    CHECK(d.K_ff(0, 0) > 1.0);
    CHECK_CLOSE(MatX(d.basis.Phi.rightCols(4)), d.Phi_f, kTight, "Phi_f: the elastic columns of the basis");
    CHECK(d.basis.num_rigid == 3);
    const IntuitiveBody body(std::make_shared<const FlexibleBodyData>(d));
    CHECK(body.num_nodes() == N + 1);
    CHECK(body.num_modes() == 4);
    CHECK(body.mass() == d.mass);
    CHECK(body.inertia() == d.inertia);
    MatX M_bar = MatX::Identity(7, 7);
    M_bar.diagonal().head<3>() << m, m, J;
    CHECK_CLOSE(body.mass_matrix(VecX::Zero(7)), M_bar, (Tolerance{1e-9, 1e-9}), "M_bar = diag(m, m, J, I)");
  }
}

TEST_CASE("flexible_body_data with a Craig-Bampton basis; bad bases are refused", "[flexible]") {
  const FeModel fe = straight_beam(1.2, 6, kSteel, Vec2(0.5, 0.2), 0.3);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const ReducedBasis cb = craig_bampton(mats.K, mats.M, node_dofs({0, 6}), 2);
  const FlexibleBodyData d = flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, mats, cb));
  CHECK(d.num_modes() == 3 * 2 - 3 + 2);
  MatX T = MatX::Zero(fe.num_dofs(), 3);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    T(3 * k, 0) = 1.0;
    T(3 * k + 1, 1) = 1.0;
    T.block<3, 1>(3 * k, 2) << -d.fe.nodes()[k].y(), d.fe.nodes()[k].x(), 1.0;
  }
  CHECK_CLOSE(MatX(T.transpose() * d.matrices.M * d.Phi_f), MatX::Zero(3, d.num_modes()), (Tolerance{1e-9, 0}),
              "Phi_f M-orthogonal to the rigid modes about the centroid");
  CHECK_CLOSE(d.fe.nodes()[0], Vec2(-0.6 * std::cos(0.3), -0.6 * std::sin(0.3)), kTight, "centred");
  CHECK_CLOSE(MatX(d.basis.Phi.leftCols(3).transpose() * d.matrices.M * d.basis.Phi.leftCols(3)),
              MatX(Vec3(d.mass, d.mass, d.inertia).asDiagonal()), (Tolerance{1e-10, 1e-10}),
              "the rigid columns are re-made about the centroid");

  CHECK_THROWS_MENTIONING(flexible_body_data(fe, MassMatrixType::consistent, cb), std::invalid_argument,
                          "num_rigid = 0");
  const FeModel longer = straight_beam(1.2, 7, kSteel);
  const FeMatrices lm = assemble(longer, MassMatrixType::consistent);
  const ReducedBasis other = modal_truncation(longer, lm, 2);
  CHECK_THROWS_MENTIONING(flexible_body_data(fe, MassMatrixType::consistent, other), std::invalid_argument,
                          "21 rows, got num_rigid = 3 and 24 rows");
}

TEST_CASE("clamped_frame_body_data: the node stays on the frame, the modes are the cantilever's", "[flexible]") {
  // A cantilever of length L: omega_i = (beta_i L)^2 sqrt(EI / (rho A L^4)), beta_1 L = 1.8751041,
  // beta_2 L = 4.6940911 (the roots of cos x cosh x = -1).
  const double L = 1.5;
  for (const int node : {0, 12}) {
    const FeModel fe = straight_beam(L, 12, kSteel, Vec2(0.2, -0.1), 0.4);
    const FlexibleBodyData d = clamped_frame_body_data(fe, MassMatrixType::consistent, node, 2);
    REQUIRE(d.num_modes() == 2);
    CHECK_CLOSE(d.Phi_f.middleRows(3 * node, 3), MatX::Zero(3, 2), (Tolerance{1e-12, 0}),
                "the clamped node moves and turns with the frame");
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(d.K_ff, d.M_ff);
    const double unit = std::sqrt(kSteel.E * kSteel.I / (kSteel.rho * kSteel.A * std::pow(L, 4)));
    CHECK_CLOSE(Vec2(eig.eigenvalues().cwiseSqrt()), Vec2(unit * Vec2(1.8751041, 4.6940911).cwiseAbs2()),
                (Tolerance{0, 1e-4}), "the cantilever frequencies");
    CHECK(d.S_f.norm() > 1e-3);  // not M-orthogonal to the rigid motions, unlike free-free modes
    CHECK_NEAR(d.mass, kSteel.rho * kSteel.A * L, (Tolerance{0, 1e-12}), "the mass");
  }
  const FeModel fe = straight_beam(L, 4, kSteel);
  CHECK_THROWS_MENTIONING(clamped_frame_body_data(fe, MassMatrixType::lumped, 5, 2), std::invalid_argument,
                          "node 5 is not a node of the model (0 .. 4)");
}

TEST_CASE("a pendulum with its frame clamped at the hinge conserves energy and turns like the centroid frame's",
          "[flexible]") {
  // The same soft pendulum with the frame at the centroid (free-free modes) and clamped at the hinge
  // node (cantilever modes): with lumped mass the full FFRF conserves energy in both frames, and the
  // tip, whose motion is dominated by the rigid swing, follows the same path to within the
  // small share of the elastic motion that the two bases represent differently.
  const auto run = [](BodyBasis basis) {
    FlexiblePendulumParameters p;
    p.elements = 8;
    p.modes = 3;
    p.basis = basis;
    p.mass_type = MassMatrixType::lumped;
    p.E = 20e9;
    const FlexibleExample ex = flexible_pendulum(p, make_ffrf_body);
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = 1e-9;
    o.atol = 1e-11;
    o.step = 1e-4;
    o.max_step = 0.005;
    const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, 0.4, o);
    double drift = 0;
    for (double e : tr.energy) drift = std::max(drift, std::abs(e - tr.energy.front()));
    CHECK_NEAR(drift / (ex.data->mass * p.gravity * p.length), 0.0, (Tolerance{1e-7, 0}),
               "energy is conserved in either frame");
    return point_position(ex.model, ex.model.find_point("beam tip"), tr.q.back());
  };
  const Vec2 centroid_frame = run(BodyBasis::free_free_modes), clamped_frame = run(BodyBasis::clamped_frame);
  CHECK_CLOSE(clamped_frame, centroid_frame, (Tolerance{2e-3, 0}), "the tip after 0.4 s, both frames");
  CHECK(clamped_frame.y() < -0.5);  // it has swung down
}

TEST_CASE("frame_for_placement puts the FE model's node 0 where asked", "[flexible]") {
  Random rnd(71);
  for (MassMatrixType type : {MassMatrixType::consistent, MassMatrixType::lumped}) {
    for (const Vec2& start : {Vec2(0.0, 0.0), Vec2(0.3, -0.1)}) {
      const FeModel fe = straight_beam(1.5, 5, kSteel, start);
      const FlexibleBodyData d = flexible_body_data(fe, type, 2);
      const Vec2 origin = rnd.vec2(-2, 2);
      const double angle = rnd.uniform(-3, 3);
      const Vec3 frame = frame_for_placement(fe, type, origin, angle);
      CHECK(frame(2) == angle);
      CHECK_CLOSE(undeformed_node_position(d, 0, frame), Vec2(origin + rot(angle) * start), (Tolerance{1e-12, 1e-12}),
                  "node 0 at origin + A(angle) x_0");
      CHECK_CLOSE(undeformed_node_position(d, 5, frame),
                  Vec2(origin + rot(angle) * (start + Vec2(1.5, 0.0))), (Tolerance{1e-12, 1e-12}), "the last node");
      CHECK_CLOSE(Vec2(frame.head<2>()), Vec2(origin + rot(angle) * (start + Vec2(0.75, 0.0))),
                  (Tolerance{1e-12, 1e-12}), "R at the centroid");
    }
  }
}

// ---- the examples --------------------------------------------------------------------------

TEST_CASE("example builders: consistent initial conditions for both formulations", "[flexible]") {
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    FlexiblePendulumParameters pp;
    pp.elements = 6;
    FlexibleSliderCrankParameters sp;
    SpinUpBeamParameters up;
    up.elements = 6;
    for (const FlexibleExample& ex :
         {flexible_pendulum(pp, make_body), flexible_slider_crank(sp, make_body), spin_up_beam(up, make_body)}) {
      const Model& m = ex.model;
      REQUIRE(ex.q0.size() == m.num_coordinates());
      REQUIRE(ex.qd0.size() == m.num_coordinates());
      REQUIRE(ex.data);
      CHECK(m.body(ex.flexible).is_flexible());
      CHECK(&data_of(m, ex.flexible) == ex.data.get());
      const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
      CHECK(e.C.norm() < 1e-12);
      CHECK((e.Cq * ex.qd0 + e.Ct).norm() < 1e-10 * std::max(1.0, ex.qd0.norm()));
      CHECK(ex.qd0.segment(m.offset(ex.flexible) + 3, ex.data->num_modes()).isZero(0.0));
      CHECK(ex.q0.segment(m.offset(ex.flexible) + 3, ex.data->num_modes()).isZero(0.0));
    }
  }
}

TEST_CASE("example builders: an initial elastic state and velocity, with the frames made consistent", "[flexible]") {
  Random rnd(907);
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    FlexiblePendulumParameters pp;
    pp.elements = 6;
    pp.modes = 2;
    FlexibleSliderCrankParameters sp;
    sp.crank_angle = 0.7;
    SpinUpBeamParameters up;
    up.elements = 6;
    const auto with_state = [&rnd](auto p, int n_f) {
      p.initial.q_f = rnd.vector(n_f, -1e-3, 1e-3);
      p.initial.q_f_dot = rnd.vector(n_f, -0.1, 0.1);
      return p;
    };
    const auto pendulum = with_state(pp, 2);
    const auto crank = with_state(sp, 3 * 2 - 3 + sp.modes);
    const auto spin = with_state(up, up.modes);
    const std::vector<std::pair<FlexibleExample, InitialElasticState>> cases{
        {flexible_pendulum(pendulum, make_body), pendulum.initial},
        {flexible_slider_crank(crank, make_body), crank.initial},
        {spin_up_beam(spin, make_body), spin.initial}};
    for (const auto& [ex, initial] : cases) {
      const Model& m = ex.model;
      const int at = m.offset(ex.flexible) + 3, n_f = ex.data->num_modes();
      CHECK_CLOSE(VecX(ex.q0.segment(at, n_f)), initial.q_f, kTight, "q_f as given");
      CHECK_CLOSE(VecX(ex.qd0.segment(at, n_f)), initial.q_f_dot, kTight, "q_f_dot as given");
      const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
      CHECK_CLOSE(e.C, VecX::Zero(e.C.size()), (Tolerance{1e-11, 0}), "C = 0 with the elastic state");
      CHECK_CLOSE(VecX(e.Cq * ex.qd0 + e.Ct), VecX::Zero(e.C.size()), (Tolerance{1e-10, 0}), "C_dot = 0");
    }
    // The pendulum's hinge node stays at the origin while the body bends: its frame moved.
    const FlexibleExample bent = flexible_pendulum(pendulum, make_body);
    CHECK_CLOSE(point_position(bent.model, bent.model.find_point("beam start"), bent.q0), Vec2::Zero(),
                (Tolerance{1e-11, 0}), "the hinge node at the origin");
    CHECK(!bent.q0.head(3).isApprox(flexible_pendulum(pp, make_body).q0.head(3)));
  }
  FlexibleSliderCrankParameters wrong;
  wrong.initial.q_f = VecX::Zero(4);
  CHECK_THROWS_MENTIONING(flexible_slider_crank(wrong), std::invalid_argument,
                          "flexible_slider_crank: initial.q_f has 4 entries; the flexible body has 5 elastic coordinates");
}

TEST_CASE("example builders: free-free modes chosen by kind, bending and axial", "[flexible]") {
  // A free-free beam: bending omega_1 = 4.7300408^2 sqrt(EI / (rho A L^4)), axial omega_1 = pi / L sqrt(E / rho).
  FlexibleSliderCrankParameters p;
  p.elements = 40;
  p.basis = BodyBasis::free_free_modes;
  p.selection.bending = 2;
  p.selection.axial = 1;
  const FlexibleExample ex = flexible_slider_crank(p);
  REQUIRE(ex.data->num_modes() == 3);
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(ex.data->K_ff, ex.data->M_ff);
  const Section s = square_section(p.E, p.rho, p.rod_side);
  const double L = p.rod_length;
  const double bending = 4.7300408 * 4.7300408 * std::sqrt(s.E * s.I / (s.rho * s.A * std::pow(L, 4)));
  const double axial = kPi / L * std::sqrt(s.E / s.rho);
  const VecX omega = eig.eigenvalues().cwiseSqrt();
  CHECK_NEAR(omega(0), bending, (Tolerance{0, 1e-3}), "the first bending mode");
  CHECK_NEAR(omega(2), axial, (Tolerance{0, 1e-3}), "the first axial mode, above the second bending one");
  CHECK(omega(1) > 2 * bending);
  CHECK(omega(1) < axial);

  FlexibleSliderCrankParameters only_axial = p;
  only_axial.selection.bending = 0;
  CHECK_NEAR(VecX(Eigen::GeneralizedSelfAdjointEigenSolver<MatX>(flexible_slider_crank(only_axial).data->K_ff,
                                                                  flexible_slider_crank(only_axial).data->M_ff)
                      .eigenvalues()
                      .cwiseSqrt())(0),
             axial, (Tolerance{0, 1e-3}), "an axial mode alone");
  FlexibleSliderCrankParameters cb = p;
  cb.basis = BodyBasis::craig_bampton;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(cb), std::invalid_argument, "needs BodyBasis::free_free_modes");
  FlexibleSliderCrankParameters too_many = p;
  too_many.elements = 2;
  too_many.selection.axial = 3;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(too_many), std::invalid_argument, "asked for 2 and 3");
}

TEST_CASE("flexible_slider_crank: velocities, body and point names", "[flexible]") {
  FlexibleSliderCrankParameters p;
  p.crank_length = 0.2;
  p.rod_length = 0.5;
  p.crank_speed = 40.0;
  p.elements = 6;
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    const FlexibleExample ex = flexible_slider_crank(p, make_body);
    const Model& m = ex.model;
    const BodyId crank = m.find_body("crank"), rod = m.find_body("rod"), slider = m.find_body("slider");
    CHECK(rod == ex.flexible);
    CHECK(ex.data->num_modes() == 3 * 2 - 3 + 2);
    const double w = p.crank_speed, l1 = p.crank_length, l2 = p.rod_length;
    // At t = 0 everything lies on the x axis: the crank tip moves up at l1 w, the slider stands,
    // the rod turns at -l1 w / l2 and its centroid (mid-span) moves at half the tip's speed.
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(crank))), Vec3(0.0, 0.5 * l1 * w, w), (Tolerance{1e-10, 1e-10}),
                "crank");
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(rod))), Vec3(0.0, 0.5 * l1 * w, -l1 * w / l2),
                (Tolerance{1e-10, 1e-10}), "rod frame");
    CHECK_CLOSE(Vec3(ex.qd0.segment<3>(m.offset(slider))), Vec3::Zero(), (Tolerance{1e-10, 1e-10}), "slider");
    CHECK(ex.qd0.segment(m.offset(rod) + 3, ex.data->num_modes()).isZero(0.0));
    CHECK_CLOSE(Vec3(ex.q0.segment<3>(m.offset(rod))), Vec3(l1 + l2 / 2, 0.0, 0.0), kTight, "rod frame at rest");
    for (const char* name : {"crank tip", "rod start", "rod end", "slider", "rod mid"}) {
      CAPTURE(name);
      CHECK_NOTHROW(m.find_point(name));
    }
    CHECK(m.point(m.find_point("rod start")).node == 0);
    CHECK(m.point(m.find_point("rod end")).node == p.elements);
    CHECK(m.point(m.find_point("rod mid")).node == p.elements / 2);
    CHECK_CLOSE(point_pose(m, m.find_point("rod mid"), ex.q0).r, Vec2(l1 + l2 / 2, 0.0), kTight, "rod mid");
    CHECK_CLOSE(point_pose(m, m.find_point("crank tip"), ex.q0).r, Vec2(l1, 0.0), kTight, "crank tip");
    CHECK_CLOSE(point_pose(m, m.find_point("rod end"), ex.q0).r, Vec2(l1 + l2, 0.0), kTight, "rod end");
  }
  p.elements = 5;
  const FlexibleExample odd = flexible_slider_crank(p);
  CHECK_THROWS_MENTIONING(odd.model.find_point("rod mid"), ModelError, "unknown point 'rod mid'");
  CHECK_NOTHROW(odd.model.find_point("rod end"));
  CHECK(odd.model.point(odd.model.find_point("rod end")).node == 5);
}

TEST_CASE("spin_up_profile: derivatives and continuity at the end of the spin-up", "[flexible]") {
  const double W = 2.0, T = 15.0;
  const DriveFunction f = spin_up_profile(W, T);
  auto value = [&](double t) { return VecX::Constant(1, f(t).f); };
  auto rate = [&](double t) { return VecX::Constant(1, f(t).fd); };
  for (double t : {0.7, 3.0, 7.5, 11.2, 14.6, 16.0, 30.0}) {
    CAPTURE(t);
    CHECK_NEAR(f(t).fd, first_derivative(value, t)(0), (Tolerance{1e-8, 1e-8}), "f' = df/dt");
    CHECK_NEAR(f(t).fdd, first_derivative(rate, t)(0), (Tolerance{1e-8, 1e-8}), "f'' = df'/dt");
  }
  // Starts from rest, ends at the rate W with zero acceleration, and continues linearly.
  CHECK_NEAR(f(0.0).f, 0.0, kTight, "f(0)");
  CHECK_NEAR(f(0.0).fd, 0.0, kTight, "f'(0)");
  CHECK_NEAR(f(0.0).fdd, 0.0, kTight, "f''(0)");
  const double eps = 1e-9;
  const DriveValue before = f(T - eps), at = f(T), after = f(T + eps);
  CHECK_NEAR(before.f, W * T / 2, (Tolerance{1e-8, 1e-10}), "f(T-) = W T / 2");
  CHECK_NEAR(at.f, W * T / 2, (Tolerance{1e-12, 1e-12}), "f(T) = W T / 2");
  CHECK_NEAR(after.f, W * T / 2, (Tolerance{1e-8, 1e-10}), "f(T+)");
  CHECK_NEAR(before.fd, W, (Tolerance{1e-8, 1e-10}), "f'(T-) = W");
  CHECK_NEAR(after.fd, W, kTight, "f'(T+) = W");
  CHECK_NEAR(before.fdd, 0.0, (Tolerance{1e-8, 0}), "f''(T-) = 0");
  CHECK_NEAR(after.fdd, 0.0, kTight, "f''(T+) = 0");
  CHECK_NEAR(f(T / 2).fdd, 2 * W / T, (Tolerance{1e-12, 1e-12}), "peak acceleration 2 W / T at mid spin-up");
  CHECK_NEAR(f(40.0).f, W * (40.0 - T / 2), (Tolerance{1e-12, 1e-12}), "after T: W (t - T/2)");
  // The spin_up_beam uses it as the hub's angle.
  const FlexibleExample ex = spin_up_beam();
  const Model& m = ex.model;
  const BodyId hub = m.find_body("hub");
  for (double t : {2.0, 20.0}) {
    VecX q = ex.q0;
    q(m.offset(hub) + 2) = f(t).f;
    CHECK(std::abs(constraints(m, q, t)(m.num_constraints() - 1)) < 1e-12);
  }
}

// ---- static equilibrium ------------------------------------------------------------------------

TEST_CASE("static_equilibrium: a rigid pendulum on a rotational spring under gravity", "[flexible]") {
  const double mass = 2.0, L = 1.2, k = 15.0, g = 9.81;
  Model m;
  m.set_gravity(Vec2(0.0, -g));
  const BodyId rod = m.add_body("rod", mass, mass * L * L / 12, Vec3(L / 2, 0.0, 0.0));
  m.add_revolute("pivot", m.add_point(ground, Vec2::Zero(), "O"), m.add_point(rod, Vec2(-L / 2, 0.0), "end"));
  m.add_rsda("spring", ground, rod, k, 0.0, 0.0);
  // The droop theta below the horizontal: k theta = m g (L/2) cos theta, by bisection.
  double lo = 0.0, hi = kPi / 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid - mass * g * L / 2 * std::cos(mid) < 0 ? lo : hi) = mid;
  }
  const double phi = -0.5 * (lo + hi);
  const StaticSolution s = static_equilibrium(m, m.initial_guess());
  CHECK_CLOSE(s.q, Vec3(L / 2 * std::cos(phi), L / 2 * std::sin(phi), phi), (Tolerance{1e-9, 1e-9}),
              "the closed-form equilibrium angle");
  CHECK(s.iterations > 0);
  CHECK(s.iterations <= StaticOptions{}.max_iterations);
  const ConstraintEvaluation e = evaluate_constraints(m, s.q, 0.0);
  CHECK_CLOSE(VecX(applied_forces(m, s.q, VecX::Zero(3), 0.0) - e.Cq.transpose() * s.lambda), VecX::Zero(3),
              (Tolerance{1e-8, 0}), "Q - C_q^T lambda = 0");
  CHECK_NEAR(s.lambda.norm(), mass * g, (Tolerance{1e-8, 1e-8}), "the pivot carries the weight");
}

TEST_CASE("static_equilibrium: a clamped flexible beam under gravity deflects by w L^4 / (8 EI)", "[flexible]") {
  const double L = 1.0, g = 9.81;
  const Section s = kSteel;
  const FeModel fe = straight_beam(L, 8, s);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  const ReducedBasis cb = craig_bampton(mats.K, mats.M, node_dofs({0}), 5);
  const DataPtr data = std::make_shared<const FlexibleBodyData>(
      flexible_body_data(fe, MassMatrixType::consistent, ffrf_basis(fe, mats, cb)));
  const double w = s.rho * s.A * g, tip = w * std::pow(L, 4) / (8 * s.E * s.I);
  for (const BodyFactory& make_body : {BodyFactory(make_intuitive_body), BodyFactory(make_ffrf_body)}) {
    Model m;
    m.set_gravity(Vec2(0.0, -g));
    const BodyId beam =
        m.add_flexible_body("beam", make_body(data), frame_for_placement(fe, MassMatrixType::consistent, Vec2::Zero(), 0.0));
    m.add_fixed("clamp", m.add_point(ground, Vec2::Zero(), "wall"), m.add_node_point(beam, 0, "root"));
    const PointId P = m.add_node_point(beam, 8, "tip");
    const StaticSolution st = static_equilibrium(m, m.initial_guess());
    const Pose root = point_pose(m, m.find_point("root"), st.q), end = point_pose(m, P, st.q);
    CHECK_CLOSE(root.r, Vec2::Zero(), (Tolerance{1e-12, 0}), "the root stays clamped");
    CHECK_NEAR(root.phi, 0.0, (Tolerance{1e-12, 0}), "and level");
    CHECK_NEAR(end.r.y(), -tip, (Tolerance{0, 1e-3}), "cantilever tip deflection under its weight");
    CHECK_NEAR(end.r.x(), L, (Tolerance{1e-4, 0}), "the tip hardly moves along the beam");
    const ConstraintEvaluation e = evaluate_constraints(m, st.q, 0.0);
    const VecX r = applied_forces(m, st.q, VecX::Zero(m.num_coordinates()), 0.0) - e.Cq.transpose() * st.lambda;
    CHECK(r.norm() < 1e-8);
    CHECK_NEAR(Vec2(st.lambda.head<2>()).norm(), data->mass * g, (Tolerance{1e-8, 1e-8}), "the clamp carries the weight");
  }
}

TEST_CASE("static_equilibrium: a body without supports has no equilibrium", "[flexible]") {
  auto refuses = [](const Model& m) {
    bool thrown = false;
    try {
      static_equilibrium(m, m.initial_guess());
    } catch (const SingularJacobianError&) {
      thrown = true;
    } catch (const ConvergenceError&) {
      thrown = true;
    }
    return thrown;
  };
  Model rigid;
  rigid.set_gravity(Vec2(0.0, -9.81));
  rigid.add_body("free", 1.0, 0.1);
  CHECK(refuses(rigid));
  Model flexible;
  flexible.set_gravity(Vec2(0.0, -9.81));
  flexible.add_flexible_body("free", make_intuitive_body(beam_data(1.0, 4, MassMatrixType::lumped, 2)));
  CHECK(refuses(flexible));
  CHECK_THROWS_AS(static_equilibrium(flexible, VecX::Zero(flexible.num_coordinates() + 1)), std::invalid_argument);
}

// ---- simulation ----------------------------------------------------------------------------

namespace {

// Simulates the pendulum for 0.3 s and checks the trajectory's sizes and its energy drift.
void check_pendulum_energy(const BodyFactory& make_body) {
  FlexiblePendulumParameters p;
  p.elements = 6;
  p.modes = 2;
  p.mass_type = MassMatrixType::lumped;
  p.E = 2e9;  // soft, so that it bends visibly while it falls
  const FlexibleExample ex = flexible_pendulum(p, make_body);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.step = 1e-4;
  o.max_step = 0.01;
  const double t_end = 0.3;
  const Trajectory tr = simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
  const std::size_t N = tr.t.size();
  REQUIRE(N > 2);
  CHECK(tr.q.size() == N);
  CHECK(tr.qd.size() == N);
  CHECK(tr.energy.size() == N);
  CHECK(tr.step.size() == N);
  CHECK(tr.work_done.size() == N);
  CHECK(tr.position_drift.size() == N);
  CHECK(tr.velocity_drift.size() == N);
  CHECK(tr.t.front() == 0.0);
  CHECK_NEAR(tr.t.back(), t_end, (Tolerance{1e-12, 0}), "the run ends at t_end");
  CHECK(tr.q.back().size() == ex.model.num_coordinates());
  CHECK(tr.qd.back().size() == ex.model.num_coordinates());
  // The beam has fallen: energy of the order of m g L/2 has moved from V to T, and it vibrates.
  const double scale = ex.data->mass * p.gravity * p.length / 2;
  const Model& m = ex.model;
  CHECK(kinetic_energy(m, tr.q.back(), tr.qd.back()) > 0.1 * scale);
  INFO("q_f at the end: " << tr.q.back().tail(p.modes).transpose());
  CHECK(tr.q.back().tail(p.modes).norm() > 1e-4);
  double drift = 0, worst_c = 0;
  for (std::size_t i = 0; i < N; ++i) {
    drift = std::max(drift, std::abs(tr.energy[i] - tr.energy.front()));
    worst_c = std::max(worst_c, tr.position_drift[i]);
  }
  CHECK_NEAR(tr.energy.front(), kinetic_energy(m, ex.q0, ex.qd0) + potential_energy(m, ex.q0), kTight,
             "energy = T + V");
  CHECK_NEAR(tr.energy.back(), kinetic_energy(m, tr.q.back(), tr.qd.back()) + potential_energy(m, tr.q.back()),
             kTight, "energy = T(q, q_dot) + V");
  INFO("energy drift " << drift << " J of a scale " << scale << " J, worst |C| " << worst_c << ", " << N << " points");
  CHECK(drift < 1e-7 * scale);
  CHECK(worst_c < 1e-8);
}

}  // namespace

TEST_CASE("simulate: a free flexible pendulum conserves its energy (intuitive body; FFRF with lumped mass)",
          "[flexible]") {
  SECTION("intuitive") { check_pendulum_energy(make_intuitive_body); }
  SECTION("FFRF") { check_pendulum_energy(make_ffrf_body); }
}

TEST_CASE("beam_point and deflection_at: the element shape functions between the nodes", "[flexible]") {
  for (const int elements : {5, 6}) {
    CAPTURE(elements);
    FlexiblePendulumParameters p;
    p.elements = elements;
    const FlexibleExample ex = flexible_pendulum(p, make_ffrf_body);
    const DeformableBody& beam = *ex.model.body(ex.flexible).deformable;
    const int at = ex.model.offset(ex.flexible), n_f = beam.num_modes();
    VecX q = ex.q0;
    q.segment<3>(at) << 0.2, -0.3, 0.4;  // the frame: anywhere, turned
    // Rigid motion only: the beam is the straight line through its nodes, without deflection.
    const Vec2 x0 = beam.node_position(0), axis = (beam.node_position(elements) - x0).normalized();
    for (double s : {0.0, 0.13, 0.5, 0.77, 1.0}) {
      CHECK((beam_point(ex, q, s) - (Vec2(0.2, -0.3) + rotation(0.4) * (x0 + s * axis))).norm() < 1e-13);
      CHECK(std::abs(deflection_at(ex, q, s)) < 1e-13);
    }
    for (int k = 0; k < n_f; ++k) q(at + 3 + k) = 0.01 * (k % 2 ? -1.0 : 1.0) / (k + 1);
    const VecX zero = VecX::Zero(3 + n_f), q_body = ex.model.body_state(q, ex.flexible);
    const double l = p.length / elements;
    // In the frame: the displacement along and across the beam at s, and the node rotations.
    const Mat2 A = rotation(0.4);
    auto local = [&](double s) {
      const Vec2 d = A.transpose() * (beam_point(ex, q, s) - Vec2(0.2, -0.3)) - (x0 + s * axis);
      return Vec2(d.dot(axis), axis.x() * d.y() - axis.y() * d.x());
    };
    for (int k = 0; k <= elements; ++k) {
      CAPTURE(k);
      const NodeMarker m = beam.node_marker(k, q_body, zero);
      // At a node: the node itself.
      CHECK((beam_point(ex, q, k * l) - m.pose.head<2>()).norm() < 1e-12);
      // The slope across the beam at the node is the node's rotation (one-sided difference
      // into an element that has the node).
      const double delta = 1e-6 * l, s = k * l, side = k < elements ? 1.0 : -1.0;
      const double slope = (local(s + side * delta).y() - local(s).y()) / (side * delta);
      CHECK(slope == Approx(m.pose.z() - 0.4).margin(1e-6));
    }
    for (int e = 0; e < elements; ++e) {
      // Inside an element: linear along, cubic across (zero fourth and second differences).
      Vec2 d[5];
      for (int j = 0; j < 5; ++j) d[j] = local((e + 0.1 + 0.2 * j) * l);
      const double scale = std::max(1e-6, d[0].norm());
      CHECK(std::abs(d[0].x() - 2 * d[1].x() + d[2].x()) < 1e-9 * scale);
      CHECK(std::abs(d[0].y() - 4 * d[1].y() + 6 * d[2].y() - 4 * d[3].y() + d[4].y()) < 1e-9 * scale);
    }
    // Mid-span is at length / 2, a node or not.
    CHECK(midspan_deflection(ex, q) == Approx(deflection_at(ex, q, 0.5 * p.length)).margin(1e-15));
    CHECK(std::abs(midspan_deflection(ex, q)) > 1e-6);
    CHECK_THROWS_MENTIONING(beam_point(ex, q, 1.5), std::invalid_argument, "outside the beam");
    CHECK_THROWS_MENTIONING(beam_point(ex, q, -0.1), std::invalid_argument, "outside the beam");
  }
}

TEST_CASE("flexible_slider_crank: every physical parameter can be set", "[flexible]") {
  FlexibleSliderCrankParameters p;
  p.crank_angle = 0.7;
  p.gravity = 9.81;
  p.crank_inertia = 4e-4;
  p.slider_inertia = 2e-5;
  const FlexibleExample ex = flexible_slider_crank(p, make_ffrf_body);
  const Model& m = ex.model;
  // Assembled at the start angle: closed, the crank at 0.7, the slider where the rigid
  // mechanism puts it, x = r cos A + sqrt(l^2 - r^2 sin^2 A).
  CHECK(constraints(m, ex.q0, 0.0).norm() < 1e-12);
  CHECK((constraint_jacobian(m, ex.q0, 0.0) * ex.qd0 + constraint_time_derivative(m, ex.q0, 0.0)).norm() < 1e-9);
  CHECK(m.body_coordinates(ex.q0, m.find_body("crank")).z() == Approx(0.7));
  const double r = p.crank_length, l = p.rod_length, A = 0.7;
  CHECK(m.body_coordinates(ex.q0, m.find_body("slider")).x() ==
        Approx(r * std::cos(A) + std::sqrt(l * l - r * r * std::sin(A) * std::sin(A))).epsilon(1e-12));
  CHECK(m.gravity().y() == -9.81);
  CHECK(m.body(m.find_body("crank")).inertia == 4e-4);
  CHECK(m.body(m.find_body("slider")).inertia == 2e-5);
  // A rectangular section b x h: the bending frequencies scale with h (omega ~ sqrt(E I / (rho A))
  // = h sqrt(E / (12 rho))), so doubling h doubles them.
  auto lowest_frequency = [](double height) {
    FlexibleSliderCrankParameters q;
    q.basis = BodyBasis::free_free_modes;
    q.rod_width = 0.004;
    q.rod_height = height;
    const FlexibleExample e = flexible_slider_crank(q);
    const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(e.data->K_ff, e.data->M_ff);
    return std::sqrt(eig.eigenvalues().minCoeff());
  };
  CHECK(lowest_frequency(0.01) / lowest_frequency(0.005) == Approx(2.0).epsilon(1e-9));
  p.crank_length = 0.4;
  p.crank_angle = 1.5;
  CHECK_THROWS_MENTIONING(flexible_slider_crank(p), std::invalid_argument, "cannot reach the guide");
}
