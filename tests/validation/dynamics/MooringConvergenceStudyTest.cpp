// Validation-label convergence study of the mooring line dynamics (the long version of
// tests/verification/dynamics/MooringConvergenceTest.cpp; see tests/validation/dynamics/README.md).
//
// examples/mooring-dynamics/model.yaml (fairlead 5 m / 10 s in-line, 10 s ramp, generalized-alpha
// rho_inf = 0.8), run for 100 s; quantity: the fairlead tension range (max - min of the fairlead reaction
// magnitude) over the last five periods, t = 50..100 s, sampled every 0.01 s (0.02 s for dt = 0.02 s).
// Self-convergence (Roache 1998, ch. 5): successive halvings of the time step (0.02 .. 0.0025 s, 200
// elements) and doublings of the mesh (100 .. 800 elements, dt = 0.005 s) must change the range by
// less than 2 % (issue bound) -- for the mesh, the raw range converges slowly because of the touchdown
// chatter on the undamped penalty seabed (see the verification test), so as there: the changes must
// decrease, the last one be < 2 %, and the range of the 0.31 s moving average be converged to 2 % from
// 100 elements on. Measured values: docs/verification-dynamics.md. Cost: about 1 min in Release on one
// core.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kDuration = 100.0;    // [s]
constexpr double kWindowStart = 50.0;  // last five periods [s]

struct RangeResult {
  double range = 0.0;          // [N]
  double filteredRange = 0.0;  // range of the 0.31 s centred moving average [N]
};

RangeResult runMooring(double dt, double outputInterval, const std::array<int, 3>& elements) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/mooring-dynamics/model.yaml");
  spec.dynamics.duration = kDuration;
  spec.dynamics.rampTime = 10.0;
  spec.dynamics.timeStep = dt;
  // (dt, output interval, duration) avoid a round-off sliver last step (see the report on
  // DynamicAnalysis::run in docs/verification-dynamics.md).
  spec.dynamics.outputInterval = outputInterval;
  spec.output.vtk = false;
  spec.output.plots = false;
  for (int s = 0; s < 3; ++s) spec.lines.at(0).sections.at(s).elements = elements[s];
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  EXPECT_TRUE(statics.converged) << statics.message;
  std::vector<double> time, tension;
  const time::DynamicResult r = sim.runDynamics([&](const model::State& state, const VecX&) {
    time.push_back(state.time);
    tension.push_back(sim.snapshot(true).at(0).endForceB.norm());
  });
  EXPECT_TRUE(r.completed) << r.message;
  const int half = std::max(1, static_cast<int>(std::lround(0.15 / outputInterval)));
  double lo = 1e300, hi = -1e300, flo = 1e300, fhi = -1e300;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < kWindowStart - 1e-9) continue;
    lo = std::min(lo, tension[i]);
    hi = std::max(hi, tension[i]);
    if (static_cast<int>(i) - half < 0 || i + half >= time.size()) continue;
    double sum = 0.0;
    for (int k = -half; k <= half; ++k) sum += tension[i + k];
    flo = std::min(flo, sum / (2 * half + 1));
    fhi = std::max(fhi, sum / (2 * half + 1));
  }
  std::printf("dt = %.4f s, elements %d/%d/%d: fairlead tension range %.1f N (filtered %.1f N), wall %.2f s\n", dt,
              elements[0], elements[1], elements[2], hi - lo, fhi - flo, r.wallSeconds);
  return {hi - lo, fhi - flo};
}

double relativeChange(double coarse, double fine) { return std::abs(coarse - fine) / fine; }

TEST(MooringConvergenceStudy, TensionRangeConvergedInTimeStep) {
  const std::array<int, 3> mesh{40, 130, 30};
  std::vector<RangeResult> r;
  r.push_back(runMooring(0.02, 0.02, mesh));
  for (double dt : {0.01, 0.005, 0.0025}) r.push_back(runMooring(dt, 0.01, mesh));
  // Issue bound: 2 % per halving of the step.
  for (std::size_t i = 0; i + 1 < r.size(); ++i)
    EXPECT_LT(relativeChange(r[i].range, r[i + 1].range), 0.02) << "halving " << i + 1;
}

TEST(MooringConvergenceStudy, TensionRangeConvergedInMesh) {
  const std::array<std::array<int, 3>, 4> meshes{{{20, 65, 15}, {40, 130, 30}, {80, 260, 60}, {160, 520, 120}}};
  std::vector<RangeResult> r;
  for (const auto& m : meshes) r.push_back(runMooring(0.005, 0.01, m));
  std::vector<double> change;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    change.push_back(relativeChange(r[i].range, r[i + 1].range));
    EXPECT_LT(relativeChange(r[i].filteredRange, r[i + 1].filteredRange), 0.02) << "refinement " << i + 1;
  }
  for (std::size_t i = 0; i + 1 < change.size(); ++i) EXPECT_LT(change[i + 1], change[i]) << "refinement " << i + 2;
  EXPECT_LT(change.back(), 0.02);
}

}  // namespace
}  // namespace tangle
