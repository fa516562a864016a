// Module 1, task T6: the system's C, C_q and C_t assembled from the joints' and drivers' blocks.
// Oracles: the kernels' blocks stacked by the test at each constraint's rows and each body's
// columns, and central differences of the student's own assembled C.
#include "fmbd/constraints.hpp"
#include "fmbd/examples.hpp"
#include "kinematics_checks.hpp"

using namespace fmbd;
using namespace fmbd::m01;

GRADED_TEST("assembly: every constraint type in its rows, every body in its columns, the ground in none",
            "[M01][T6][points=2]") {
  const Model m = assembly_model();
  testing::Random random(611);
  for (int k = 0; k < 4; ++k) {
    ConstraintEvaluation out = constraint_storage(m);
    if (!check_assembly(m, random.vector(m.num_coordinates(), -1.5, 1.5), random.uniform(0.0, 2.0), out,
                        "three bodies, seven constraints, fresh storage")) {
      break;
    }
  }
}

GRADED_TEST("assembly: storage that holds an earlier call's entries is overwritten", "[M01][T6][points=1]") {
  const Model m = assembly_model();
  testing::Random random(612);
  ConstraintEvaluation out = constraint_storage(m);
  out.C = random.vector(out.C.size(), 5.0, 9.0);
  out.Ct = random.vector(out.Ct.size(), 5.0, 9.0);
  out.Cq = MatX::Constant(out.Cq.rows(), out.Cq.cols(), 7.0);
  for (int k = 0; k < 3; ++k) {
    if (!check_assembly(m, random.vector(m.num_coordinates(), -1.5, 1.5), 0.4 * k, out,
                        "three bodies, the same storage called again")) {
      break;
    }
  }
}

GRADED_TEST("assembly: the slider-crank and the four-bar, driven, at every crank angle", "[M01][T6][points=1]") {
  examples::SliderCrankParameters sp;
  const Model slider = examples::slider_crank(sp);
  examples::FourBarParameters fp;
  const Model four = examples::four_bar(fp);
  ConstraintEvaluation out_slider = constraint_storage(slider), out_four = constraint_storage(four);
  for (int k = 0; k < 12; ++k) {
    const double A = sp.A0 + 2 * kPi * k / 12 + 0.05;
    if (!check_assembly(slider, examples::slider_crank_configuration(sp, A), (A - sp.A0) / sp.omega, out_slider,
                        "slider-crank")) {
      break;
    }
    const double theta = fp.theta0 + 2 * kPi * k / 12;
    if (!check_assembly(four, four_bar_configuration(fp, theta), (theta - fp.theta0) / fp.omega, out_four, "four-bar")) {
      break;
    }
  }
}
