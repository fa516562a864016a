// Benchmark: the spin-up profile of Kane, Ryan and Banerjee (1987) on two 10 m beams, with the
// linear full FFRF of module 8 and the stiffened body of this extra (geometric_stiffening.hpp).
//
// A beam clamped to a hub spun up by theta_dot(t) = (Omega_s/T)(t - (T/2 pi) sin(2 pi t/T)) for
// t < T and Omega_s after (module 7's spin_up_beam, T = 15 s), Omega_s = 4 and 10 rad/s, to
// t = 20 s. Two beams, both 10 m long (README, section "Validation"): the aluminium section of
// module 7's SpinUpBeamParameters (whose own beam is 8 m long), and Kane, Ryan and Banerjee's
// beam, rho A = 1.2 kg/m, EI = 14000 N m^2. Per beam, rate and
// form (module 8 with the frame clamped at the hub; stiffened with the frame clamped at the hub
// and at the centroid) it prints CSV rows "group,case,quantity,value,unit":
//
//   peak_tip_deflection, peak_time    the largest |tip deflection| in the hub frame, with its sign
//   final_tip_deflection              at t = 20 s (empty for a run-away)
//   peak_to_peak_15_20                max - min of the tip deflection over 15-20 s, sampled every
//                                     0.05 s (empty for a run-away)
//   runaway_time                      when the tip left the radial line by 2 m (a linear FFRF
//                                     that diverges stops there)
//   seconds                           wall time of the run
//
// Options: --quick (the aluminium beam at 4 rad/s only, to t = 16 s).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "bench.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/geometric_stiffening.hpp"
#include "fmbd/marker.hpp"
#include "fmbd/simulation.hpp"

using namespace fmbd;

namespace {

struct Beam {
  const char* name;
  SpinUpBeamParameters p;
};

double tip_deflection(const FlexibleExample& ex, const VecX& q) {
  const Model& m = ex.model;
  const Vec2 tip = point_position(m, m.find_point("beam tip"), q);
  return (rotation(m.body_coordinates(q, m.find_body("hub"))(2)).transpose() * tip).y();
}

void run(const std::string& group, SpinUpBeamParameters p, const char* form, BodyBasis basis, const BodyFactory& make,
         double t_end) {
  p.basis = basis;
  const FlexibleExample ex = spin_up_beam(p, make);
  SimulationOptions o;
  o.integrator = Integrator::dormand_prince;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.max_step = 0.01;
  o.stabilisation = Stabilisation::projection;
  VecX q = ex.q0, qd = ex.qd0;
  double peak = 0.0, peak_time = 0.0, runaway = -1.0, last = 0.0, low = HUGE_VAL, high = -HUGE_VAL;
  const double piece = 0.05;
  const double wall = bench::seconds([&] {
    for (int i = 0; i * piece < t_end - 1e-9 && runaway < 0; ++i) {
      const Trajectory r = simulate(ex.model, q, qd, i * piece, (i + 1) * piece, o);
      q = r.q.back();
      qd = r.qd.back();
      last = tip_deflection(ex, q);
      if (std::abs(last) > std::abs(peak)) {
        peak = last;
        peak_time = r.t.back();
      }
      if (r.t.back() >= 15.0 - 1e-9) {
        low = std::min(low, last);
        high = std::max(high, last);
      }
      if (std::abs(last) > 2.0) runaway = r.t.back();
    }
  });
  const std::string name = group + " " + form;
  bench::row("spin_up", name, "peak_tip_deflection", peak, "m");
  bench::row("spin_up", name, "peak_time", peak_time, "s");
  if (runaway < 0) {
    bench::row("spin_up", name, "final_tip_deflection", last, "m");
    if (t_end >= 20.0) bench::row("spin_up", name, "peak_to_peak_15_20", high - low, "m");
  } else
    bench::row("spin_up", name, "runaway_time", runaway, "s");
  bench::row("spin_up", name, "seconds", wall, "s");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  Beam aluminium{"aluminium", {}};
  aluminium.p.length = 10.0;  // the section, E and rho of SpinUpBeamParameters
  Beam light{"rhoA1.2_EI14000", {}};
  light.p.length = 10.0;
  light.p.A = 1.0;
  light.p.rho = 1.2;
  light.p.E = 2.8e7;  // EA = 2.8e7 N, far above the bending modes
  light.p.I = 14000.0 / 2.8e7;
  const double t_end = quick ? 16.0 : 20.0;
  const Beam beams[2] = {aluminium, light};
  for (int b = 0; b < (quick ? 1 : 2); ++b) {
    const Beam& beam = beams[b];
    for (double rate : {4.0, 10.0}) {
      if (quick && rate != 4.0) continue;
      SpinUpBeamParameters p = beam.p;
      p.spin_rate = rate;
      p.spin_up_time = 15.0;
      char group[64];
      std::snprintf(group, sizeof group, "%s %.0f rad/s", beam.name, rate);
      run(group, p, "module 8 clamped frame", BodyBasis::clamped_frame, make_ffrf_body, t_end);
      run(group, p, "stiffened clamped frame", BodyBasis::clamped_frame, make_stiffened_ffrf_body, t_end);
      run(group, p, "stiffened centroid frame", BodyBasis::craig_bampton, make_stiffened_ffrf_body, t_end);
    }
  }
  return 0;
}
