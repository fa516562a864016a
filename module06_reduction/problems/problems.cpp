// Tutorial problems of module 6 (README.md in this folder): the rotation mode of the tip of a free
// L-shaped frame, a Craig-Bampton constraint mode of a beam with joints at both ends, and the
// entry M_bar[theta, theta] of the reduced mass matrix of the L-shaped frame. Every answer and
// every named mistake is computed by the engine (assembly, rigid-body modes, modal truncation,
// Craig-Bampton).
#include <string>
#include <vector>

#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/reduction.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// A free L-shaped frame: node 0 at the origin, node 1 at (L1, 0), node 2 at (L1, L2); one
// element per leg, a square section of side a [mm].
struct Frame {
  int material = 0;
  double a_mm = 20;
  double L1 = 1, L2 = 1;  // m
};

Section frame_section(const Frame& f) {
  const Material& mat = kMaterials[f.material];
  return square_section(mat.E, mat.rho, f.a_mm * 1e-3);
}

FeModel l_frame(const Frame& f) {
  FeModel fe;
  fe.add_node(Vec2(0, 0));
  fe.add_node(Vec2(f.L1, 0));
  fe.add_node(Vec2(f.L1, f.L2));
  fe.add_element(0, 1, frame_section(f));
  fe.add_element(1, 2, frame_section(f));
  return fe;
}

// One leg alone, as its own free body.
FeModel leg(const Vec2& a, const Vec2& b, const Section& section) {
  FeModel fe;
  fe.add_node(a);
  fe.add_node(b);
  fe.add_element(0, 1, section);
  return fe;
}

Frame draw_frame(Parameters& r) {
  Frame f;
  f.material = r.integer(0, 1);
  f.a_mm = r.grid(10, 2, 16);
  f.L1 = r.grid(0.40, 0.05, 17);
  f.L2 = r.grid(0.30, 0.05, 15);
  return f;
}

std::string frame_text(const Frame& f) {
  const Material& mat = kMaterials[f.material];
  return "A free L-shaped frame has node 0 at (0, 0), node 1 at (L1, 0) and node 2 at (L1, L2), with L1 = " +
         format_value(f.L1) + " m and L2 = " + format_value(f.L2) +
         " m, and one Euler-Bernoulli frame element per leg (0-1 and 1-2). It is made of " + mat.name +
         " (E = " + format_value(mat.E * 1e-9) + " GPa, rho = " + format_value(mat.rho) +
         " kg/m^3) with a square solid section of side a = " + format_value(f.a_mm) +
         " mm (A = a^2). The mass matrix is the consistent one; each node has the DOFs (u_x, u_y, psi).";
}

// The translational entries of a rotation about `centre` at `node`: (-(y - c_y), x - c_x).
Quantity rotation_about(const FeModel& fe, int node, const Vec2& centre) {
  const Vec2 d = fe.nodes()[node] - centre;
  return Quantity::vector({-d.y(), d.x()});
}

// ---- M06P1: the rotation mode at the tip of the L-shaped frame ----------------------------

Quantity tip_rotation_mode(const Frame& f) {
  const FeModel fe = l_frame(f);
  const RigidBodyModes rigid = rigid_body_modes(fe, assemble(fe, MassMatrixType::consistent).M);
  return Quantity::vector({rigid.Phi_r(dof_index(2, NodeDof::ux), 2), rigid.Phi_r(dof_index(2, NodeDof::uy), 2)});
}

Problem rotation_mode_problem() {
  Problem p;
  p.id = "M06P1";
  p.title = "rotation mode at the tip of a free L-shaped frame";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "m";
  p.make = [](Parameters& r) {
    const Frame f = draw_frame(r);
    Variant v;
    v.statement = frame_text(f) + "\nThe third rigid-body mode r_c of the FFRF basis is a unit rotation about the frame's "
                                  "mass centre c. Give its entries (u_x, u_y) at node 2, in m (per radian).";
    v.solve = [f] {
      const FeModel fe = l_frame(f);
      const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
      const RigidBodyModes rigid = rigid_body_modes(fe, mats.M);
      const Vec2 nodes_mean = (fe.nodes()[0] + fe.nodes()[1] + fe.nodes()[2]) / 3;
      const Vec2 d = fe.nodes()[2] - rigid.centroid;
      Solution s;
      s.answer = tip_rotation_mode(f);
      s.mistakes.emplace_back("the rotation about node 0 (the model's origin) instead of the mass centre",
                              rotation_about(fe, 2, Vec2::Zero()));
      s.mistakes.emplace_back("the mass centre taken as the mean of the node positions", rotation_about(fe, 2, nodes_mean));
      s.mistakes.emplace_back("the radial vector (x - c_x, y - c_y) instead of the rotation (-(y - c_y), x - c_x)",
                              Quantity::vector({d.x(), d.y()}));
      const Section S = frame_section(f);
      const FeModel leg1 = leg(fe.nodes()[0], fe.nodes()[1], S), leg2 = leg(fe.nodes()[1], fe.nodes()[2], S);
      s.steps.push_back("leg masses m_1 = rho A L1 = " + format_value(rigid_body_modes(leg1, assemble(leg1, MassMatrixType::consistent).M).mass) +
                        " kg, m_2 = rho A L2 = " + format_value(rigid_body_modes(leg2, assemble(leg2, MassMatrixType::consistent).M).mass) +
                        " kg, m = " + format_value(rigid.mass) + " kg");
      s.steps.push_back("c = (m_1 (L1/2, 0) + m_2 (L1, L2/2)) / m = " + format_quantity(vec2(rigid.centroid)) + " m");
      s.steps.push_back("x_2 - c = " + format_quantity(vec2(d)) + " m");
      s.steps.push_back("r_c at node 2: (-(y_2 - c_y), x_2 - c_x) = " + format_quantity(s.answer) + " m");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M06P2: a Craig-Bampton constraint mode of a beam with joints at both ends -------------

// A straight beam along x, node 1 at L1 and node 2 at L1 + L2; the rows (v_1, psi_1) of the
// constraint mode of interface DOF `column` (0..5: node 0, then node 2); the interface is nodes 0
// and 2, without psi_2 when `tip_rotation_free`.
Quantity constraint_mode(double L1, double L2, int column, bool tip_rotation_free) {
  FeModel fe;
  fe.add_node(Vec2(0, 0));
  fe.add_node(Vec2(L1, 0));
  fe.add_node(Vec2(L1 + L2, 0));
  const Section section = square_section(210e9, 7850, 0.02);
  fe.add_element(0, 1, section);
  fe.add_element(1, 2, section);
  const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
  std::vector<int> interface = node_dofs({0, 2});
  if (tip_rotation_free) interface.pop_back();
  const ReducedBasis cb = craig_bampton(mats.K, mats.M, interface, 0);
  return Quantity::vector({cb.Phi(dof_index(1, NodeDof::uy), column), cb.Phi(dof_index(1, NodeDof::psi), column)});
}

Problem constraint_mode_problem() {
  Problem p;
  p.id = "M06P2";
  p.title = "a Craig-Bampton constraint mode of a beam of two elements";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "";
  p.make = [](Parameters& r) {
    // One element short, the other long (never equal), in either order.
    const double short_L = r.grid(0.20, 0.05, 9), long_L = r.grid(0.65, 0.05, 9);
    const bool long_first = r.integer(0, 1) == 1;
    const double L1 = long_first ? long_L : short_L, L2 = long_first ? short_L : long_L;
    Variant v;
    v.statement = "A straight beam of constant E I lies on the x axis: node 0 at x = 0, node 1 at x = L1 = " + format_value(L1) +
                  " m, node 2 at x = L1 + L2 = " + format_value(L1 + L2) + " m (L2 = " + format_value(L2) +
                  " m), two Euler-Bernoulli frame elements. Joints attach at both ends, so a Craig-Bampton basis takes the six "
                  "DOFs (u_x, u_y, psi) of nodes 0 and 2 as its interface DOFs; node 1 is interior.\nGive the entries (v_1, "
                  "psi_1) of the constraint mode of the transverse displacement v_2 = u_y of node 2: the static shape for v_2 = 1 "
                  "with the other five interface DOFs held at 0 (v_1 in m per m, psi_1 in rad per m; enter them without a unit).";
    v.solve = [L1, L2] {
      Solution s;
      s.answer = constraint_mode(L1, L2, 4, false);
      s.mistakes.emplace_back("the lengths L1 and L2 swapped (node 1 measured from node 2)", constraint_mode(L2, L1, 4, false));
      s.mistakes.emplace_back("the rotation psi_2 left free (a cantilever pushed at its tip)", constraint_mode(L1, L2, 4, true));
      s.mistakes.emplace_back("the constraint mode of v_0 (the other end) instead of v_2", constraint_mode(L1, L2, 1, false));
      s.mistakes.emplace_back("the constraint mode of psi_2 instead of v_2", constraint_mode(L1, L2, 5, false));
      s.steps.push_back("K_ii: the (v_1, psi_1) block of both elements, E I [[12/L1^3 + 12/L2^3, -6/L1^2 + 6/L2^2], "
                        "[-6/L1^2 + 6/L2^2, 4/L1 + 4/L2]] (u_1 decouples)");
      s.steps.push_back("K_ib, column v_2: E I (-12/L2^3, -6/L2^2)");
      s.steps.push_back("Psi = -K_ii^-1 K_ib: (v_1, psi_1) = " + format_quantity(s.answer) +
                        " (the cubic 3 xi^2 - 2 xi^3 of the whole beam at xi = L1 / (L1 + L2))");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M06P3: the reduced mass entry M_bar[theta, theta] of the L-shaped frame ---------------

double reduced_rotation_mass(const Frame& f, MassMatrixType type) {
  const FeModel fe = l_frame(f);
  return modal_truncation(fe, assemble(fe, type), 0).M_bar(2, 2);
}

Problem reduced_mass_problem() {
  Problem p;
  p.id = "M06P3";
  p.title = "the reduced mass entry of the rotation mode of an L-shaped frame";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-7);
  p.unit = "kg m^2";
  p.make = [](Parameters& r) {
    const Frame f = draw_frame(r);
    Variant v;
    v.statement = frame_text(f) + "\nIts FFRF basis by modal truncation is Phi = [Phi_r, Phi_f], Phi_r = [t_x, t_y, r_c] with "
                                  "r_c the unit rotation about the mass centre. Give the entry M_bar[theta, theta] = r_c^T M r_c "
                                  "of the reduced mass matrix, in kg m^2.";
    v.solve = [f] {
      const FeModel fe = l_frame(f);
      const FeMatrices mats = assemble(fe, MassMatrixType::consistent);
      const RigidBodyModes rigid = rigid_body_modes(fe, mats.M);
      const double J = reduced_rotation_mass(f, MassMatrixType::consistent);
      // Each leg alone: its mass, centre and own J about its centre.
      const Section S = frame_section(f);
      const FeModel leg1 = leg(fe.nodes()[0], fe.nodes()[1], S), leg2 = leg(fe.nodes()[1], fe.nodes()[2], S);
      const RigidBodyModes r1 = rigid_body_modes(leg1, assemble(leg1, MassMatrixType::consistent).M);
      const RigidBodyModes r2 = rigid_body_modes(leg2, assemble(leg2, MassMatrixType::consistent).M);
      // The rotation about node 0 (the model's origin), with the same mass matrix.
      VecX r_o = VecX::Zero(fe.num_dofs());
      for (int k = 0; k < fe.num_nodes(); ++k) r_o.segment<3>(3 * k) << -fe.nodes()[k].y(), fe.nodes()[k].x(), 1.0;
      Solution s;
      s.answer = Quantity::number(J);
      s.mistakes.emplace_back("the lumped mass matrix instead of the consistent one",
                              Quantity::number(reduced_rotation_mass(f, MassMatrixType::lumped)));
      s.mistakes.emplace_back("the rotation about node 0 instead of the mass centre", Quantity::number(r_o.dot(mats.M * r_o)));
      s.mistakes.emplace_back("the parallel-axis terms m_i |c_i - c|^2 left out (the legs' own m L^2/12 only)",
                              Quantity::number(r1.inertia + r2.inertia));
      s.mistakes.emplace_back("the legs' own m L^2/12 left out (point masses at their centres)",
                              Quantity::number(J - r1.inertia - r2.inertia));
      s.steps.push_back("m_1 = rho A L1 = " + format_value(r1.mass) + " kg, m_2 = rho A L2 = " + format_value(r2.mass) + " kg");
      s.steps.push_back("c = " + format_quantity(vec2(rigid.centroid)) + " m; leg centres c_1 = " + format_quantity(vec2(r1.centroid)) +
                        " m, c_2 = " + format_quantity(vec2(r2.centroid)) + " m");
      s.steps.push_back("own inertias m_1 L1^2/12 = " + format_value(r1.inertia) + " kg m^2, m_2 L2^2/12 = " +
                        format_value(r2.inertia) + " kg m^2");
      s.steps.push_back("parallel axes: m_1 |c_1 - c|^2 + m_2 |c_2 - c|^2 = " + format_value(J - r1.inertia - r2.inertia) + " kg m^2");
      s.steps.push_back("M_bar[theta, theta] = J = " + format_value(J) + " kg m^2");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module06_problems() {
  return {rotation_mode_problem(), constraint_mode_problem(), reduced_mass_problem()};
}

}  // namespace fmbd::problems
