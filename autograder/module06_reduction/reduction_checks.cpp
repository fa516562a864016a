// The module 6 checks declared in reduction_checks.hpp (documented there), compiled once for all
// the module's test files. Helpers used only here are in the anonymous namespace.

#include "reduction_checks.hpp"

#include "linear_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace fmbd::testing::m06 {

namespace {

Section section(double E, double rho, double A, double I) {
  Section s;
  s.E = E;
  s.rho = rho;
  s.A = A;
  s.I = I;
  return s;
}

/// A polyline frame through `points`: segment s from points[s] to points[s+1] (and from the last
/// point back to the first if `closed`) divided into elements[s] equal elements of sections[s].
FeModel polyline(const std::vector<Vec2>& points, const std::vector<int>& elements,
                 const std::vector<Section>& sections, bool closed = false) {
  FeModel fe;
  const int corners = static_cast<int>(points.size());
  std::vector<int> corner_node(corners);
  for (int k = 0; k < corners; ++k) corner_node[k] = -1;
  corner_node[0] = fe.add_node(points[0]);
  const int segments = closed ? corners : corners - 1;
  for (int s = 0; s < segments; ++s) {
    const int a = s, b = (s + 1) % corners;
    int previous = corner_node[a];
    for (int e = 1; e <= elements[s]; ++e) {
      int next;
      if (e == elements[s] && corner_node[b] >= 0) {
        next = corner_node[b];
      } else {
        const double t = static_cast<double>(e) / elements[s];
        next = fe.add_node((1.0 - t) * points[a] + t * points[b]);
        if (e == elements[s]) corner_node[b] = next;
      }
      fe.add_element(previous, next, sections[s]);
      previous = next;
    }
  }
  return fe;
}

}  // namespace

// ---- small helpers ------------------------------------------------------------------------

MatX pick(const MatX& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatX out(rows.size(), cols.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = A(rows[r], cols[c]);
  return out;
}

std::vector<int> complement(int n, const std::vector<int>& listed) {
  std::vector<int> out;
  for (int i = 0; i < n; ++i)
    if (std::find(listed.begin(), listed.end(), i) == listed.end()) out.push_back(i);
  return out;
}

// ---- frames -------------------------------------------------------------------------------

FeModel random_triangle(Random& rnd) {
  std::vector<Vec2> corners;
  const Vec2 centre = rnd.vec2(-2.0, 2.0);
  const double turn = rnd.uniform(0.0, 6.0);
  for (int k = 0; k < 3; ++k) {
    const double angle = turn + 2.0 * k + rnd.uniform(-0.3, 0.3);
    corners.push_back(centre + rnd.uniform(0.6, 1.4) * Vec2(std::cos(angle), std::sin(angle)));
  }
  std::vector<int> elements;
  std::vector<Section> sections;
  for (int k = 0; k < 3; ++k) {
    elements.push_back(1 + static_cast<int>(rnd.uniform(0.0, 3.999)));
    const double side = rnd.uniform(0.02, 0.06);
    sections.push_back(section(kSteelE * rnd.uniform(0.3, 1.0), kSteelRho * rnd.uniform(0.3, 1.2), side * side,
                               side * side * side * side / 12.0));
  }
  return polyline(corners, elements, sections, true);
}

FeModel l_frame() {
  const double a = 0.03;
  return polyline({Vec2(0.4, 0.3), Vec2(2.4, 0.3), Vec2(2.4, 1.8)}, {4, 3},
                  {steel(0.04), section(7.0e10, 2700.0, a * a, a * a * a * a / 12.0)});
}

// ---- rigid-body properties as integrals over the elements --------------------------------

RigidOracle rigid_oracle(const FeModel& fe, MassMatrixType type) {
  RigidOracle o;
  Vec2 moment = Vec2::Zero();
  for (const BeamElement& e : fe.elements()) {
    const Vec2 a = fe.nodes()[e.node_a], b = fe.nodes()[e.node_b];
    const double L = (b - a).norm(), m_e = e.section.rho * e.section.A * L;
    o.mass += m_e;
    moment += m_e * 0.5 * (a + b);
  }
  o.centroid = moment / o.mass;
  for (const BeamElement& e : fe.elements()) {
    const Vec2 a = fe.nodes()[e.node_a], b = fe.nodes()[e.node_b];
    const double L = (b - a).norm(), m_e = e.section.rho * e.section.A * L;
    if (type == MassMatrixType::consistent) {
      o.inertia += m_e * ((0.5 * (a + b) - o.centroid).squaredNorm() + L * L / 12.0);
    } else {
      o.inertia += 0.5 * m_e * ((a - o.centroid).squaredNorm() + (b - o.centroid).squaredNorm()) +
                   2.0 * m_e * L * L / 78.0;
    }
  }
  return o;
}

MatX rigid_columns(const FeModel& fe, const Vec2& p, double psi) {
  MatX Phi = MatX::Zero(fe.num_dofs(), 3);
  for (int k = 0; k < fe.num_nodes(); ++k) {
    const Vec2 d = fe.nodes()[k] - p;
    Phi(3 * k, 0) = 1.0;
    Phi(3 * k + 1, 1) = 1.0;
    Phi(3 * k + 2, 2) = psi;
    Phi(3 * k, 2) = -d.y();
    Phi(3 * k + 1, 2) = d.x();
  }
  return Phi;
}

double position_scale(const FeModel& fe) {
  double s = 1.0;
  for (const Vec2& x : fe.nodes()) s = std::max(s, x.norm());
  return s;
}

// ---- hints for rigid_body_modes ----------------------------------------------------------

namespace {

constexpr const char* kCentroidFormula = "c = (t_y^T M r_o, -t_x^T M r_o) / m";
constexpr const char* kInertiaFormula = "J = r_c^T M r_c";
constexpr const char* kRigidFormula =
    "Phi_r = [t_x, t_y, r_c]: node k gets (1, 0, 0), (0, 1, 0) and (-(y_k - c_y), x_k - c_x, 1)";

std::string centroid_words(const char* words) { return with_formula(words, kCentroidFormula); }

}  // namespace

std::string centroid_hint(const Vec2& got, const RigidOracle& o) {
  const Vec2 c = o.centroid;
  return diagnose(got, c,
                  {{centroid_words("your centroid sign of c_y: r_o has -y_k in the x rows"), Vec2(c.x(), -c.y())},
                   {centroid_words("your centroid sign of c_x: r_o has +x_k in the y rows"), Vec2(-c.x(), c.y())},
                   {centroid_words("your centroid signs of both components are flipped"), Vec2(-c.x(), -c.y())},
                   {centroid_words("your centroid components swapped"), Vec2(-c.y(), c.x())},
                   {centroid_words("your centroid not divided by the mass m"), Vec2(o.mass * c)},
                   {centroid_words("your centroid left at the origin"), Vec2(Vec2::Zero())}},
                  centroid_words("your centroid is not the first moments of M over the mass"));
}

std::string inertia_hint(double got, const RigidOracle& o) {
  const Vec2 c = o.centroid;
  const double J = o.inertia, m = o.mass;
  return diagnose(as_matrix(got), as_matrix(J),
                  {{with_formula("your J about the origin: take the unit rotation about the centroid c, not about the "
                                 "origin (that adds m |c|^2)", kInertiaFormula),
                    as_matrix(J + m * c.squaredNorm())},
                   {centroid_words("your J is about a wrong centre: fix the sign of c_y of the centroid first"),
                    as_matrix(J + 4.0 * m * c.y() * c.y())},
                   {centroid_words("your J is about a wrong centre: fix the sign of c_x of the centroid first"),
                    as_matrix(J + 4.0 * m * c.x() * c.x())},
                   {centroid_words("your J is about a wrong centre: divide the centroid's first moments by m first"),
                    as_matrix(J + m * (m - 1.0) * (m - 1.0) * c.squaredNorm())}},
                  with_formula("your J is not the M-norm of the unit rotation about the centroid (for a straight "
                               "beam m L^2 / 12)", kInertiaFormula),
                  Tolerance{1e-6, 1e-6});
}

std::string phi_r_hint(const FeModel& fe, const MatX& Phi_r, const RigidOracle& o) {
  const Vec2 c = o.centroid;
  if (Phi_r.rows() != fe.num_dofs() || Phi_r.cols() != 3)
    return "your Phi_r is not n x 3 (n = 3 N): translation x, translation y, rotation about the centroid";
  return diagnose(flat(Phi_r), flat(rigid_columns(fe, c)),
                  {{with_formula("your rotation column about the origin instead of the centroid", kRigidFormula),
                    flat(rigid_columns(fe, Vec2::Zero()))},
                   {centroid_words("your rotation column is about a wrong centre: check the centroid signs"),
                    flat(rigid_columns(fe, Vec2(c.x(), -c.y())))},
                   {centroid_words("your rotation column is about a wrong centre: check the centroid signs"),
                    flat(rigid_columns(fe, Vec2(-c.x(), c.y())))},
                   {centroid_words("your rotation column is about a wrong centre: divide the first moments by m"),
                    flat(rigid_columns(fe, Vec2(o.mass * c)))},
                   {"your rotation column: the psi entry of every node is 1 (the sections turn with the body)",
                    flat(rigid_columns(fe, c, 0.0))},
                   {with_formula("your rotation column turned the wrong way: it must turn counterclockwise",
                                 kRigidFormula),
                    flat(MatX(rigid_columns(fe, c) - 2.0 * rigid_columns(fe, c, 0.0).rightCols<1>() *
                                                          Eigen::RowVector3d(0, 0, 1)))}},
                  with_formula("your Phi_r is not the two unit translations and the unit rotation about the centroid",
                               kRigidFormula),
                  Tolerance{1e-9, 1e-9});
}

void check_rigid_body_modes(const FeModel& fe, const RigidBodyModes& rb, const RigidOracle& o) {
  CHECK_NEAR_NAMED("your mass m", rb.mass, o.mass, (Tolerance{0.0, 1e-11}),
                   with_formula("your mass is not the M-norm of a unit translation",
                                "m = t_x^T M t_x, t_x = (1, 0, 0) at every node"));
  CHECK_CLOSE_NAMED("your centroid c", rb.centroid, o.centroid, (Tolerance{1e-10, 1e-10}),
                    centroid_hint(rb.centroid, o));
  CHECK_NEAR_NAMED("your J about the centroid", rb.inertia, o.inertia, (Tolerance{0.0, 1e-10}),
                   inertia_hint(rb.inertia, o));
  CHECK_CLOSE(rb.Phi_r, rigid_columns(fe, o.centroid), (Tolerance{1e-10, 1e-10}), phi_r_hint(fe, rb.Phi_r, o));
}

// ---- eigenvalues --------------------------------------------------------------------------

VecX eigenvalues(const MatX& K, const MatX& M) {
  return generalized_eigen(symmetric_part(K), symmetric_part(M), false).values;
}

VecX frequencies(const MatX& K, const MatX& M) { return eigenvalues(K, M).cwiseMax(0.0).cwiseSqrt(); }

MatX mode_shapes(const MatX& K, const MatX& M, int count) {
  return generalized_eigen(symmetric_part(K), symmetric_part(M)).vectors.leftCols(count);
}

VecX free_free_omegas(const Section& s, double L, int count) {
  VecX w(count);
  for (int i = 0; i < count; ++i)
    w(i) = kFreeFreeBetaL[i] * kFreeFreeBetaL[i] * std::sqrt(s.E * s.I / (s.rho * s.A)) / (L * L);
  return w;
}

VecX diagonal_frequencies(const MatX& K_bar, int first) {
  const int k = static_cast<int>(K_bar.rows()) - first;
  if (k <= 0) return VecX(0);
  return K_bar.diagonal().tail(k).cwiseMax(0.0).cwiseSqrt();
}

// ---- Craig-Bampton oracles ----------------------------------------------------------------

MatX constraint_modes(const MatX& K, const std::vector<int>& interface, double sign) {
  const int n = static_cast<int>(K.rows()), n_b = static_cast<int>(interface.size());
  const std::vector<int> interior = complement(n, interface);
  const MatX K_ii = pick(K, interior, interior), K_ib = pick(K, interior, interface);
  const MatX u_i = -sign * solve_spd(K_ii, K_ib);
  MatX Psi = MatX::Zero(n, n_b);
  for (int r = 0; r < n_b; ++r) Psi(interface[r], r) = 1.0;
  for (std::size_t r = 0; r < interior.size(); ++r) Psi.row(interior[r]) = u_i.row(r);
  return Psi;
}

std::string constraint_hint(const MatX& K, const std::vector<int>& interface, const MatX& columns) {
  const MatX expected = constraint_modes(K, interface);
  if (columns.rows() != expected.rows() || columns.cols() != expected.cols())
    return "constraint modes: the first n_b columns of Phi, n rows each, in the order of the interface";
  MatX unit_only = MatX::Zero(expected.rows(), expected.cols());
  for (std::size_t r = 0; r < interface.size(); ++r) unit_only(interface[r], r) = 1.0;
  return diagnose(flat(columns), flat(expected),
                  {{with_formula("your Psi sign: the interior follows the unit interface displacement",
                                 "Psi = -K_ii^{-1} K_ib"),
                    flat(constraint_modes(K, interface, -1.0))},
                   {with_formula("your Psi missing: the interior rows of the constraint modes are the static response "
                                 "to the unit interface displacement, not zero", "Psi = -K_ii^{-1} K_ib"),
                    flat(unit_only)}},
                  with_formula("your constraint modes are wrong: constraint mode r is 1 at its own interface DOF "
                               "interface[r], 0 at the other interface DOFs, and the static response Psi on the "
                               "interior rows",
                               "Psi = -K_ii^{-1} K_ib"),
                  Tolerance{1e-7, 1e-7});
}

ReducedBasis craig_bampton_oracle(const MatX& K, const MatX& M, const std::vector<int>& interface, int k) {
  const int n = static_cast<int>(K.rows()), n_b = static_cast<int>(interface.size());
  const std::vector<int> interior = complement(n, interface);
  const MatX modes = mode_shapes(pick(K, interior, interior), pick(M, interior, interior), k);
  ReducedBasis b;
  b.Phi = MatX::Zero(n, n_b + k);
  b.Phi.leftCols(n_b) = constraint_modes(K, interface);
  for (std::size_t r = 0; r < interior.size(); ++r) b.Phi.row(interior[r]).tail(k) = modes.row(r);
  b.M_bar = b.Phi.transpose() * M * b.Phi;
  b.K_bar = b.Phi.transpose() * K * b.Phi;
  b.num_rigid = 0;
  return b;
}

double outside_span(const MatX& A, const MatX& B, const MatX& M) {
  const MatX G = symmetric_part(B.transpose() * M * B);
  const MatX R = A - B * solve_symmetric(G, B.transpose() * M * A);
  const double scale = std::max((A.transpose() * M * A).trace(), 1e-300);
  return std::abs((R.transpose() * M * R).trace()) / scale;
}

}  // namespace fmbd::testing::m06
