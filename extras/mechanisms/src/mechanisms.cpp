#include "fmbd/mechanisms.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmbd::mechanisms {

SevenBodyLoop seven_body_loop(const SevenBodyLoopParameters& p) {
  // Joint positions at t = 0 [m].
  const Vec2 G1(0, 0), G2(0.40, 0), G3(0.75, 0), G4(1.10, 0), anchor(1.40, 0.60);
  const Vec2 A(0.08, 0.06), B(0.35, 0.32), C(0.70, 0.36), D(1.05, 0.34);
  const Vec2 E = 0.5 * (G2 + B), F = 0.5 * (G3 + C);
  struct Link {
    const char* name;
    std::vector<std::pair<const char*, Vec2>> joints;
  };
  const std::vector<Link> links = {{"crank", {{"G1", G1}, {"A", A}}},
                                   {"coupler", {{"A", A}, {"B", B}}},
                                   {"rocker 1", {{"G2", G2}, {"B", B}, {"E", E}}},
                                   {"link 2", {{"E", E}, {"C", C}}},
                                   {"rocker 2", {{"G3", G3}, {"C", C}, {"F", F}}},
                                   {"link 3", {{"F", F}, {"D", D}}},
                                   {"rocker 3", {{"G4", G4}, {"D", D}}}};
  SevenBodyLoop out;
  Model& m = out.model;
  m.set_gravity(Vec2(0, -p.gravity));
  std::vector<BodyId> bodies;
  for (const Link& link : links) {
    // A slender rod of 2 kg per metre between its two outer joints, centroid at their middle.
    const Vec2 a = link.joints[0].second, b = link.joints[1].second;
    const double L = (b - a).norm(), mass = 2 * L * p.mass_scale;
    const Vec2 centre = 0.5 * (a + b);
    bodies.push_back(m.add_body(link.name, mass, mass * L * L / 12, Vec3(centre.x(), centre.y(), 0.0)));
    for (const auto& [joint, r] : link.joints) m.add_point_at(bodies.back(), r, std::string(link.name) + " " + joint);
  }
  for (const auto& [name, r] : {std::pair<const char*, Vec2>{"G1", G1}, {"G2", G2}, {"G3", G3}, {"G4", G4}})
    m.add_point_at(ground, r, std::string("ground ") + name);
  m.add_point_at(ground, anchor, "ground anchor");
  auto revolute = [&](const std::string& joint, const std::string& a, const std::string& b) {
    m.add_revolute(joint, m.find_point(a + " " + joint), m.find_point(b + " " + joint));
  };
  revolute("G1", "ground", "crank");
  revolute("A", "crank", "coupler");
  revolute("B", "coupler", "rocker 1");
  revolute("G2", "ground", "rocker 1");
  revolute("E", "rocker 1", "link 2");
  revolute("C", "link 2", "rocker 2");
  revolute("G3", "ground", "rocker 2");
  revolute("F", "rocker 2", "link 3");
  revolute("D", "link 3", "rocker 3");
  revolute("G4", "ground", "rocker 3");
  m.add_torque("motor", bodies[0], DriveFunction::constant(p.torque * p.mass_scale));
  const double rest = 0.8 * (anchor - D).norm();
  m.add_tsda("spring", m.find_point("rocker 3 D"), m.find_point("ground anchor"), p.stiffness * p.mass_scale, rest,
             p.damping * p.mass_scale);
  out.q0 = m.initial_guess();
  out.qd0 = VecX::Zero(m.num_coordinates());
  return out;
}

}  // namespace fmbd::mechanisms

namespace fmbd::mechanisms {

namespace {
constexpr double kGravity = 9.81;
}

FourBarChain four_bar_chain(int windows, const Vec2& origin) {
  if (windows < 1) throw std::invalid_argument("four_bar_chain: at least one window, got " + std::to_string(windows));
  FourBarChain out;
  out.windows = windows;
  Model& m = out.model;
  m.set_gravity(Vec2(0, -kGravity));
  std::vector<BodyId> crank;
  std::vector<double> q, qd;
  for (int k = 0; k <= windows; ++k) {
    const std::string name = "crank " + std::to_string(k);
    crank.push_back(m.add_body(name, 1.0, 1.0 / 12));
    m.add_revolute("pivot " + std::to_string(k), m.add_point(ground, origin + Vec2(k, 0), "A" + std::to_string(k)),
                   m.add_point(crank.back(), Vec2(0, -0.5), "foot of " + name));
    q.insert(q.end(), {origin.x() + k, origin.y() + 0.5, 0.0});
    qd.insert(qd.end(), {0.5, 0.0, -1.0});
  }
  for (int k = 0; k < windows; ++k) {
    const std::string name = "coupler " + std::to_string(k);
    const BodyId coupler = m.add_body(name, 1.0, 1.0 / 12);
    for (int side : {0, 1})
      m.add_revolute(name + " at B" + std::to_string(k + side),
                     m.add_point(crank[k + side], Vec2(0, 0.5), "B" + std::to_string(k + side) + " " + name),
                     m.add_point(coupler, Vec2(side ? 0.5 : -0.5, 0), name + " end " + std::to_string(side)));
    q.insert(q.end(), {origin.x() + k + 0.5, origin.y() + 1.0, 0.0});
    qd.insert(qd.end(), {1.0, 0.0, 0.0});
  }
  out.q0 = Eigen::Map<const VecX>(q.data(), static_cast<Eigen::Index>(q.size()));
  out.qd0 = Eigen::Map<const VecX>(qd.data(), static_cast<Eigen::Index>(qd.size()));
  return out;
}

std::vector<double> four_bar_chain_theta(int windows, double dt, double T) {
  const long outputs = std::lround(T / dt), per = static_cast<long>(std::ceil(dt / 1e-5 - 1e-9));
  if (!(dt > 0) || outputs < 1 || std::abs(outputs * dt - T) > 1e-9 * T)
    throw std::invalid_argument("four_bar_chain_theta: T must be a positive multiple of dt");
  const double N = windows, J = (N + 1) / 3 + N, G = kGravity * ((N + 1) / 2 + N), h = dt / static_cast<double>(per);
  auto f = [&](double th) { return -G * std::cos(th) / J; };
  double th = M_PI / 2, w = -1.0;
  std::vector<double> out{th};
  for (long i = 0; i < outputs; ++i) {
    for (long s = 0; s < per; ++s) {
      const double a1 = w, b1 = f(th);
      const double a2 = w + 0.5 * h * b1, b2 = f(th + 0.5 * h * a1);
      const double a3 = w + 0.5 * h * b2, b3 = f(th + 0.5 * h * a2);
      const double a4 = w + h * b3, b4 = f(th + h * a3);
      th += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      w += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
    }
    out.push_back(th);
  }
  return out;
}

FourBarChainError four_bar_chain_error(const Trajectory& run, const std::vector<double>& theta) {
  if (run.t.size() != theta.size())
    throw std::invalid_argument("four_bar_chain_error: " + std::to_string(run.t.size()) + " recorded points for " +
                                std::to_string(theta.size()) + " exact ones");
  FourBarChainError e;
  for (std::size_t i = 0; i < run.t.size(); ++i) {
    const Vec3 c = run.q[i].head<3>();  // crank 0: its centre and angle (0 standing vertical)
    const Vec2 B0 = c.head<2>() + 0.5 * Vec2(-std::sin(c(2)), std::cos(c(2)));
    e.position = std::max(e.position, (B0 - Vec2(std::cos(theta[i]), std::sin(theta[i]))).cwiseAbs().maxCoeff());
    e.energy = std::max(e.energy, std::abs(run.energy[i] - run.energy.front()));
  }
  return e;
}

}  // namespace fmbd::mechanisms
