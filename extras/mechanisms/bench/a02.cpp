// Benchmark: the accuracy of module 4's simulate() on the N-four-bar mechanism (problem A02 of the
// IFToMM library of computational benchmark problems, fmbd/mechanisms.hpp) against its exact
// one-degree-of-freedom motion, through every flat position (where C_q loses N ranks). Prints CSV
// rows "group,case,quantity,value,unit" without a header, per case (windows, span, integrator):
//
//   position_error   the largest distance (max norm) of B0 from the exact motion at 100 output
//                    points per second [m]; the benchmark's tolerance is 1e-3 m;
//   energy_drift     the largest |E - E0| at those points [J];
//   reached          the time the run reached: the span, or where it stopped (the error on stderr;
//                    0 for an error that carries no time);
//   steps, rejected_steps   accepted steps and steps taken again;
//   seconds          the wall time of the run (printed, never checked).
//
// The cases: 4 and 10 windows for 10 s, and the benchmark's 40 windows for 20 s, each with RK4
// and projection at h = 1e-3 and 1e-4 s, and Dormand-Prince with projection at rtol 1e-6 and 1e-9.
// The 40-window RK4 run at 1e-4 s takes several minutes.
//
// Options: --quick (4 windows, 0.5 s: a smoke test), --windows N and --span T (one chain only),
// --method TEXT (only the methods whose name contains TEXT, e.g. "Dormand" or "h=1e-3").
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "fmbd/mechanisms.hpp"
#include "fmbd/simulation.hpp"
#include "bench.hpp"

using namespace fmbd;
using fmbd::bench::row;
using fmbd::bench::seconds;

namespace {

constexpr double kOutput = 0.01;  // output interval [s]

struct Method {
  std::string name;
  SimulationOptions options;
};

std::vector<Method> methods() {
  std::vector<Method> out;
  for (double h : {1e-3, 1e-4}) {
    SimulationOptions o;
    o.integrator = Integrator::rk4;
    o.step = h;
    o.stabilisation = Stabilisation::projection;
    o.output_interval = kOutput;
    out.push_back({std::string("RK4 + projection h=") + (h == 1e-3 ? "1e-3" : "1e-4"), o});
  }
  for (double rtol : {1e-6, 1e-9}) {
    SimulationOptions o;
    o.integrator = Integrator::dormand_prince;
    o.rtol = rtol;
    o.atol = 1e-3 * rtol;
    o.step = 1e-3;
    o.stabilisation = Stabilisation::projection;
    o.output_interval = kOutput;
    out.push_back({std::string("Dormand-Prince + projection rtol=") + (rtol == 1e-6 ? "1e-6" : "1e-9"), o});
  }
  return out;
}

void run_case(int windows, double span, const std::string& only) {
  const mechanisms::FourBarChain chain = mechanisms::four_bar_chain(windows);
  const std::vector<double> theta = mechanisms::four_bar_chain_theta(windows, kOutput, span);
  for (const Method& m : methods()) {
    if (m.name.find(only) == std::string::npos) continue;
    const std::string name = "A02 " + std::to_string(windows) + " windows " +
                             std::to_string(static_cast<int>(span)) + " s " + m.name;
    Trajectory run;
    double reached = span;
    const double wall = seconds([&] {
      try {
        run = simulate(chain.model, chain.q0, chain.qd0, 0.0, span, m.options);
      } catch (const IntegrationError& e) {
        reached = e.t;
        std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
      } catch (const std::exception& e) {  // a stage without acceleration: its message has the time
        reached = 0;
        std::fprintf(stderr, "%s: %s\n", name.c_str(), e.what());
      }
    });
    if (reached == span) {
      const mechanisms::FourBarChainError e = mechanisms::four_bar_chain_error(run, theta);
      row("a02", name, "position_error", e.position, "m");
      row("a02", name, "energy_drift", e.energy, "J");
      row("a02", name, "steps", run.steps, "1");
      row("a02", name, "rejected_steps", run.rejected_steps, "1");
    }
    row("a02", name, "reached", reached, "s");
    row("a02", name, "seconds", wall, "s");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int windows = 0;
  double span = 0;
  bool quick = false;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--windows") == 0 && i + 1 < argc) {
      windows = std::stoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--span") == 0 && i + 1 < argc) {
      span = std::stod(argv[++i]);
    } else if (std::strcmp(argv[i], "--method") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--windows N] [--span SECONDS] [--method TEXT]\n", argv[0]);
      return 2;
    }
  }
  try {
    if (quick) {
      run_case(4, 0.5, only);
    } else if (windows > 0) {
      run_case(windows, span > 0 ? span : 10.0, only);
    } else {
      run_case(4, 10.0, only);
      run_case(10, 10.0, only);
      run_case(40, 20.0, only);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fmbd-bench-a02: %s\n", e.what());
    return 1;
  }
  return 0;
}
