// Example systems with one flexible body (given code, module 7).
#include "fmbd/flexible_examples.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/craig_bampton.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/kinematic_errors.hpp"
#include "fmbd/linear_solve.hpp"
#include "fmbd/modal_truncation.hpp"

namespace fmbd {

namespace {

constexpr double pi = 3.14159265358979323846;


// A straight beam along x from the origin, reduced as asked; `joints` are its interface nodes.
std::shared_ptr<const FlexibleBodyData> beam_data(double length, int elements, const Section& s, MassMatrixType type,
                                                   BodyBasis basis, int modes, const ModeSelection& selection,
                                                   const std::vector<int>& joints, FeModel& fe) {
  fe = straight_beam(length, elements, s);
  const bool by_kind = selection.bending >= 0 || selection.axial >= 0;
  if (by_kind && basis != BodyBasis::free_free_modes)
    throw std::invalid_argument("mode selection by kind (bending, axial) needs BodyBasis::free_free_modes");
  if (by_kind)
    return std::make_shared<const FlexibleBodyData>(
        flexible_body_data(fe, type, modes_by_kind(fe, assemble(fe, type), selection)));
  if (basis == BodyBasis::free_free_modes)
    return std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, modes));
  if (basis == BodyBasis::clamped_frame)
    return std::make_shared<const FlexibleBodyData>(clamped_frame_body_data(fe, type, joints.at(0), modes));
  const FeMatrices m = assemble(fe, type);
  const ReducedBasis cb = craig_bampton(m.K, m.M, node_dofs(joints), modes);
  return std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, type, ffrf_basis(fe, m, cb)));
}

// Velocities with every q_f_dot = 0 that satisfy C_q q_dot = -C_t: the velocity equation on the
// (x, y, phi) coordinates of all bodies, which must determine them (a driven mechanism).
VecX rigid_velocities(const Model& m, const VecX& q, double t) {
  const ConstraintEvaluation e = evaluate_constraints(m, q, t);
  std::vector<int> frame;
  for (int b = 0; b < m.num_bodies(); ++b)
    for (int k = 0; k < 3; ++k) frame.push_back(m.offset(BodyId{b}) + k);
  MatX Cq(e.Cq.rows(), frame.size());
  for (std::size_t c = 0; c < frame.size(); ++c) Cq.col(c) = e.Cq.col(frame[c]);
  const VecX v = solve_square(m, Cq, -e.Ct, "rigid initial velocities");
  VecX qd = VecX::Zero(m.num_coordinates());
  for (std::size_t c = 0; c < frame.size(); ++c) qd(frame[c]) = v(c);
  return qd;
}

// The flexible body's elastic state at t = 0 as asked, with the frame coordinates of every body
// moved by least-norm Newton corrections until C = 0, then their velocities until C_dot = 0.
void set_elastic_state(FlexibleExample& ex, const InitialElasticState& initial, const char* where) {
  if (initial.q_f.size() == 0 && initial.q_f_dot.size() == 0) return;
  const Model& m = ex.model;
  const int n_f = ex.data->num_modes(), at = m.offset(ex.flexible) + 3;
  for (const auto& [v, name] : {std::pair<const VecX&, const char*>{initial.q_f, "q_f"}, {initial.q_f_dot, "q_f_dot"}})
    if (v.size() != 0 && v.size() != n_f)
      throw std::invalid_argument(std::string(where) + ": initial." + name + " has " + std::to_string(v.size()) +
                                  " entries; the flexible body has " + std::to_string(n_f) + " elastic coordinates");
  if (initial.q_f.size() != 0) ex.q0.segment(at, n_f) = initial.q_f;
  if (initial.q_f_dot.size() != 0) ex.qd0.segment(at, n_f) = initial.q_f_dot;
  std::vector<int> frame;
  for (int b = 0; b < m.num_bodies(); ++b)
    for (int k = 0; k < 3; ++k) frame.push_back(m.offset(BodyId{b}) + k);
  const auto frame_columns = [&](const MatX& Cq) {
    MatX out(Cq.rows(), static_cast<Eigen::Index>(frame.size()));
    for (std::size_t c = 0; c < frame.size(); ++c) out.col(static_cast<Eigen::Index>(c)) = Cq.col(frame[c]);
    return out;
  };
  const double tolerance = 1e-12 * std::max(1.0, ex.q0.cwiseAbs().maxCoeff());
  double residual = 0;
  for (int iteration = 0;; ++iteration) {
    const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
    residual = e.C.norm();
    if (residual <= tolerance) break;
    if (iteration == 50)
      throw ConvergenceError(std::string(where) + ": no frame position fits the initial elastic state (|C| = " +
                                 readable(residual) + " after 50 iterations)",
                             iteration, residual);
    const VecX dq = Eigen::CompleteOrthogonalDecomposition<MatX>(frame_columns(e.Cq)).solve(VecX(-e.C));
    for (std::size_t c = 0; c < frame.size(); ++c) ex.q0(frame[c]) += dq(static_cast<Eigen::Index>(c));
  }
  const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
  const VecX dv = Eigen::CompleteOrthogonalDecomposition<MatX>(frame_columns(e.Cq)).solve(VecX(-(e.Cq * ex.qd0 + e.Ct)));
  for (std::size_t c = 0; c < frame.size(); ++c) ex.qd0(frame[c]) += dv(static_cast<Eigen::Index>(c));
}

}  // namespace

ReducedBasis modes_by_kind(const FeModel& fe, const FeMatrices& m, const ModeSelection& selection) {
  const int bending = std::max(selection.bending, 0), axial = std::max(selection.axial, 0);
  const ReducedBasis all = modal_truncation(fe, m, fe.num_dofs() - 3);
  std::vector<int> picked;
  int found_bending = 0, found_axial = 0;
  for (int c = 3; c < all.size(); ++c) {
    VecX along = VecX::Zero(fe.num_dofs());
    for (int k = 0; k < fe.num_nodes(); ++k) along(3 * k) = all.Phi(3 * k, c);
    const double share = along.dot(m.M * along) / all.Phi.col(c).dot(m.M * all.Phi.col(c));
    int& found = share > 0.5 ? found_axial : found_bending;
    if (found < (share > 0.5 ? axial : bending)) picked.push_back(c);
    ++found;
  }
  if (found_bending < bending || found_axial < axial)
    throw std::invalid_argument("mode selection: the beam has " + std::to_string(found_bending) + " bending and " +
                                std::to_string(found_axial) + " axial modes; asked for " + std::to_string(bending) +
                                " and " + std::to_string(axial) + " (more elements give more)");
  MatX Phi(fe.num_dofs(), 3 + static_cast<int>(picked.size()));
  Phi.leftCols(3) = all.Phi.leftCols(3);
  for (std::size_t j = 0; j < picked.size(); ++j) Phi.col(3 + static_cast<int>(j)) = all.Phi.col(picked[j]);
  return with_matrices(Phi, m.K, m.M, 3);
}

FlexibleExample flexible_pendulum(const FlexiblePendulumParameters& p, const BodyFactory& make_body) {
  FlexibleExample ex;
  FeModel fe;
  ex.data = beam_data(p.length, p.elements, square_section(p.E, p.rho, p.side), p.mass_type, p.basis, p.modes,
                      p.selection, {0}, fe);
  Model& m = ex.model;
  m.set_gravity(Vec2(0.0, -p.gravity));
  ex.flexible = m.add_flexible_body("beam", make_body(ex.data),
                                    frame_for_placement(fe, p.mass_type, Vec2::Zero(), 0.0));
  m.add_revolute("hinge", m.add_point(ground, Vec2::Zero(), "O"), m.add_node_point(ex.flexible, 0, "beam start"));
  m.add_node_point(ex.flexible, p.elements, "beam tip");
  ex.q0 = m.initial_guess();
  ex.qd0 = VecX::Zero(m.num_coordinates());
  set_elastic_state(ex, p.initial, "flexible_pendulum");
  return ex;
}

FlexibleExample flexible_slider_crank(const FlexibleSliderCrankParameters& p, const BodyFactory& make_body) {
  FlexibleExample ex;
  FeModel fe;
  const double b = p.rod_width > 0 ? p.rod_width : p.rod_side;
  const Section section = p.rod_height > 0 ? Section{p.E, p.rho, b * p.rod_height, b * std::pow(p.rod_height, 3) / 12}
                                           : square_section(p.E, p.rho, p.rod_side);
  ex.data = beam_data(p.rod_length, p.elements, section, p.mass_type, p.basis, p.modes, p.selection, {0, p.elements}, fe);
  Model& m = ex.model;
  m.set_gravity(Vec2(0.0, -p.gravity));
  // The rigid mechanism at crank angle A: crank tip T, slider at x_s on the x axis.
  const double l1 = p.crank_length, l2 = p.rod_length, A = p.crank_angle;
  const Vec2 tip = l1 * Vec2(std::cos(A), std::sin(A));
  if (!(l2 > std::abs(tip.y())))
    throw std::invalid_argument("flexible_slider_crank: the rod (" + readable(l2) + " m) cannot reach the guide");
  const Vec2 slider_at(tip.x() + std::sqrt(l2 * l2 - tip.y() * tip.y()), 0.0);
  const double slider_size = 0.02;
  const double crank_inertia = p.crank_inertia >= 0 ? p.crank_inertia : p.crank_mass * l1 * l1 / 12;
  const double slider_inertia = p.slider_inertia >= 0 ? p.slider_inertia : p.slider_mass * slider_size * slider_size / 6;
  const BodyId crank = m.add_body("crank", p.crank_mass, crank_inertia, Vec3(tip.x() / 2, tip.y() / 2, A));
  ex.flexible = m.add_flexible_body(
      "rod", make_body(ex.data),
      frame_for_placement(fe, p.mass_type, tip, std::atan2(slider_at.y() - tip.y(), slider_at.x() - tip.x())));
  const BodyId slider = m.add_body("slider", p.slider_mass, slider_inertia, Vec3(slider_at.x(), 0.0, 0.0));
  m.add_revolute("crank bearing", m.add_point(ground, Vec2::Zero(), "O"), m.add_point(crank, Vec2(-l1 / 2, 0), "crank hub"));
  m.add_revolute("crank pin", m.add_point(crank, Vec2(l1 / 2, 0), "crank tip"), m.add_node_point(ex.flexible, 0, "rod start"));
  m.add_revolute("wrist pin", m.add_node_point(ex.flexible, p.elements, "rod end"), m.add_point(slider, Vec2::Zero(), "slider"));
  m.add_translational("slide", m.add_point(ground, Vec2::Zero(), "guide"), m.find_point("slider"), Vec2::UnitX());
  if (p.elements % 2 == 0) m.add_node_point(ex.flexible, p.elements / 2, "rod mid");
  m.add_absolute_angle_driver("crank drive", crank, DriveFunction::linear(A, p.crank_speed));

  // The rod starts undeformed and without elastic velocity: the rigid velocities follow from the
  // velocity equation on the frame coordinates alone.
  ex.q0 = m.initial_guess();
  ex.qd0 = rigid_velocities(m, ex.q0, 0.0);
  set_elastic_state(ex, p.initial, "flexible_slider_crank");
  return ex;
}

DriveFunction spin_up_profile(double spin_rate, double spin_up_time) {
  const double W = spin_rate, T = spin_up_time;
  return DriveFunction::custom(
      [W, T](double t) {
        if (t >= T) return DriveValue{W * (t - T / 2), W, 0.0};
        const double c = T / (2 * pi), w = 2 * pi / T;
        return DriveValue{W / T * (t * t / 2 + c * c * (std::cos(w * t) - 1)), W / T * (t - c * std::sin(w * t)),
                          W / T * (1 - std::cos(w * t))};
      },
      "spin-up to " + readable(W) + " rad/s in " + readable(T) + " s");
}

FlexibleExample spin_up_beam(const SpinUpBeamParameters& p, const BodyFactory& make_body) {
  FlexibleExample ex;
  FeModel fe;
  ex.data = beam_data(p.length, p.elements, Section{p.E, p.rho, p.A, p.I}, p.mass_type, p.basis, p.modes, p.selection,
                      {0}, fe);
  Model& m = ex.model;
  const BodyId hub = m.add_body("hub", 1.0, 1.0, Vec3::Zero());
  ex.flexible = m.add_flexible_body("beam", make_body(ex.data), frame_for_placement(fe, p.mass_type, Vec2::Zero(), 0.0));
  m.add_revolute("hub bearing", m.add_point(ground, Vec2::Zero(), "O"), m.add_point(hub, Vec2::Zero(), "hub centre"));
  m.add_fixed("clamp", m.add_point(hub, Vec2::Zero(), "hub clamp"), m.add_node_point(ex.flexible, 0, "beam root"));
  m.add_node_point(ex.flexible, p.elements, "beam tip");
  m.add_absolute_angle_driver("spin-up", hub, spin_up_profile(p.spin_rate, p.spin_up_time));
  ex.q0 = m.initial_guess();
  ex.qd0 = VecX::Zero(m.num_coordinates());
  set_elastic_state(ex, p.initial, "spin_up_beam");
  return ex;
}

namespace {

struct BeamState {
  const DeformableBody& body;
  VecX q_body, zero;
  Vec3 frame;  // (R, theta) of the floating frame
  double length;
};

BeamState beam_state(const FlexibleExample& ex, const VecX& q) {
  const DeformableBody& beam = *ex.model.body(ex.flexible).deformable;
  const VecX q_body = ex.model.body_state(q, ex.flexible);
  const double length = (beam.node_position(beam.num_nodes() - 1) - beam.node_position(0)).norm();
  return {beam, q_body, VecX::Zero(q_body.size()), ex.model.body_coordinates(q, ex.flexible), length};
}

Vec2 node_global(const BeamState& b, int node) { return b.body.node_marker(node, b.q_body, b.zero).pose.head<2>(); }

}  // namespace

Vec2 beam_point(const FlexibleExample& ex, const VecX& q, double s) {
  const BeamState b = beam_state(ex, q);
  if (!(s >= 0 && s <= b.length))
    throw std::invalid_argument("beam_point: s = " + readable(s) + " m lies outside the beam (0 to " +
                                readable(b.length) + " m)");
  const Vec2 x0 = b.body.node_position(0);
  const Vec2 axis = (b.body.node_position(b.body.num_nodes() - 1) - x0) / b.length;
  const int last = b.body.num_nodes() - 1;
  int e = 0;  // the element [node e, node e + 1] that holds s
  while (e + 1 < last && (b.body.node_position(e + 1) - x0).dot(axis) <= s) ++e;
  const Vec2 xa = b.body.node_position(e), xb = b.body.node_position(e + 1);
  const double l = (xb - xa).norm(), xi = std::clamp((s - (xa - x0).dot(axis)) / l, 0.0, 1.0);
  const Vec2 along = (xb - xa) / l, across(-along.y(), along.x());
  const Mat2 A = rotation(b.frame.z());
  // Displacement (along, across) and rotation of a node, in the floating frame.
  auto local = [&](int node, const Vec2& x_bar) {
    const NodeMarker m = b.body.node_marker(node, b.q_body, b.zero);
    const Vec2 d = A.transpose() * (m.pose.head<2>() - b.frame.head<2>()) - x_bar;
    return Vec3(d.dot(along), d.dot(across), m.pose.z() - b.frame.z());
  };
  const Vec3 ua = local(e, xa), ub = local(e + 1, xb);
  const double h1 = 1 - 3 * xi * xi + 2 * xi * xi * xi, h2 = xi * (1 - xi) * (1 - xi);
  const double h3 = xi * xi * (3 - 2 * xi), h4 = xi * xi * (xi - 1);
  const double u = (1 - xi) * ua.x() + xi * ub.x();
  const double v = h1 * ua.y() + h2 * l * ua.z() + h3 * ub.y() + h4 * l * ub.z();
  return b.frame.head<2>() + A * (xa + (xi * l + u) * along + v * across);
}

double deflection_at(const FlexibleExample& ex, const VecX& q, double s) {
  const BeamState b = beam_state(ex, q);
  const Vec2 a = node_global(b, 0), c = beam_point(ex, q, s) - a;
  const Vec2 u = (node_global(b, b.body.num_nodes() - 1) - a).normalized();
  return u.x() * c.y() - u.y() * c.x();
}

double midspan_deflection(const FlexibleExample& ex, const VecX& q) {
  return deflection_at(ex, q, 0.5 * beam_state(ex, q).length);
}

}  // namespace fmbd
