// Project test (not graded) of the flexible capstone's grading (task M08T6): a slider-crank built
// in a different but equivalent way scores full on every check of the graded tests.
#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/craig_bampton.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/slider_crank_capstone.hpp"
#include "grading.hpp"
#include "slider_crank_capstone_checks.hpp"

using namespace fmbd;
using namespace fmbd::testing;
using namespace fmbd::testing::m08;

namespace {

namespace s = fmbd::simeon;

// Simeon's slider-crank as another student might build it: 12 elements numbered from the wrist
// pin to the crank pin (the rod's frame turned by pi), Craig-Bampton with three fixed-interface
// modes, the published fields fitted by plain least squares, the bodies in reverse order, the
// crank's frame at its centroid and turned, the slider's frame turned, every joint with i and j
// swapped.
FlexibleExample equivalent_slider_crank() {
  const double pi = std::acos(-1.0), L1 = s::crank_length, L2 = s::rod_length;
  const int elements = 12, N = elements + 1;
  const Section section{s::E, s::rho, s::rod_width * s::rod_height, std::pow(s::rod_width, 4) / 12};
  const FeModel fe = straight_beam(L2, elements, section);
  const FeMatrices fm = assemble(fe, MassMatrixType::consistent);
  FlexibleExample ex;
  ex.data = std::make_shared<const FlexibleBodyData>(flexible_body_data(
      fe, MassMatrixType::consistent, ffrf_basis(fe, fm, craig_bampton(fm.K, fm.M, node_dofs({0, elements}), 3))));
  const FlexibleBodyData& d = *ex.data;
  const int n_f = d.num_modes();
  // FE node k sits at x = L2 - k L2 / elements on the chord; the FE axes are the chord's turned by pi.
  const auto fit = [&](const double* c) {
    VecX u(3 * N);
    for (int k = 0; k < N; ++k) {
      const double xi = 1.0 - static_cast<double>(k) / elements;
      u(3 * k) = -(c[2] * 4 * xi * (1 - xi) + c[3] * xi * (2 * xi - 1));
      u(3 * k + 1) = -(c[0] * std::sin(pi * xi) + c[1] * std::sin(2 * pi * xi));
      u(3 * k + 2) = (c[0] * pi * std::cos(pi * xi) + 2 * pi * c[1] * std::cos(2 * pi * xi)) / L2;
    }
    return VecX(d.basis.Phi.colPivHouseholderQr().solve(u).tail(n_f));
  };
  const VecX q_f = fit(s::q0 + 3), q_f_dot = fit(s::qd0 + 3);
  const auto deformed = [&](int k) { return Vec2(d.nodes[k].x_bar + d.nodes[k].Phi_t * q_f); };
  const Vec2 crank_end = deformed(elements), chord = deformed(0) - crank_end;
  const double theta = -std::atan2(chord.y(), chord.x());
  const Vec2 R = Vec2(L1, 0) - rotation(theta) * crank_end;

  Model& m = ex.model;
  const double crank_frame = 0.4, slider_frame = 1.0;
  const BodyId slider = m.add_body("slider", s::slider_mass, 0.0, Vec3(L1 + chord.norm(), 0, slider_frame));
  ex.flexible = m.add_flexible_body("rod", make_ffrf_body(ex.data), Vec3(R.x(), R.y(), theta));
  const BodyId crank = m.add_body("crank", s::crank_mass, s::crank_inertia - s::crank_mass * L1 * L1 / 4,
                                  Vec3(L1 / 2, 0, crank_frame));
  m.add_revolute("wrist", m.add_point_at(slider, Vec2(L1 + chord.norm(), 0), "wrist on slider"),
                 m.add_node_point(ex.flexible, 0, "wrist on rod"));
  m.add_revolute("pin", m.add_node_point(ex.flexible, elements, "pin on rod"),
                 m.add_point_at(crank, Vec2(L1, 0), "pin on crank"));
  m.add_revolute("bearing", m.add_point_at(crank, Vec2::Zero(), "O on crank"), m.add_point(ground, Vec2::Zero(), "O"));
  m.add_translational("guide", m.add_point_at(slider, Vec2(L1 + chord.norm(), 0), "guide on slider"),
                      m.add_point(ground, Vec2::Zero(), "guide"), Vec2(std::cos(slider_frame), -std::sin(slider_frame)),
                      -slider_frame);
  m.add_absolute_angle_driver("motor", crank, DriveFunction::linear(crank_frame, s::crank_speed));

  const int rod = m.offset(ex.flexible);
  ex.q0 = m.initial_guess();
  ex.q0.segment(rod + 3, n_f) = q_f;
  const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
  std::vector<int> frames;
  for (int b = 0; b < m.num_bodies(); ++b)
    for (int k = 0; k < 3; ++k) frames.push_back(m.offset(BodyId{b}) + k);
  MatX Cq(e.Cq.rows(), static_cast<Eigen::Index>(frames.size()));
  for (std::size_t c = 0; c < frames.size(); ++c) Cq.col(static_cast<Eigen::Index>(c)) = e.Cq.col(frames[c]);
  const VecX v = Cq.colPivHouseholderQr().solve(VecX(-e.Ct - e.Cq.middleCols(rod + 3, n_f) * q_f_dot));
  ex.qd0 = VecX::Zero(m.num_coordinates());
  for (std::size_t c = 0; c < frames.size(); ++c) ex.qd0(frames[c]) = v(static_cast<Eigen::Index>(c));
  ex.qd0.segment(rod + 3, n_f) = q_f_dot;
  return ex;
}

}  // namespace

TEST_CASE("capstone: an equivalent flexible slider-crank scores full on every check of M08T6", "[capstone]") {
  const FlexibleExample ex = equivalent_slider_crank();
  REQUIRE(check_capstone_structure(ex));
  check_capstone_start(ex);
  check_capstone_motion(ex);
  check_capstone_energy(ex);
}

TEST_CASE("capstone: the grader's step keeps RK4 stable for the basis", "[capstone]") {
  const FlexibleExample ex = equivalent_slider_crank();
  const double h = capstone_step(ex);
  CHECK(h <= 5e-5);
  CHECK(std::abs(s::t_end / h - std::round(s::t_end / h)) < 1e-9);
}
