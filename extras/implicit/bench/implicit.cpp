// Benchmark: explicit RK4 at its stable step against the implicit generalised-alpha method at large
// steps, on the flexible slider-crank with a full FFRF rod of 23 elastic coordinates (10 beam
// elements, Craig-Bampton on both end nodes with 20 fixed-interface modes).
//
// Prints CSV rows "group,case,quantity,value,unit" (no header): RK4's stability limit (found by
// bisection on short runs), then for each integrator the wall time for the simulated span, steps
// per second, the speed-up over RK4 and the largest errors of the slider position and of the rod's
// mid-span deflection against the RK4 run. --quick: a tenth of the span and no bisection.
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "fmbd/ffrf.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/generalized_alpha.hpp"

using namespace fmbd;

namespace {

void row(const std::string& name, const char* quantity, double value, const char* unit) {
  std::printf("implicit,%s,%s,%.4g,%s\n", name.c_str(), quantity, value, unit);
}

struct Run {
  Trajectory trajectory;
  double seconds = 0.0;
};

template <class Integrate>
Run timed(Integrate integrate) {
  const auto start = std::chrono::steady_clock::now();
  Run r;
  r.trajectory = integrate();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

bool rk4_stable(const FlexibleExample& ex, double step, double t_end) {
  SimulationOptions o;
  o.integrator = Integrator::rk4;
  o.step = step;
  o.output_interval = t_end;
  try {
    simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, o);
    return true;
  } catch (const IntegrationError&) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  try {
    FlexibleSliderCrankParameters p;
    p.elements = 10;
    p.modes = 20;
    const FlexibleExample ex = flexible_slider_crank(p, make_ffrf_body);
    const std::string model = "slider-crank " + std::to_string(ex.data->num_modes()) + " modes";
    const double t_end = quick ? 0.01 : 0.1, interval = 1e-3;
    const std::string span = quick ? "0.01 s" : "0.1 s";
    const int slider = ex.model.offset(ex.model.find_body("slider"));

    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> modes(ex.data->K_ff, ex.data->M_ff, Eigen::EigenvaluesOnly);
    const double omega_max = std::sqrt(modes.eigenvalues().maxCoeff());
    row(model, "highest elastic frequency (frame fixed)", omega_max, "rad/s");
    row(model, "rk4 limit 2 sqrt(2)/omega_max", 2 * std::sqrt(2.0) / omega_max, "s");
    const double rk4_step = 8e-6;
    if (!quick) {
      double stable = 5e-6, unstable = 1.2e-5;
      for (int i = 0; i < 7; ++i) {
        const double mid = 0.5 * (stable + unstable);
        (rk4_stable(ex, mid, 0.005) ? stable : unstable) = mid;
      }
      row(model, "rk4 stability limit (0.005 s runs)", 0.5 * (stable + unstable), "s");
    }

    SimulationOptions rk4;
    rk4.integrator = Integrator::rk4;
    rk4.step = rk4_step;
    rk4.output_interval = interval;
    const Run reference = timed([&] { return simulate(ex.model, ex.q0, ex.qd0, 0.0, t_end, rk4); });
    const std::string rk4_case = model + " rk4 h=8e-6";
    row(rk4_case, ("wall time for " + span).c_str(), reference.seconds, "s");
    row(rk4_case, "steps per second", reference.trajectory.steps / reference.seconds, "1/s");
    double peak = 0.0;
    for (const VecX& q : reference.trajectory.q) peak = std::max(peak, std::abs(midspan_deflection(ex, q)));
    row(rk4_case, "peak mid-span deflection", peak, "m");

    struct Case {
      const char* name;
      double step;
      JacobianUpdate update;
    };
    for (const Case& c : {Case{"h=1e-3", 1e-3, JacobianUpdate::every_iteration},
                          Case{"h=1e-3 modified Newton", 1e-3, JacobianUpdate::once_per_step},
                          Case{"h=2.5e-4", 2.5e-4, JacobianUpdate::every_iteration},
                          Case{"h=2.5e-4 modified Newton", 2.5e-4, JacobianUpdate::once_per_step}}) {
      GeneralizedAlphaOptions ga;
      ga.jacobian_update = c.update;
      const Run r = timed([&] { return generalized_alpha(ex.model, ex.q0, ex.qd0, 0.0, t_end, c.step, ga, interval); });
      const std::string name = model + " generalized-alpha " + c.name;
      row(name, ("wall time for " + span).c_str(), r.seconds, "s");
      row(name, "steps per second", r.trajectory.steps / r.seconds, "1/s");
      row(name, "speed-up over rk4", reference.seconds / r.seconds, "1");
      double slider_error = 0.0, deflection_error = 0.0;
      const std::size_t points = std::min(r.trajectory.q.size(), reference.trajectory.q.size());
      for (std::size_t i = 0; i < points; ++i) {
        const VecX& q = r.trajectory.q[i];
        const VecX& q_ref = reference.trajectory.q[i];
        slider_error = std::max(slider_error, std::abs(q(slider) - q_ref(slider)));
        deflection_error =
            std::max(deflection_error, std::abs(midspan_deflection(ex, q) - midspan_deflection(ex, q_ref)));
      }
      row(name, "largest slider position error", slider_error, "m");
      row(name, "largest mid-span deflection error / peak", 100.0 * deflection_error / peak, "%");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-implicit: %s\n", e.what());
    return 1;
  }
  return 0;
}
