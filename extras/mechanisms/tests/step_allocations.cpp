// extras.mechanisms.step_allocates_nothing: after its first steps, a step of simulate() makes no heap
// allocation. Counts every allocation of this process (the counting malloc of
// extras/support/bench.hpp), so it is a program of its own, not a case of extras.mechanisms.
//
// For each case: two runs of s0 and s steps that record no point but the first and the last
// (output_interval beyond t_end); the allocations of the longer run less those of the shorter
// are the allocations of s - s0 steps, and must be zero. A case fails with its count per step.
#include <algorithm>
#include <cstdio>
#include <utility>
#include <string>

#include "bench.hpp"
#include "fmbd/mechanisms.hpp"
#include "fmbd/simulation.hpp"

using namespace fmbd;

namespace {

struct Case {
  std::string name;
  SimulationOptions options;
};

SimulationOptions fixed(Integrator integrator, Stabilisation stabilisation, bool work) {
  SimulationOptions o;
  o.integrator = integrator;
  o.step = 1e-3;
  o.stabilisation = stabilisation;
  o.output_interval = 1e9;  // only the first and the last point
  o.integrate_work = work;
  return o;
}

// Allocations of simulate() from the loop's initial state to t_end, and its steps.
std::pair<long, int> allocations_of(const mechanisms::SevenBodyLoop& loop, const SimulationOptions& o, double t_end) {
  const long before = bench::allocations.load();
  const Trajectory run = simulate(loop.model, loop.q0, loop.qd0, 0.0, t_end, o);
  return {bench::allocations.load() - before, run.steps};
}

}  // namespace

int main() {
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__)
  std::printf("no counting allocator on this platform (glibc without AddressSanitizer only): skipped\n");
  return 0;
#else
  const mechanisms::SevenBodyLoop loop = mechanisms::seven_body_loop();
  const Case cases[] = {
      {"RK4 + projection (the benchmark's run)", fixed(Integrator::rk4, Stabilisation::projection, false)},
      {"RK4 + projection, work monitor on", fixed(Integrator::rk4, Stabilisation::projection, true)},
      {"RK4 + Baumgarte", fixed(Integrator::rk4, Stabilisation::baumgarte, false)},
      {"Euler, no stabilisation", fixed(Integrator::euler, Stabilisation::none, false)},
      {"Dormand-Prince + projection", fixed(Integrator::dormand_prince, Stabilisation::projection, false)},
  };
  int failed = 0;
  for (const Case& c : cases) {
    const double t0 = 0.05, t1 = 0.25;  // 50 and 250 fixed steps of 1 ms
    allocations_of(loop, c.options, t0);  // the thread's solver buffers take their sizes here
    const auto [long_run, long_steps] = allocations_of(loop, c.options, t1);
    const auto [short_run, short_steps] = allocations_of(loop, c.options, t0);
    const long extra = long_run - short_run;
    const int steps = long_steps - short_steps;
    const bool ok = extra == 0 && steps > 0;
    failed += ok ? 0 : 1;
    std::printf("%s seven-body loop, %s: %ld allocations in %d steps (%.3g a step)\n", ok ? "ok  " : "FAIL",
                c.name.c_str(), extra, steps, static_cast<double>(extra) / std::max(steps, 1));
  }
  if (failed)
    std::printf("%d case(s) allocate in the step loop: a step of simulate() should write into storage sized at "
                "its start (DynamicsData, Stages, the Simulation's own vectors)\n", failed);
  return failed ? 1 : 0;
#endif
}
