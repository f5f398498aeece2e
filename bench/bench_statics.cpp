/// @file bench_statics.cpp
/// Static analysis of the benchmark mooring line, examples/catenary-mooring/model.yaml: 1130 m of
/// chain 76 / wire 96 / chain 76 in 345 m of water, 200 bar elements (603 DOF), anchored 1000 m from a
/// fairlead 20 m below the surface, frictionless seabed. Newton from the analytic catenary shape.
///
/// Benchmarks (wall time, milliseconds):
///  - BM_StaticsEndToEnd: read and check the YAML file, mesh, build the initial shape, solve;
///  - BM_StaticSolve: the solve alone (Simulation::solveStatics from the initial shape; the model is
///    read once and the Simulation built outside the timed region).
/// Counters: Newton iterations, fairlead tension [kN] (sanity: ~308 kN, see the example's header).

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace {

const std::string kModel = std::string(TANGLE_EXAMPLES_DIR) + "/catenary-mooring/model.yaml";

void reportSolution(benchmark::State& state, tangle::analysis::Simulation& sim, const tangle::solver::StaticResult& r) {
  if (!r.converged) {
    state.SkipWithError(r.message.c_str());
    return;
  }
  state.counters["newton_iterations"] = r.iterations;
  state.counters["fairlead_tension_kN"] = sim.snapshot().at(0).endForceB.norm() / 1000.0;
}

void BM_StaticsEndToEnd(benchmark::State& state) {
  for (auto _ : state) {
    tangle::analysis::Simulation sim(tangle::io::readModelFile(kModel));
    const tangle::solver::StaticResult r = sim.solveStatics();
    benchmark::DoNotOptimize(r.residual);
    state.PauseTiming();
    reportSolution(state, sim, r);
    state.ResumeTiming();
  }
}
BENCHMARK(BM_StaticsEndToEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StaticSolve(benchmark::State& state) {
  const tangle::model::ModelSpec spec = tangle::io::readModelFile(kModel);
  for (auto _ : state) {
    state.PauseTiming();
    auto sim = std::make_unique<tangle::analysis::Simulation>(spec);
    state.ResumeTiming();
    const tangle::solver::StaticResult r = sim->solveStatics();
    benchmark::DoNotOptimize(r.residual);
    state.PauseTiming();
    reportSolution(state, *sim, r);
    sim.reset();
    state.ResumeTiming();
  }
}
BENCHMARK(BM_StaticSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
