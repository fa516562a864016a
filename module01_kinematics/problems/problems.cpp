// Tutorial problems of module 1 (README.md in this folder): the DOF of a chain with a slider, the
// position of a body's point, and the Jacobian of a revolute joint. Every answer and every named
// mistake is computed by the engine on a model built here; the numbers come from the student's
// parameter stream (problems/problems.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/dof.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/model.hpp"
#include "fmbd/planar.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// ---- M01P1: DOF of a chain of links, with or without a slider at its tip -----------------

struct Chain {
  int links = 2;
  bool slider = false;
  int drivers = 0;
  std::vector<double> lengths;  // m
  std::vector<double> angles;   // deg, from the x axis
};

// Link k runs from joint k-1 to joint k (joint 0: the ground pivot O at the origin). Links
// 1..drivers carry an absolute-angle driver; the slider, if any, sits on a horizontal guide
// through the tip.
Model chain_model(const Chain& c, bool with_drivers) {
  Model m;
  Vec2 start = Vec2::Zero();
  PointId previous = m.add_point(ground, start, "O");
  BodyId body = ground;
  for (int k = 0; k < c.links; ++k) {
    const double phi = c.angles[k] * kDeg;
    const Vec2 end = start + c.lengths[k] * Vec2(std::cos(phi), std::sin(phi));
    const Vec2 mid = 0.5 * (start + end);
    const std::string name = "link " + std::to_string(k + 1);
    body = m.add_body(name, 1.0, 0.1, Vec3(mid.x(), mid.y(), phi));
    const PointId a = m.add_point(body, Vec2(-c.lengths[k] / 2, 0), name + " start");
    m.add_revolute("joint " + std::to_string(k), previous, a);
    if (with_drivers && k < c.drivers) m.add_absolute_angle_driver("motor " + std::to_string(k + 1), body, DriveFunction::constant(phi));
    previous = m.add_point(body, Vec2(c.lengths[k] / 2, 0), name + " end");
    start = end;
  }
  if (c.slider) {
    const BodyId slider = m.add_body("slider", 1.0, 0.1, Vec3(start.x(), start.y(), 0));
    const PointId s = m.add_point(slider, Vec2::Zero(), "slider pin");
    m.add_revolute("tip", previous, s);
    const PointId guide = m.add_point(ground, Vec2(0, start.y()), "guide");
    m.add_translational("guide", guide, s, Vec2::UnitX());
  }
  return m;
}

Problem dof_problem() {
  Problem p;
  p.id = "M01P1";
  p.title = "degrees of freedom of a driven chain";
  p.points = 2;
  p.tolerance = Tolerance(0, 0.01);
  p.make = [](Parameters& r) {
    Chain c;
    c.links = r.integer(2, 5);
    c.slider = r.integer(0, 1) == 1;
    c.drivers = r.integer(0, c.links - 1);
    for (int k = 0; k < c.links; ++k) {
      c.lengths.push_back(r.grid(0.10, 0.05, 13));
      c.angles.push_back((k % 2 ? -1 : 1) * r.grid(20, 5, 11));  // zig-zag: no two links in line
    }
    Variant v;
    v.statement = "A planar chain of " + std::to_string(c.links) +
                  " rigid links: link 1 is pinned to the ground at O = (0, 0), and link k + 1 is pinned to "
                  "the end of link k (revolute joints).";
    if (c.slider)
      v.statement += " The end of the last link is pinned to a slider (a rigid body) that moves on a horizontal "
                     "guide fixed to the ground (a translational joint).";
    else
      v.statement += " The end of the last link is free.";
    v.statement += c.drivers == 0 ? " No link is driven."
                   : c.drivers == 1 ? " Link 1 is driven by a motor that prescribes its angle (an absolute-angle driver)."
                                    : " Links 1 to " + std::to_string(c.drivers) +
                                          " are each driven by a motor that prescribes the link's angle (absolute-angle "
                                          "drivers).";
    v.statement += "\nThe links, from O: ";
    for (int k = 0; k < c.links; ++k)
      v.statement += (k ? ", " : "") + std::string("L") + std::to_string(k + 1) + " = " + format_value(c.lengths[k]) + " m at " +
                     format_value(c.angles[k]) + " deg";
    v.statement += ".\nHow many degrees of freedom does the mechanism have (drivers included)?";
    v.solve = [c] {
      const Model m = chain_model(c, true);
      const VecX q = m.initial_guess();
      const int n = m.num_coordinates();
      const int dof = degrees_of_freedom(m, q);
      const int rank = n - dof;
      const Model undriven = chain_model(c, false);
      Solution s;
      s.answer = Quantity::number(dof);
      s.mistakes.emplace_back("the ground counted as a body (3 coordinates too many)", Quantity::number(n + 3 - rank));
      s.mistakes.emplace_back("the drivers not subtracted (each removes one freedom)",
                              Quantity::number(degrees_of_freedom(undriven, undriven.initial_guess())));
      s.mistakes.emplace_back("one equation per joint (a revolute or a translational joint removes two freedoms)",
                              Quantity::number(n - static_cast<int>(m.constraints().size())));
      s.steps.push_back("bodies n_b = " + std::to_string(m.num_bodies()) + ", coordinates n = 3 n_b = " + std::to_string(n));
      s.steps.push_back("equations m = " + std::to_string(m.num_constraints()) + " (2 per revolute and translational joint, 1 per driver)");
      s.steps.push_back("rank C_q = " + std::to_string(rank));
      s.steps.push_back("DOF = n - rank C_q = " + std::to_string(dof));
      return s;
    };
    return v;
  };
  return p;
}

// ---- M01P2: global position of a point of a body ------------------------------------------

struct PointData {
  double x, y, phi_deg;  // m, m, deg
  double sx, sy;         // mm
};

Vec2 point_at(const PointData& d, double phi, const Vec2& R, double s_scale) {
  Model m;
  const BodyId b = m.add_body("body", 1.0, 0.1, Vec3(R.x(), R.y(), phi));
  const PointId P = m.add_point(b, s_scale * Vec2(d.sx, d.sy), "P");
  return point_position(m, P, m.initial_guess());
}

Problem position_problem() {
  Problem p;
  p.id = "M01P2";
  p.title = "global position of a point of a body";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m";
  p.make = [](Parameters& r) {
    PointData d{};
    d.x = r.grid(-0.50, 0.01, 101);
    d.y = r.grid(-0.50, 0.01, 101);
    d.phi_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);  // never a multiple of 90 deg
    d.sx = r.grid(40, 10, 27);
    d.sy = r.grid(-150, 10, 31);
    Variant v;
    v.statement = "A body's centroid is at R = (" + format_value(d.x) + ", " + format_value(d.y) + ") m and its body frame is turned by phi = " +
                  format_value(d.phi_deg) + " deg (counter-clockwise from the global x axis). A point P has the body-frame "
                  "coordinates s = (" + format_value(d.sx) + ", " + format_value(d.sy) + ") mm from the centroid.\n"
                  "Give the global position r_P of P.";
    v.solve = [d] {
      const Vec2 R(d.x, d.y);
      const double phi = d.phi_deg * kDeg;
      Solution s;
      const Vec2 r = point_at(d, phi, R, 1e-3);
      s.answer = vec2(r);
      s.mistakes.emplace_back("A^T instead of A: the point turned the wrong way", vec2(point_at(d, -phi, R, 1e-3)));
      s.mistakes.emplace_back("the rotation left out (R + s)", vec2(point_at(d, 0, R, 1e-3)));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos and sin as radians",
                              vec2(point_at(d, d.phi_deg, R, 1e-3)));
      s.mistakes.emplace_back("s in mm added to R in m", vec2(point_at(d, phi, R, 1.0)));
      s.mistakes.emplace_back("the centroid left out (A s only)", vec2(point_at(d, phi, Vec2::Zero(), 1e-3)));
      s.steps.push_back("phi = " + format_value(phi) + " rad, cos phi = " + format_value(std::cos(phi)) + ", sin phi = " + format_value(std::sin(phi)));
      s.steps.push_back("s = (" + format_value(d.sx * 1e-3) + ", " + format_value(d.sy * 1e-3) + ") m");
      s.steps.push_back("A s = " + format_quantity(vec2(r - R)) + " m");
      s.steps.push_back("r_P = R + A s = " + format_quantity(vec2(r)) + " m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M01P3: Jacobian of a revolute joint between the ground and a body -------------------

struct PinData {
  double sx, sy;    // m
  double phi_deg;
};

// C_q (2 x 3) of the revolute O (ground) - P (body) at angle phi, the pin at the origin.
MatX pin_jacobian(const PinData& d, double phi) {
  const Vec2 s(d.sx, d.sy);
  Model m;
  const Vec2 R = -(rotation(phi) * s);
  const BodyId b = m.add_body("body", 1.0, 0.1, Vec3(R.x(), R.y(), phi));
  const PointId O = m.add_point(ground, Vec2::Zero(), "O");
  const PointId P = m.add_point(b, s, "P");
  m.add_revolute("pin", O, P);
  return constraint_jacobian(m, m.initial_guess(), 0.0);
}

Quantity mat(const MatX& A) {
  std::vector<double> values;
  for (int r = 0; r < A.rows(); ++r)
    for (int c = 0; c < A.cols(); ++c) values.push_back(A(r, c));
  return Quantity::matrix(static_cast<int>(A.rows()), static_cast<int>(A.cols()), values);
}

Problem jacobian_problem() {
  Problem p;
  p.id = "M01P3";
  p.title = "Jacobian of a revolute joint to the ground";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::matrix;
  p.rows = 2;
  p.cols = 3;
  p.make = [](Parameters& r) {
    PinData d{};
    d.sx = -r.grid(0.10, 0.01, 31);
    d.sy = r.grid(-0.05, 0.01, 11);
    d.phi_deg = r.grid(5, 5, 17) + 90 * r.integer(0, 3);
    Variant v;
    v.statement = "A body (coordinates q = (x, y, phi)) is pinned to the ground at O = (0, 0) by a revolute joint at its "
                  "point P, s = (" + format_value(d.sx) + ", " + format_value(d.sy) + ") m in the body frame. The joint is written "
                  "C = r_O - r_P = 0 (the ground first).\nAt phi = " + format_value(d.phi_deg) +
                  " deg, give the Jacobian C_q = dC/dq (2 x 3, columns x, y, phi; entries in SI, no unit).";
    v.solve = [d] {
      const double phi = d.phi_deg * kDeg;
      const MatX Cq = pin_jacobian(d, phi);
      Solution s;
      s.answer = mat(Cq);
      s.mistakes.emplace_back("A^T instead of A (the wrong sign of phi in the third column)", mat(pin_jacobian(d, -phi)));
      s.mistakes.emplace_back("degrees against radians: phi in degrees put into cos and sin as radians",
                              mat(pin_jacobian(d, d.phi_deg)));
      // A s instead of A I~ s: the third column turned back by 90 degrees.
      MatX no_tilde = Cq;
      no_tilde.col(2) = rotation(-90 * kDeg) * Cq.col(2);
      s.mistakes.emplace_back("I~ left out: A s instead of A I~ s in the third column", mat(no_tilde));
      s.steps.push_back("phi = " + format_value(phi) + " rad");
      s.steps.push_back("A I~ s = " + format_quantity(vec2(-Cq.col(2))) + " m");
      s.steps.push_back("C_q = -[I, A I~ s] = " + format_quantity(mat(Cq)));
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module01_problems() { return {dof_problem(), position_problem(), jacobian_problem()}; }

}  // namespace fmbd::problems
