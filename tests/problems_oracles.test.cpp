// Project tests of the tutorial problems, continued from problems.test.cpp: each engine answer
// agrees with an independent closed form, on ordinary and extreme variants.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "fmbd/forward_dynamics.hpp"
#include "fmbd/model.hpp"
#include "fmbd/reactions.hpp"
#include "grading.hpp"
#include "modules.hpp"
#include "problems.hpp"
#include "problems_support.hpp"

using namespace fmbd::problems;
using namespace fmbd::problems::testing;

// ---- the oracles: closed forms of each answer from the drawn parameters -------------------

namespace {

using Oracle = std::function<Quantity(const std::vector<double>&)>;

// Modules 1 and 2: kinematics, constraints and Newton-Raphson.
void add_kinematics_oracles(std::map<std::string, Oracle>& o) {
  o["M01P1"] = [](const std::vector<double>& p) {  // links, slider, drivers: Gruebler
    const int links = static_cast<int>(p[0]), slider = static_cast<int>(p[1]), drivers = static_cast<int>(p[2]);
    return Quantity::number(3 * (links + slider) - 2 * links - 4 * slider - drivers);
  };
  o["M01P2"] = [](const std::vector<double>& p) {  // x, y, phi, quadrant, s_x, s_y [mm]
    const double phi = (p[2] + 90 * p[3]) * kDeg, sx = p[4] / 1000, sy = p[5] / 1000;
    return Quantity::vector({p[0] + std::cos(phi) * sx - std::sin(phi) * sy, p[1] + std::sin(phi) * sx + std::cos(phi) * sy});
  };
  o["M01P3"] = [](const std::vector<double>& p) {  // -s_x, s_y, phi, quadrant
    const double sx = -p[0], sy = p[1], phi = (p[2] + 90 * p[3]) * kDeg;
    const double a = -std::cos(phi) * sy - std::sin(phi) * sx, b = -std::sin(phi) * sy + std::cos(phi) * sx;
    return Quantity::matrix(2, 3, {-1, 0, -a, 0, -1, -b});
  };
  o["M02P1"] = [](const std::vector<double>& p) {  // L, phi0, direction, distance: scalar Newton on L cos phi = x_B
    const double L = p[0], phi0 = p[1] * kDeg, target = (p[1] + (p[2] ? 1 : -1) * p[3]) * kDeg;
    const double x_B = std::round(L * std::cos(target) * 1000) / 1000;
    return Quantity::number(phi0 + (L * std::cos(phi0) - x_B) / (L * std::sin(phi0)));
  };
  o["M02P2"] = [](const std::vector<double>& p) {  // r, l, A, half turn, rpm
    const double r = p[0], l = p[1], A = (p[2] + 180 * p[3]) * kDeg, omega = p[4] * 2 * kPi / 60;
    const double s = std::sin(A), c = std::cos(A);
    return Quantity::number(omega * (-r * s - r * r * s * c / std::sqrt(l * l - r * r * s * s)));
  };
  o["M02P3"] = [](const std::vector<double>& p) {
    const double pi = (p[0] + 90 * p[1]) * kDeg, pj = (p[2] + 90 * p[3]) * kDeg;
    const double wi = (p[4] ? 1 : -1) * p[5], wj = (p[6] ? 1 : -1) * p[7];
    const double six = p[8], siy = p[9], sjx = -p[10], sjy = p[11];
    auto As = [](double phi, double x, double y) {
      return std::vector<double>{std::cos(phi) * x - std::sin(phi) * y, std::sin(phi) * x + std::cos(phi) * y};
    };
    const auto a = As(pi, six, siy), b = As(pj, sjx, sjy);
    return Quantity::vector({a[0] * wi * wi - b[0] * wj * wj, a[1] * wi * wi - b[1] * wj * wj});
  };
}

// Modules 3 and 4: Lagrange's equations and integration.
void add_dynamics_oracles(std::map<std::string, Oracle>& o) {
  o["M03P1"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega: F = m a_G - m g
    const double m = p[0], L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], g = 9.81;
    return Quantity::vector({-m * L / 2 * w * w * std::cos(phi), -m * L / 2 * w * w * std::sin(phi) + m * g});
  };
  o["M03P2"] = [](const std::vector<double>& p) {  // r, l, A, half turn, m1, m2, m3
    const double r = p[0], l = p[1], A = (p[2] + 180 * p[3]) * kDeg, m1 = p[4], m2 = p[5], m3 = p[6];
    const double beta = std::asin(-r * std::sin(A) / l);
    const double beta_dot = -r * std::cos(A) / (l * std::cos(beta));
    const double vx = -r * std::sin(A) - l / 2 * std::sin(beta) * beta_dot;
    const double vy = r * std::cos(A) + l / 2 * std::cos(beta) * beta_dot;
    const double x_dot = -r * std::sin(A) - l * std::sin(beta) * beta_dot;
    return Quantity::number(m1 * r * r / 3 + m2 * (vx * vx + vy * vy) + m2 * l * l / 12 * beta_dot * beta_dot +
                            m3 * x_dot * x_dot);
  };
  o["M03P3"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega, sign, alpha
    const double m = p[0], L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, alpha = (p[6] ? 1 : -1) * p[7], g = 9.81;
    return Quantity::number(m * L * L / 3 * alpha + m * g * L / 2 * std::cos(phi));
  };
  // m, w, H, y_1, H - y_2, m_b, w - d. Statics of the door: the moment of the loads about the hinge
  // axis, g (m w/2 + m_b d), is taken by the couple of the horizontal forces, -F_2x = F_1x = that / h;
  // the vertical forces have only their sum W fixed, and the least F_1y^2 + F_2y^2 is W/2 each.
  o["M03P4"] = [](const std::vector<double>& p) {
    const double m = p[0], w = p[1], h = p[2] - p[4] - p[3], mb = p[5], d = w - p[6], g = 9.81;
    const double F = g * (m * w / 2 + mb * d) / h, W = (m + mb) * g;
    return Quantity::vector({F, W / 2, -F, W / 2});
  };
  o["M04P1"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega: J_O phi_ddot = moment of m g
    const double L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], g = 9.81;
    const double alpha = -3 * g * std::cos(phi) / (2 * L), c = std::cos(phi), s = std::sin(phi);
    return Quantity::vector({L / 2 * (-alpha * s - w * w * c), L / 2 * (alpha * c - w * w * s), alpha});
  };
  o["M04P2"] = [](const std::vector<double>& p) {  // m, k, c, x0 [mm], v0, h [ms]: y1 = (sum_{j<=4} (hA)^j / j!) y0
    const double m = p[0], k = p[1], c = p[2], h = p[5] / 1000;
    // z <- y0, then z <- hA z / j, accumulated: the RK4 polynomial of the linear y' = A y.
    double x = p[3] / 1000, v = p[4], sx = x, sv = v;
    for (int j = 1; j <= 4; ++j) {
      const double nx = h * v / j, nv = h * (-k * x - c * v) / (m * j);
      x = nx, v = nv, sx += x, sv += v;
    }
    return Quantity::number(sv);
  };
  o["M04P3"] = [](const std::vector<double>& p) {  // m, L, phi, quadrant, sign, omega, h [ms]
    const double L = p[1], phi = (p[2] + 90 * p[3]) * kDeg, w = (p[4] ? 1 : -1) * p[5], hw = p[6] / 1000 * w;
    return Quantity::vector({L / 2 * (std::cos(phi + hw) - std::cos(phi) + hw * std::sin(phi)),
                             L / 2 * (std::sin(phi + hw) - std::sin(phi) - hw * std::cos(phi))});
  };
}

// Modules 5 and 6: finite elements, modes and reduction.
void add_fe_oracles(std::map<std::string, Oracle>& o) {
  o["M05P1"] = [](const std::vector<double>& p) {  // material, a [mm], L, alpha, quadrant: 6 E I / L^2 (-s, c)
    const double E = p[0] ? 70e9 : 210e9, a = p[1] / 1000, L = p[2], alpha = (p[3] + 90 * p[4]) * kDeg;
    const double k = 6 * E * (a * a * a * a / 12) / (L * L);
    return Quantity::vector({-k * std::sin(alpha), k * std::cos(alpha)});
  };
  o["M05P2"] = [](const std::vector<double>& p) {  // material, a [mm], L: 24 E I / L_e^3 against 312 m_e / 420
    const double E = p[0] ? 70e9 : 210e9, rho = p[0] ? 2700 : 7850, a = p[1] / 1000, Le = p[2] / 2;
    const double K = 24 * E * (a * a * a * a / 12) / (Le * Le * Le), M = 312 * rho * a * a * Le / 420;
    return Quantity::number(std::sqrt(K / M) / (2 * kPi));
  };
  o["M05P3"] = [](const std::vector<double>& p) {  // material, a [mm], L, alpha, quadrant
    const double rho = p[0] ? 2700 : 7850, a = p[1] / 1000, m = rho * a * a * p[2], alpha = (p[3] + 90 * p[4]) * kDeg;
    const double c = std::cos(alpha), s = std::sin(alpha);
    return Quantity::vector({m / 3 * c * c + 156 * m / 420 * s * s, (m / 3 - 156 * m / 420) * c * s});
  };
  // The L-shaped frame (material, a [mm], L1, L2): leg masses in proportion to L1 and L2, the
  // centroid of the legs' centres; the rotation about it, and J by the parallel-axis theorem.
  o["M06P1"] = [](const std::vector<double>& p) {
    const double L1 = p[2], L2 = p[3];
    const double cx = (L1 * L1 / 2 + L2 * L1) / (L1 + L2), cy = (L2 * L2 / 2) / (L1 + L2);
    return Quantity::vector({-(L2 - cy), L1 - cx});
  };
  o["M06P2"] = [](const std::vector<double>& p) {  // short, long, long first: the cubic 3 xi^2 - 2 xi^3
    const double L = p[0] + p[1], xi = (p[2] ? p[1] : p[0]) / L;
    return Quantity::vector({3 * xi * xi - 2 * xi * xi * xi, 6 * (xi - xi * xi) / L});
  };
  o["M06P3"] = [](const std::vector<double>& p) {
    const double rho = p[0] ? 2700 : 7850, A = (p[1] / 1000) * (p[1] / 1000), L1 = p[2], L2 = p[3];
    const double m1 = rho * A * L1, m2 = rho * A * L2;
    const double cx = (m1 * L1 / 2 + m2 * L1) / (m1 + m2), cy = m2 * L2 / 2 / (m1 + m2);
    const double d1 = (L1 / 2 - cx) * (L1 / 2 - cx) + cy * cy, d2 = (L1 - cx) * (L1 - cx) + (L2 / 2 - cy) * (L2 / 2 - cy);
    return Quantity::number(m1 * (L1 * L1 / 12 + d1) + m2 * (L2 * L2 / 12 + d2));
  };
}

// Modules 7 and 8: the intuitive and the full floating frame of reference.
void add_flexible_oracles(std::map<std::string, Oracle>& o) {
  // The spinning dumbbell (m, d, k, Omega): one mass on its circle, m Omega^2 (d + u) = 2k u.
  o["M07P1"] = [](const std::vector<double>& p) {
    const double m = p[0], d = p[1], k = p[2], w2 = p[3] * p[3];
    return Quantity::vector({0.0, m * w2 * d / (2 * k - m * w2)});
  };
  o["M07P2"] = [](const std::vector<double>& p) {  // ..., q_f, sign, |q_f_dot|: each mass at radius d + q_f
    const double m = p[0], d = p[1], w2 = p[3] * p[3], q = p[4], qd = (p[5] ? 1 : -1) * p[6];
    return Quantity::vector({m * (w2 * d * d + qd * qd), m * (w2 * (d + q) * (d + q) + qd * qd)});
  };
  // theta, quadrant, x_bar, y_bar, phi_x, phi_y, q_f (sign, size), F_x (sign, size), F_y (sign, size), k, m:
  // the virtual work of F on the node's velocity per theta_dot and per q_f_dot.
  o["M07P3"] = [](const std::vector<double>& p) {
    const double th = (p[0] + 90 * p[1]) * kDeg, c = std::cos(th), s = std::sin(th);
    const double q = (p[6] ? 1 : -1) * p[7], Fx = (p[8] ? 1 : -1) * p[9], Fy = (p[10] ? 1 : -1) * p[11], k = p[12];
    const double X = p[2] + p[4] * q, Y = p[3] + p[5] * q;
    const double Q_theta = Fx * (-s * X - c * Y) + Fy * (c * X - s * Y);
    const double Q_f = Fx * (c * p[4] - s * p[5]) + Fy * (s * p[4] + c * p[5]) - k * q;
    return Quantity::vector({Q_theta, Q_f});
  };
  // Two point masses m at (-d, 0), (d, 0) with the shape (-a, b1), (a, b2): (m, d, a, b1, b2, ...).
  o["M08P1"] = [](const std::vector<double>& p) {  // ..., theta, quadrant, omega, q_f
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4];
    const double th = (p[5] + 90 * p[6]) * kDeg, w2 = p[7] * p[7], q = p[8];
    const double F = w2 * m * q * (b1 + b2);  // the centrifugal force of the moved mass centre, frame y
    return Quantity::vector({-std::sin(th) * F, std::cos(th) * F, 0.0,
                             w2 * m * (2 * a * d + q * (2 * a * a + b1 * b1 + b2 * b2))});
  };
  o["M08P2"] = [](const std::vector<double>& p) {  // ..., q_f
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4], q = p[5];
    const double x = d + a * q;
    return Quantity::vector({m * (2 * x * x + b1 * b1 * q * q + b2 * b2 * q * q), m * d * (b2 - b1)});
  };
  o["M08P3"] = [](const std::vector<double>& p) {  // ..., omega (sign, size), q_f, q_f_dot (sign, size)
    const double m = p[0], d = p[1], a = p[2], b1 = p[3], b2 = p[4];
    const double w = (p[5] ? 1 : -1) * p[6], q = p[7], qd = (p[8] ? 1 : -1) * p[9];
    return Quantity::number(-2 * w * qd * m * (2 * a * d + q * (2 * a * a + b1 * b1 + b2 * b2)));
  };
  o["M08P4"] = [](const std::vector<double>& p) {  // m, d, k, Omega: as M07P1's true stretch
    const double m = p[0], d = p[1], k = p[2], w2 = p[3] * p[3];
    return Quantity::number(m * w2 * d / (2 * k - m * w2));
  };
  // m, L, r_h, Omega, Omega/omega_1: EI to three digits; the cubic tip-load shape gives
  // int v'^2 = 6/5 v^2/L, so omega^2 = omega_1^2 + (6 (r_h + L)/(5 L) - 1) Omega^2.
  o["M08P5"] = [](const std::vector<double>& p) {
    const double m = p[0], L = p[1], r = p[2], W = p[3];
    const double exact = m * std::pow(W / p[4], 2) * L * L * L / 3;
    const double digits = std::pow(10.0, std::floor(std::log10(exact)) - 2);
    const double EI = std::round(exact / digits) * digits;
    const double w1_2 = 3 * EI / (m * L * L * L);
    return Quantity::vector({std::sqrt(w1_2), std::sqrt(w1_2 + (6 * (r + L) / (5 * L) - 1) * W * W)});
  };
}

// The drawn parameters of each problem, in the order its make() draws them.
std::map<std::string, Oracle> oracles() {
  std::map<std::string, Oracle> o;
  add_kinematics_oracles(o);
  add_dynamics_oracles(o);
  add_fe_oracles(o);
  add_flexible_oracles(o);
  return o;
}

// The ratio that makes a variant extreme, per problem (the grid's far corner is looked for).
std::map<std::string, std::function<double(const std::vector<double>&)>> extremes() {
  std::map<std::string, std::function<double(const std::vector<double>&)>> e;
  e["M01P1"] = [](const std::vector<double>& p) { return p[0] + p[1]; };                    // longest chain
  e["M01P2"] = [](const std::vector<double>& p) { return -std::hypot(p[0], p[1]); };        // centroid near O
  e["M01P3"] = [](const std::vector<double>& p) { return -p[0]; };                          // shortest arm
  e["M02P1"] = [](const std::vector<double>& p) { return p[3] / p[0]; };                    // far guess, short link
  e["M02P2"] = [](const std::vector<double>& p) { return p[0] / p[1]; };                    // r / l near lock
  e["M02P3"] = [](const std::vector<double>& p) { return p[5] / p[7]; };                    // unequal rates
  e["M03P1"] = [](const std::vector<double>& p) { return p[5] * p[5] * p[1] / p[0]; };     // fast, long, light
  e["M03P2"] = [](const std::vector<double>& p) { return p[6] / (p[4] + p[5]) + p[0] / p[1]; };  // heavy slider
  e["M03P3"] = [](const std::vector<double>& p) { return p[7] * p[1]; };                   // fast spin-up
  e["M03P4"] = [](const std::vector<double>& p) { return p[1] / (p[2] - p[3] - p[4]); };  // wide door, close hinges
  e["M04P1"] = [](const std::vector<double>& p) { return p[5] * p[5] * p[1]; };            // fast, long
  e["M04P2"] = [](const std::vector<double>& p) { return std::sqrt(p[1] / p[0]) * p[5]; };  // omega h
  e["M04P3"] = [](const std::vector<double>& p) { return p[5] * p[6]; };                   // h phi_dot
  e["M05P1"] = [](const std::vector<double>& p) { return p[2] / p[1]; };                   // slender
  e["M05P2"] = [](const std::vector<double>& p) { return p[2] / p[1]; };                   // slender, low f_1
  e["M05P3"] = [](const std::vector<double>& p) { return p[1] * p[1] * p[2]; };            // heavy
  e["M06P1"] = [](const std::vector<double>& p) { return p[3] / p[2]; };                   // tall frame
  e["M06P2"] = [](const std::vector<double>& p) { return (p[2] ? p[1] : p[0]) / (p[0] + p[1]); };  // xi_1
  e["M06P3"] = [](const std::vector<double>& p) { return p[1] * p[1] * (p[2] + p[3]); };   // heavy, large
  e["M07P1"] = [](const std::vector<double>& p) { return p[0] * p[3] * p[3] / p[2]; };    // spin against spring
  e["M07P2"] = [](const std::vector<double>& p) { return p[4] / p[1]; };                   // stretch against d
  e["M07P3"] = [](const std::vector<double>& p) { return p[5] * p[7] / p[2]; };            // deformation against x_bar
  e["M08P1"] = [](const std::vector<double>& p) { return p[7] * p[7] * p[8]; };            // fast spin, large q_f
  e["M08P2"] = [](const std::vector<double>& p) { return p[5] * (p[3] + p[4]) / p[1]; };   // large deformation
  e["M08P3"] = [](const std::vector<double>& p) { return p[6] * p[9]; };                   // fast spin and rate
  e["M08P4"] = [](const std::vector<double>& p) { return p[0] * p[3] * p[3] / p[2]; };    // spin against spring
  e["M08P5"] = [](const std::vector<double>& p) { return p[4] * (p[2] + p[1]) / p[1]; };  // fast spin, large hub
  return e;
}

}  // namespace

TEST_CASE("each engine answer agrees with an independent closed form", "[problems]") {
  const auto oracle = oracles();
  const auto extreme = extremes();
  for (const Problem& p : all_problems()) {
    REQUIRE(oracle.count(p.id) == 1);
    // Ada, and the most and least extreme of 300 students.
    std::string lowest = "student 0", highest = "student 0";
    double low = 1e300, high = -1e300;
    for (int k = 0; k < 300; ++k) {
      const std::string name = "student " + std::to_string(k);
      const double x = extreme.at(p.id)(make_variant(p, name).parameters);
      if (x < low) low = x, lowest = name;
      if (x > high) high = x, highest = name;
    }
    for (const std::string& student : {std::string("Ada Lovelace"), lowest, highest}) {
      const Variant v = make_variant(p, student);
      const Quantity engine = v.solve().answer;
      const Quantity closed = oracle.at(p.id)(v.parameters);
      INFO(p.id << " of " << student << ": engine " << format_quantity(engine, 15) << ", closed form "
                << format_quantity(closed, 15));
      CHECK(within(engine, closed, Tolerance(1e-9, 1e-12)));
    }
  }
}

TEST_CASE("M03P4's hinge forces are those of the multipliers module 4's forward dynamics reports", "[problems]") {
  // The door of the statement, built here from the drawn parameters (m, w, H, y_1, H - y_2, m_b,
  // w - d) and released at rest: forward_dynamics (solve_augmented's rank-revealing path) finds
  // q_ddot = 0, one dependent row, and the multipliers of least norm, whose hinge forces are the
  // problem's answer.
  const Problem door = module03_problems().at(3);
  REQUIRE(door.id == "M03P4");
  for (const std::string& student : kStudents) {
    const Variant v = make_variant(door, student);
    const std::vector<double>& p = v.parameters;
    const double m = p[0], w = p[1], H = p[2], y1 = p[3], y2 = p[2] - p[4], mb = p[5], d = w - p[6], g = 9.81;
    fmbd::Model model;
    model.set_gravity(fmbd::Vec2(0, -g));
    const fmbd::BodyId leaf = model.add_body("door", m, m * (w * w + H * H) / 12, fmbd::Vec3(w / 2, H / 2, 0));
    const int lower = model.add_revolute("lower", model.add_point(fmbd::ground, fmbd::Vec2(0, y1), "lower frame"),
                                         model.add_point_at(leaf, fmbd::Vec2(0, y1), "lower leaf"));
    const int upper = model.add_revolute("upper", model.add_point(fmbd::ground, fmbd::Vec2(0, y2), "upper frame"),
                                         model.add_point_at(leaf, fmbd::Vec2(0, y2), "upper leaf"));
    model.add_point_force("bag", model.add_point_at(leaf, fmbd::Vec2(d, 1.0), "handle"), fmbd::Vec2(0, -mb * g));
    const fmbd::VecX q = model.initial_guess();
    const fmbd::Accelerations a = fmbd::forward_dynamics(model, q, fmbd::VecX::Zero(3), 0.0);
    INFO(student);
    CHECK(a.qdd.norm() < 1e-9);
    CHECK(a.rank_deficit == 1);
    const fmbd::Vec2 F1 = fmbd::joint_reaction(model, lower, q, a.lambda).on_j.force;
    const fmbd::Vec2 F2 = fmbd::joint_reaction(model, upper, q, a.lambda).on_j.force;
    const Quantity engine = Quantity::vector({F1.x(), F1.y(), F2.x(), F2.y()});
    const Quantity answer = v.solve().answer;
    INFO("forward dynamics " << format_quantity(engine, 15) << ", M03P4 " << format_quantity(answer, 15));
    CHECK(within(engine, answer, Tolerance(1e-9, 1e-9)));
  }
}

TEST_CASE("the flexible bodies of modules 7 and 8 deform by at most 5 % of their size", "[problems]") {
  // The largest displacement of a mass or node against its distance from the frame's origin, from
  // the drawn parameters (M08P5 asks for small vibrations: no finite deformation).
  std::map<std::string, std::function<double(const std::vector<double>&)>> deformation;
  auto stretch = [](const std::vector<double>& p) {  // m, d, k, Omega: the true stretch over d
    const double w2 = p[0] * p[3] * p[3];
    return w2 / (2 * p[2] - w2);
  };
  deformation["M07P1"] = stretch;
  deformation["M08P4"] = stretch;
  deformation["M07P2"] = [](const std::vector<double>& p) { return p[4] / p[1]; };
  deformation["M07P3"] = [](const std::vector<double>& p) {
    return std::hypot(p[4], p[5]) * p[7] / std::hypot(p[2], p[3]);
  };
  auto dumbbell = [](int q_index) {  // (m, d, a, b1, b2, ...): the mass with the larger shape, b2 > b1
    return [q_index](const std::vector<double>& p) { return std::hypot(p[2], p[4]) * p[q_index] / p[1]; };
  };
  deformation["M08P1"] = dumbbell(8);
  deformation["M08P2"] = dumbbell(5);
  deformation["M08P3"] = dumbbell(7);
  for (const Problem& p : all_problems()) {
    if (deformation.count(p.id) == 0) continue;
    double worst = 0;
    std::string who;
    for (int k = 0; k < 300; ++k) {
      const std::string name = "student " + std::to_string(k);
      const double x = deformation.at(p.id)(make_variant(p, name).parameters);
      if (x > worst) worst = x, who = name;
    }
    INFO(p.id << ": " << who << " deforms the body by " << 100 * worst << " % of its size");
    CHECK(worst <= 0.05);
    CHECK(worst > 0.0);
  }
}
