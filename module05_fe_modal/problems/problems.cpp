// Tutorial problems of module 5 (README.md in this folder): entries of the stiffness matrix of an
// inclined beam element, the first natural frequency of a clamped-clamped beam of two elements,
// and entries of the consistent mass matrix of an inclined element. Every answer and every named
// mistake is computed by the engine (element matrices, assembly, supports, modal analysis).
#include <cmath>
#include <string>
#include <vector>

#include "fmbd/beam_element.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/fe_model.hpp"
#include "fmbd/modal.hpp"
#include "fmbd/supports.hpp"
#include "modules.hpp"

namespace fmbd::problems {

namespace {

// An element (or beam) of a square section of side a [mm].
struct Beam {
  int material = 0;
  double a_mm = 20;     // side of the square section [mm]
  double L = 1;         // m
  double alpha_deg = 0; // angle of the element from the x axis, counter-clockwise
};

Section section_of(const Beam& b) {
  const Material& mat = kMaterials[b.material];
  return square_section(mat.E, mat.rho, b.a_mm * 1e-3);
}

std::string section_text(const Beam& b) {
  const Material& mat = kMaterials[b.material];
  return std::string(mat.name) + " (E = " + format_value(mat.E * 1e-9) + " GPa, rho = " + format_value(mat.rho) +
         " kg/m^3), a square solid section of side a = " + format_value(b.a_mm) + " mm (A = a^2, I = a^4 / 12)";
}

// The global matrices of one element of length L at angle alpha from node 0 to node 1:
// T^T k_e T and T^T m_e T, assembled.
FeMatrices element_matrices(const Section& section, double L, double alpha, MassMatrixType type) {
  return assemble(straight_beam(L, 1, section, Vec2::Zero(), alpha), type);
}

Beam draw_inclined(Parameters& r) {
  Beam b;
  b.material = r.integer(0, 1);
  b.a_mm = r.grid(10, 2, 16);
  b.L = r.grid(0.20, 0.05, 17);
  b.alpha_deg = r.grid(10, 5, 15) + 90 * r.integer(0, 3);  // never a multiple of 90 deg
  return b;
}

std::string inclined_text(const Beam& b) {
  return "A planar Euler-Bernoulli frame element of length L = " + format_value(b.L) + " m runs from node a to node b at alpha = " +
         format_value(b.alpha_deg) + " deg from the global x axis (counter-clockwise). It is made of " + section_text(b) +
         ". Each node has the global DOFs (u_x, u_y, psi); the global element matrices are T^T k_e T and "
         "T^T m_e T, T = blockdiag(R, R), R = [[c, s, 0], [-s, c, 0], [0, 0, 1]].";
}

// ---- M05P1: the column of psi_a of the global element stiffness -------------------------

Quantity psi_column(const Section& section, double L, double alpha) {
  const MatX K = element_matrices(section, L, alpha, MassMatrixType::consistent).K;
  return Quantity::vector({K(0, 2), K(1, 2)});
}

Problem stiffness_problem() {
  Problem p;
  p.id = "M05P1";
  p.title = "stiffness entries of an inclined beam element";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-3);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "N";
  p.make = [](Parameters& r) {
    const Beam b = draw_inclined(r);
    Variant v;
    v.statement = inclined_text(b) + "\nGive the entries of the global element stiffness matrix in the rows u_x and "
                                     "u_y of node a and the column psi of node a: (K[u_xa, psi_a], K[u_ya, psi_a]), "
                                     "the forces at node a per radian of rotation of node a.";
    v.solve = [b] {
      const Section S = section_of(b);
      const double alpha = b.alpha_deg * kDeg;
      Section per_L3 = S;  // 6 E I / L^3: the section's I divided by L
      per_L3.I = S.I / b.L;
      Solution s;
      s.answer = psi_column(S, b.L, alpha);
      s.mistakes.emplace_back("T k_e T^T instead of T^T k_e T (the element turned by -alpha)", psi_column(S, b.L, -alpha));
      s.mistakes.emplace_back("the transformation left out (the local entries 0 and 6 E I / L^2)", psi_column(S, b.L, 0.0));
      s.mistakes.emplace_back("sin and cos swapped (the angle taken from the y axis)", psi_column(S, b.L, kPi / 2 - alpha));
      s.mistakes.emplace_back("6 E I / L^3 instead of 6 E I / L^2", psi_column(per_L3, b.L, alpha));
      s.mistakes.emplace_back("degrees against radians: alpha in degrees put into cos and sin as radians",
                              psi_column(S, b.L, b.alpha_deg));
      const Mat6 k = beam_stiffness(S, b.L);
      s.steps.push_back("A = " + format_value(S.A) + " m^2, I = " + format_value(S.I) + " m^4, E I = " + format_value(S.E * S.I) + " N m^2");
      s.steps.push_back("local k_e[v_a, psi_a] = 6 E I / L^2 = " + format_value(k(1, 2)) + " N, k_e[u_a, psi_a] = 0");
      s.steps.push_back("K = T^T k_e T: (K[u_xa, psi_a], K[u_ya, psi_a]) = R^T (0, 6 E I / L^2) = 6 E I / L^2 "
                        "(-sin alpha, cos alpha) = " + format_quantity(psi_column(S, b.L, alpha)) + " N");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M05P2: first natural frequency of a clamped-clamped beam of two elements -------------

// f_1 [Hz] (or omega_1 [rad/s]) of a straight beam of `length`, two equal elements, clamped at
// both ends.
double first_frequency(const Beam& b, double length, MassMatrixType type, bool hertz) {
  const FeModel fe = straight_beam(length, 2, section_of(b));
  const FeMatrices mats = assemble(fe, type);
  const DofMap map = apply_supports(fe, {{0, Support::clamped}, {2, Support::clamped}});
  const Modes modes = modal_analysis(reduce(mats.K, map), reduce(mats.M, map), 1);
  return hertz ? modes.hertz()(0) : modes.omega(0);
}

Problem frequency_problem() {
  Problem p;
  p.id = "M05P2";
  p.title = "first natural frequency of a clamped beam of two elements";
  p.points = 3;
  p.tolerance = Tolerance(2e-3, 1e-4);
  p.unit = "1/s";
  p.make = [](Parameters& r) {
    Beam b;
    b.material = r.integer(0, 1);
    b.a_mm = r.grid(10, 2, 16);
    b.L = r.grid(0.6, 0.1, 25);
    Variant v;
    v.statement = "A straight beam of length L = " + format_value(b.L) + " m is clamped at both ends. It is made of " +
                  section_text(b) + ". It is modelled by two equal Euler-Bernoulli frame elements (nodes 0, 1, 2; "
                  "consistent mass matrices), so that only the middle node 1 is free: (u_x, u_y, psi).\nGive the "
                  "first natural frequency f_1 of the model in Hz.";
    v.solve = [b] {
      const double f1 = first_frequency(b, b.L, MassMatrixType::consistent, true);
      Solution s;
      s.answer = Quantity::number(f1);
      s.mistakes.emplace_back("the lumped mass matrix instead of the consistent one",
                              Quantity::number(first_frequency(b, b.L, MassMatrixType::lumped, true)));
      s.mistakes.emplace_back("omega in rad/s given as the frequency in Hz (f = omega / (2 pi))",
                              Quantity::number(first_frequency(b, b.L, MassMatrixType::consistent, false)));
      s.mistakes.emplace_back("the whole beam's length L in the element matrices instead of the element's L/2",
                              Quantity::number(first_frequency(b, 2 * b.L, MassMatrixType::consistent, true)));
      const Section S = section_of(b);
      const double Le = b.L / 2, me = S.rho * S.A * Le;
      const Mat6 k = beam_stiffness(S, Le);
      const Mat6 m = beam_mass(S, Le, MassMatrixType::consistent);
      s.steps.push_back("element: L_e = L/2 = " + format_value(Le) + " m, m_e = rho A L_e = " + format_value(me) + " kg, E I = " +
                        format_value(S.E * S.I) + " N m^2");
      s.steps.push_back("node 1 is node b of element 1 and node a of element 2: K[v_1, v_1] = 2 (12 E I / L_e^3) = " +
                        format_value(2 * k(4, 4)) + " N/m, K[v_1, psi_1] = -6 E I / L_e^2 + 6 E I / L_e^2 = 0");
      s.steps.push_back("M[v_1, v_1] = 2 (156 m_e / 420) = " + format_value(2 * m(4, 4)) + " kg, M[v_1, psi_1] = 0; the axial and "
                        "rotation DOFs give higher frequencies");
      s.steps.push_back("omega_1 = sqrt(K[v_1, v_1] / M[v_1, v_1]) = " +
                        format_value(first_frequency(b, b.L, MassMatrixType::consistent, false)) + " rad/s");
      s.steps.push_back("f_1 = omega_1 / (2 pi) = " + format_value(f1) + " Hz");
      return s;
    };
    return v;
  };
  return p;
}

// ---- M05P3: consistent mass entries of an inclined element --------------------------------

Quantity mass_entries(const Section& section, double L, double alpha, MassMatrixType type) {
  const MatX M = element_matrices(section, L, alpha, type).M;
  return Quantity::vector({M(0, 0), M(0, 1)});
}

Problem mass_problem() {
  Problem p;
  p.id = "M05P3";
  p.title = "consistent mass entries of an inclined beam element";
  p.points = 2;
  p.tolerance = Tolerance(2e-3, 1e-6);
  p.kind = Kind::vector;
  p.rows = 2;
  p.unit = "kg";
  p.make = [](Parameters& r) {
    const Beam b = draw_inclined(r);
    Variant v;
    v.statement = inclined_text(b) + "\nWith the consistent mass matrix, give the entries of the global element mass "
                                     "matrix (M[u_xa, u_xa], M[u_xa, u_ya]) of node a.";
    v.solve = [b] {
      const Section S = section_of(b);
      const double alpha = b.alpha_deg * kDeg;
      Section per_length = S;  // m = rho A instead of rho A L
      per_length.rho = S.rho / b.L;
      const Quantity M = mass_entries(S, b.L, alpha, MassMatrixType::consistent);
      Solution s;
      s.answer = M;
      s.mistakes.emplace_back("the lumped mass matrix instead of the consistent one",
                              mass_entries(S, b.L, alpha, MassMatrixType::lumped));
      s.mistakes.emplace_back("the transformation left out (the local entries m/3 and 0)",
                              mass_entries(S, b.L, 0.0, MassMatrixType::consistent));
      s.mistakes.emplace_back("the axial (2 m/6) and transverse (156 m/420) masses swapped",
                              mass_entries(S, b.L, alpha + kPi / 2, MassMatrixType::consistent));
      s.mistakes.emplace_back("the element mass taken as rho A (L left out)",
                              mass_entries(per_length, b.L, alpha, MassMatrixType::consistent));
      s.mistakes.emplace_back("degrees against radians: alpha in degrees put into cos and sin as radians",
                              mass_entries(S, b.L, b.alpha_deg, MassMatrixType::consistent));
      const double m = S.rho * S.A * b.L, c = std::cos(alpha), sn = std::sin(alpha);
      s.steps.push_back("m = rho A L = " + format_value(m) + " kg; local: m_e[u_a, u_a] = 2 m/6 = " + format_value(m / 3) +
                        " kg, m_e[v_a, v_a] = 156 m/420 = " + format_value(156 * m / 420) + " kg, no u-v coupling");
      s.steps.push_back("alpha = " + format_value(alpha) + " rad, c = " + format_value(c) + ", s = " + format_value(sn));
      s.steps.push_back("M[u_xa, u_xa] = (m/3) c^2 + (156 m/420) s^2, M[u_xa, u_ya] = (m/3 - 156 m/420) c s: " +
                        format_quantity(M) + " kg");
      return s;
    };
    return v;
  };
  return p;
}

}  // namespace

std::vector<Problem> module05_problems() { return {stiffness_problem(), frequency_problem(), mass_problem()}; }

}  // namespace fmbd::problems
