/// @file bench_dynamics.cpp
/// Dynamic analysis of the benchmark mooring line, examples/mooring-dynamics/model.yaml: the
/// 200-element chain-wire-chain line of examples/catenary-mooring with its fairlead moved in-line,
/// amplitude 5 m, period 10 s (ramped in over 10 s), generalized-alpha (rho_inf = 0.8), dt = 0.01 s,
/// Morison drag and added mass, penalty seabed. No output is written (the observer is empty).
///
/// Benchmarks (manual timing = wall time of Simulation::runDynamics only; reading, meshing and the
/// static solve that gives the initial condition are outside the timed region):
///  - BM_MooringDynamics/200: the example's 200 s;
///  - BM_MooringDynamics/20: 20 s, for quick runs (ramp and first period only, so a slightly lower
///    Newton iteration count per step than the long run).
/// Counters: real-time factor (simulated time / wall time), steps, Newton iterations per step.
///
/// Profile it with, e.g., valgrind --tool=callgrind ./bench_dynamics --benchmark_filter=BM_MooringDynamicsShort
/// (BM_MooringDynamicsShort/5: 5 s simulated, one iteration).

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace {

const std::string kModel = std::string(TANGLE_EXAMPLES_DIR) + "/mooring-dynamics/model.yaml";

void runMooring(benchmark::State& state) {
  tangle::model::ModelSpec spec = tangle::io::readModelFile(kModel);
  spec.dynamics.duration = static_cast<double>(state.range(0));
  spec.output.vtk = false;
  spec.output.plots = false;
  double simulated = 0.0, wall = 0.0;
  long steps = 0, newton = 0;
  for (auto _ : state) {
    tangle::analysis::Simulation sim(spec);
    const tangle::solver::StaticResult statics = sim.solveStatics();
    if (!statics.converged) {
      state.SkipWithError(statics.message.c_str());
      break;
    }
    const tangle::time::DynamicResult r = sim.runDynamics({}, false);
    if (!r.completed) {
      state.SkipWithError(r.message.c_str());
      break;
    }
    state.SetIterationTime(r.wallSeconds);
    simulated += r.endTime;
    wall += r.wallSeconds;
    steps += r.steps;
    newton += r.newtonIterations;
  }
  if (wall > 0.0) {
    state.counters["real_time_factor"] = simulated / wall;
    state.counters["steps"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
    state.counters["newton_per_step"] = static_cast<double>(newton) / static_cast<double>(steps);
  }
}

void BM_MooringDynamics(benchmark::State& state) { runMooring(state); }
BENCHMARK(BM_MooringDynamics)->Arg(200)->Arg(20)->UseManualTime()->Unit(benchmark::kSecond)->MinTime(1.0);

void BM_MooringDynamicsShort(benchmark::State& state) { runMooring(state); }
BENCHMARK(BM_MooringDynamicsShort)->Arg(5)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
