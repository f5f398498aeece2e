/// @file bench_contact_step.cpp
/// Cost of line-to-line contact in a dynamic step, on the seed paper's application (section 7.1):
/// examples/drilling-riser-drift/model.yaml (a 200-element chain-wire-chain mooring line and a
/// 100-element drilling riser with its LMRP hanging from a free semisubmersible; current, regular
/// waves, seabed with friction; dt = 0.01 s).
///
/// Two situations, each with the contact block as in the file and with contact switched off:
///  - BM_DriftStep/{0,1}: the example from its static equilibrium, riser and mooring line ~30 m apart
///    (contact on: broad phase, step limiter and step validator every step, nothing touching);
///  - BM_RiserOnMooringStep/{0,1}: the drilling unit moved 35 m (to y = -3 m) so that the riser hangs
///    against the mooring line: the static solve finds the riser resting on the line (one contact
///    point, ~3.9 kN, 218 m down the riser, 808 m from the anchor), and the dynamics run with that
///    contact active (with contact off the riser passes through the line).
/// Each iteration runs 2 s of dynamics (~200 steps) from the static equilibrium; the timed region is
/// Simulation::runDynamics only (manual time = its wall time). Argument: 1 = contact on, 0 = off.
/// Counters: time per step [s], steps, Newton iterations per step, contact points at the end.
/// Target (issue 4): contact adds at most 20 % to the time of a step.
///
/// Profile with e.g. valgrind --tool=callgrind ./bench_contact_step --benchmark_filter=RiserOnMooring/1
/// --benchmark_min_time=1x.

#include <benchmark/benchmark.h>

#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace {

const std::string kModel = std::string(TANGLE_EXAMPLES_DIR) + "/drilling-riser-drift/model.yaml";

tangle::model::ModelSpec loadModel(bool contact, bool onMooring) {
  tangle::model::ModelSpec spec = tangle::io::readModelFile(kModel);
  spec.dynamics.duration = 2.0;
  spec.dynamics.outputInterval = spec.dynamics.duration;
  spec.output.vtk = false;
  spec.output.plots = false;
  spec.contact.enabled = contact;
  if (onMooring)
    for (tangle::model::VesselSpec& v : spec.vessels)
      if (v.name == "drilling_unit") v.position.y() = -3.0;
  return spec;
}

void runStep(benchmark::State& state, bool onMooring) {
  const bool contact = state.range(0) != 0;
  const tangle::model::ModelSpec spec = loadModel(contact, onMooring);
  double wall = 0.0;
  long steps = 0, newton = 0;
  int points = 0;
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
    wall += r.wallSeconds;
    steps += r.steps;
    newton += r.newtonIterations;
    points = 0;
    if (sim.contact())
      for (const auto& p : sim.contact()->contacts()) points += p.normalForce > 0.0 ? 1 : 0;
  }
  if (steps > 0) {
    state.counters["time_per_step"] = wall / static_cast<double>(steps);
    state.counters["steps"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kAvgIterations);
    state.counters["newton_per_step"] = static_cast<double>(newton) / static_cast<double>(steps);
    state.counters["contact_points"] = points;
  }
}

void BM_DriftStep(benchmark::State& state) { runStep(state, false); }
BENCHMARK(BM_DriftStep)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_RiserOnMooringStep(benchmark::State& state) { runStep(state, true); }
BENCHMARK(BM_RiserOnMooringStep)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
