// Module 8, task T6: the capstone of the flexible half, Simeon's flexible slider-crank
// (capstone/README.md).
#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <vector>

#include "fmbd/constraints.hpp"
#include "fmbd/craig_bampton.hpp"
#include "fmbd/errors.hpp"
#include "fmbd/fe_assembly.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/slider_crank_capstone.hpp"

namespace fmbd {

FlexibleExample flexible_slider_crank_capstone() {
  // TASK(M08T6): build Simeon's slider-crank (capstone/README.md, slider_crank_capstone.hpp):
  //   the rod as a beam FE model (module 5) reduced by a basis of your choice (module 6) into a
  //   full FFRF body (make_ffrf_body); the crank with its inertia about O, the rod and the point
  //   mass slider, named "crank", "rod" and "slider"; the pins at the rod's end nodes, the slider
  //   on the x axis and the crank driven at omega. Then the published initial state: the rod's
  //   elastic coordinates and rates that carry the published fields u, w and their rates at t = 0
  //   (your basis holds them only approximately: fit them), the frames that close the joints
  //   with them, and the rigid rates from the velocity equation. Return the FlexibleExample.
  //   Stuck? ./workbook hint M08T6
  // BEGIN SOLUTION
  namespace s = simeon;
  const double pi = std::acos(-1.0), L1 = s::crank_length, L2 = s::rod_length;
  const int elements = 8, fixed_interface_modes = 2;
  const MassMatrixType mass = MassMatrixType::consistent;
  const Section section{s::E, s::rho, s::rod_width * s::rod_height,
                        s::rod_width * s::rod_height * s::rod_height * s::rod_height / 12};
  const FeModel fe = straight_beam(L2, elements, section);
  const FeMatrices fm = assemble(fe, mass);
  const ReducedBasis cb = craig_bampton(fm.K, fm.M, node_dofs({0, elements}), fixed_interface_modes);
  FlexibleExample ex;
  ex.data = std::make_shared<const FlexibleBodyData>(flexible_body_data(fe, mass, ffrf_basis(fe, fm, cb)));
  const FlexibleBodyData& d = *ex.data;
  const int n_f = d.num_modes(), N = elements + 1;

  // The published fields (q1, q2, q3, q4 of w and u) at the nodes: (u, w, w') in the chord frame,
  // whose axes are those of the FE model at t = 0. Fitted on the whole basis by least squares
  // weighted with M_FE; the rigid part goes to the frame, the elastic part is q_f.
  const auto elastic_fit = [&](const double* c) {
    VecX u(3 * N);
    for (int k = 0; k < N; ++k) {
      const double x = d.nodes[k].x_bar.x() - d.nodes[0].x_bar.x(), xi = x / L2;
      u(3 * k) = c[2] * 4 * xi * (1 - xi) + c[3] * xi * (2 * xi - 1);
      u(3 * k + 1) = c[0] * std::sin(pi * xi) + c[1] * std::sin(2 * pi * xi);
      u(3 * k + 2) = (c[0] * pi * std::cos(pi * xi) + c[1] * 2 * pi * std::cos(2 * pi * xi)) / L2;
    }
    const MatX MPhi = d.matrices.M * d.basis.Phi;
    const VecX all = (d.basis.Phi.transpose() * MPhi).ldlt().solve(MPhi.transpose() * u);
    return VecX(all.tail(n_f));
  };
  const VecX q_f = elastic_fit(s::q0 + 3), q_f_dot = elastic_fit(s::qd0 + 3);

  // The rod's frame that puts its deformed node 0 at the crank pin and its last node on the x axis.
  const auto deformed = [&](int k) { return Vec2(d.nodes[k].x_bar + d.nodes[k].Phi_t * q_f); };
  const Vec2 p0 = deformed(0), chord = deformed(elements) - p0;
  const double theta = -std::atan2(chord.y(), chord.x());
  const Vec2 R = Vec2(L1, 0) - rotation(theta) * p0;

  Model& m = ex.model;
  const BodyId crank = m.add_body("crank", s::crank_mass, s::crank_inertia, Vec3::Zero());  // frame at O
  ex.flexible = m.add_flexible_body("rod", make_ffrf_body(ex.data), Vec3(R.x(), R.y(), theta));
  const BodyId slider = m.add_body("slider", s::slider_mass, 0.0, Vec3(L1 + chord.norm(), 0, 0));
  m.add_revolute("crank bearing", m.add_point(ground, Vec2::Zero(), "O"), m.add_point(crank, Vec2::Zero(), "hub"));
  m.add_revolute("crank pin", m.add_point(crank, Vec2(L1, 0), "crank tip"), m.add_node_point(ex.flexible, 0, "rod start"));
  m.add_revolute("wrist pin", m.add_node_point(ex.flexible, elements, "rod end"), m.add_point(slider, Vec2::Zero(), "pin"));
  m.add_translational("guide", m.add_point(ground, Vec2::Zero(), "guide"), m.find_point("pin"), Vec2::UnitX());
  m.add_absolute_angle_driver("crank drive", crank, DriveFunction::linear(0.0, s::crank_speed));

  const int rod = m.offset(ex.flexible);
  ex.q0 = m.initial_guess();
  ex.q0.segment(rod + 3, n_f) = q_f;
  // The rates of the frames (3 per body) from C_q q_dot = -C_t, the elastic rates as fitted.
  const ConstraintEvaluation e = evaluate_constraints(m, ex.q0, 0.0);
  MatX frames(e.Cq.rows(), 3 * m.num_bodies());
  std::vector<int> column;
  for (int b = 0; b < m.num_bodies(); ++b)
    for (int k = 0; k < 3; ++k) column.push_back(m.offset(BodyId{b}) + k);
  for (int c = 0; c < static_cast<int>(column.size()); ++c) frames.col(c) = e.Cq.col(column[c]);
  const VecX rates = frames.partialPivLu().solve(VecX(-e.Ct - e.Cq.middleCols(rod + 3, n_f) * q_f_dot));
  ex.qd0 = VecX::Zero(m.num_coordinates());
  for (int c = 0; c < static_cast<int>(column.size()); ++c) ex.qd0(column[c]) = rates(c);
  ex.qd0.segment(rod + 3, n_f) = q_f_dot;
  return ex;
  // END SOLUTION
  // STUB: throw NotImplemented("M08T6 flexible_slider_crank_capstone");
}

}  // namespace fmbd
