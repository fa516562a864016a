// extras.mechanisms.step_allocates_nothing: after its first steps, a step of simulate() makes no heap
// allocation, on the seven-body loop (rigid bodies) and on module 7's flexible slider-crank (its
// rod an intuitive body, module 8's full FFRF body, and its fast form ModalFfrfBody of
// extras/fast_ffrf with 16 elements and 4 modes, the bench's target case). Counts every allocation
// of this process (the counting malloc of extras/support/bench.hpp), so it is a program of its own,
// not a case of extras.mechanisms.
//
// For each case: two runs of s0 and s steps that record no point but the first and the last
// (output_interval beyond t_end); the allocations of the longer run less those of the shorter
// are the allocations of s - s0 steps, and must be zero. A case fails with its count per step.
#include <algorithm>
#include <cstdio>
#include <utility>
#include <string>

#include "bench.hpp"
#include "fmbd/ffrf.hpp"
#include "fmbd/ffrf_invariants.hpp"
#include "fmbd/flexible_examples.hpp"
#include "fmbd/mechanisms.hpp"
#include "fmbd/simulation.hpp"

using namespace fmbd;

namespace {

struct Case {
  std::string name;
  SimulationOptions options;
};

// A model, its initial state and its step (the cases run at it).
struct System {
  std::string name;
  const Model& model;
  const VecX &q0, &qd0;
  double step;
};

SimulationOptions fixed(Integrator integrator, Stabilisation stabilisation, bool work) {
  SimulationOptions o;
  o.integrator = integrator;
  o.stabilisation = stabilisation;
  o.output_interval = 1e9;  // only the first and the last point
  o.integrate_work = work;
  return o;
}

// Allocations of simulate() from the system's initial state to t_end, and its steps; the case's
// options run at the system's step.
std::pair<long, int> allocations_of(const System& system, const SimulationOptions& options, double t_end) {
  SimulationOptions o = options;
  o.step = system.step;
  const long before = bench::allocations.load();
  const Trajectory run = simulate(system.model, system.q0, system.qd0, 0.0, t_end, o);
  return {bench::allocations.load() - before, run.steps};
}

// Whether s - s0 steps of the case (50 and 250 fixed steps) allocate nothing; prints the count.
bool allocates_nothing(const System& system, const Case& c) {
  const double t0 = 50 * system.step, t1 = 250 * system.step;
  allocations_of(system, c.options, t0);  // the thread's solver buffers take their sizes here
  const auto [long_run, long_steps] = allocations_of(system, c.options, t1);
  const auto [short_run, short_steps] = allocations_of(system, c.options, t0);
  const long extra = long_run - short_run;
  const int steps = long_steps - short_steps;
  const bool ok = extra == 0 && steps > 0;
  std::printf("%s %s, %s: %ld allocations in %d steps (%.3g a step)\n", ok ? "ok  " : "FAIL", system.name.c_str(),
              c.name.c_str(), extra, steps, static_cast<double>(extra) / std::max(steps, 1));
  return ok;
}

}  // namespace

int main() {
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__)
  std::printf("no counting allocator on this platform (glibc without AddressSanitizer only): skipped\n");
  return 0;
#else
  const mechanisms::SevenBodyLoop loop = mechanisms::seven_body_loop();
  const System seven{"seven-body loop", loop.model, loop.q0, loop.qd0, 1e-3};
  const Case cases[] = {
      {"RK4 + projection (the benchmark's run)", fixed(Integrator::rk4, Stabilisation::projection, false)},
      {"RK4 + projection, work monitor on", fixed(Integrator::rk4, Stabilisation::projection, true)},
      {"RK4 + Baumgarte", fixed(Integrator::rk4, Stabilisation::baumgarte, false)},
      {"Euler, no stabilisation", fixed(Integrator::euler, Stabilisation::none, false)},
      {"Dormand-Prince + projection", fixed(Integrator::dormand_prince, Stabilisation::projection, false)},
  };
  int failed = 0;
  for (const Case& c : cases) failed += allocates_nothing(seven, c) ? 0 : 1;

  // The flexible slider-crank of module 7, its rod an IntuitiveBody, module 8's FfrfBody and the
  // fast form ModalFfrfBody (16 elements, 4 modes: fmbd-bench-ffrf's target), at steps of 10 µs
  // (1 µs for the stiffer 16-element rod, as in the bench: Euler blows up at 10 µs).
  FlexibleSliderCrankParameters target;
  target.elements = 16;
  target.modes = 4;
  const FlexibleExample intuitive = flexible_slider_crank(), ffrf = flexible_slider_crank({}, make_ffrf_body);
  const FlexibleExample fast = flexible_slider_crank(target, make_modal_ffrf_body);
  const double h = 1e-5;
  const System cranks[] = {
      {"flexible slider-crank, intuitive body", intuitive.model, intuitive.q0, intuitive.qd0, h},
      {"flexible slider-crank, FfrfBody", ffrf.model, ffrf.q0, ffrf.qd0, h},
      {"flexible slider-crank, ModalFfrfBody (16 elements, 4 modes)", fast.model, fast.q0, fast.qd0, 1e-6},
  };
  const Case flexible_cases[] = {
      {"RK4 + projection", fixed(Integrator::rk4, Stabilisation::projection, false)},
      {"RK4 + Baumgarte, work monitor on", fixed(Integrator::rk4, Stabilisation::baumgarte, true)},
      {"Euler, no stabilisation", fixed(Integrator::euler, Stabilisation::none, false)},
  };
  for (const System& crank : cranks)
    for (const Case& c : flexible_cases) failed += allocates_nothing(crank, c) ? 0 : 1;
  if (failed)
    std::printf("%d case(s) allocate in the step loop: a step of simulate() should write into storage sized at "
                "its start (DynamicsData, Stages, the Simulation's own vectors, a body's kept node markers)\n", failed);
  return failed ? 1 : 0;
#endif
}
