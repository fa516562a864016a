#include "fmbd/mechanisms.hpp"

#include <algorithm>
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
