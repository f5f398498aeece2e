// Dynamic verification, convergence of a mooring line response (issue 3, item 5).
//
// examples/mooring-dynamics/model.yaml: the 1130 m chain-wire-chain benchmark line (345 m water, 200
// elements) with its fairlead moved in-line, 5 m amplitude, 10 s period, ramped in over 10 s, integrated
// with generalized-alpha (rho_inf = 0.8). Quantity: the fairlead tension range (max - min of the
// magnitude of the fairlead reaction, inertia included, sampled at every step) over the last period of a
// 30 s run (t = 20..30 s; the response is periodic from the second period on: the range per period
// varies by < 1 % between t = 20 and 60 s). There is no closed form: this is a self-convergence study
// (solution verification, Roache 1998, "Verification and validation in computational science and
// engineering", ch. 5): successive refinements of the time step and of the mesh must change the range
// by less than 2 % (issue bound). Longer runs (100 s, finer steps and meshes): tests/validation/dynamics.
//
// Measured (docs/verification-dynamics.md has the tables). Time step at 200 elements: 0.02 -> 0.01 s
// changes the range by 0.46 %, 0.01 -> 0.005 s by 0.30 %. Mesh at dt = 0.01 s: 50 -> 100 elements
// 14 %, 100 -> 200 4.9 %, 200 -> 400 1.9 %, 400 -> 800 0.35 %. The mesh convergence of the raw range is
// slow because of high-frequency content (3-5 Hz, rms 1.5 kN at 200 elements) from nodes landing on the
// undamped penalty seabed (normal stiffness 1e5 N/m/m, zero damping in the example; a seabed damping of
// 4000 N s/m/m cuts that rms by 58 %): coarser meshes land heavier nodes. The
// same range of a 0.31 s centred moving average of the tension (which removes that content and keeps the
// 0.1 Hz response and its low harmonics) changes by 4.1 %, 0.34 %, 0.31 %, 0.006 %. So the mesh
// assertions are: the changes decrease with refinement (convergence), the last one (400 -> 800) is below
// 2 %, and the filtered range is converged to 2 % from 100 elements on. The benchmark's 200 elements are
// 2.2 % above the 800-element range.

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

constexpr double kDuration = 30.0;     // [s]
constexpr double kWindowStart = 20.0;  // last period [s]

struct RangeResult {
  double range = 0.0;          // max - min of the fairlead tension in the window [N]
  double filteredRange = 0.0;  // same for its 0.3 s centred moving average [N]
  double wallSeconds = 0.0;
};

/// Runs the benchmark line with the given step and elements per section (chain, wire, chain).
RangeResult runMooring(double dt, const std::array<int, 3>& elements) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/mooring-dynamics/model.yaml");
  spec.dynamics.duration = kDuration;
  spec.dynamics.rampTime = 10.0;
  spec.dynamics.timeStep = dt;
  // Output at every step so that max and min are not missed between samples. (Step, output interval and
  // duration are chosen so that the run does not end on a round-off sliver step; see the report on
  // DynamicAnalysis::run.)
  spec.dynamics.outputInterval = dt;
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
  RangeResult out;
  out.wallSeconds = r.wallSeconds;
  const int half = std::max(1, static_cast<int>(std::lround(0.15 / dt)));  // window 2 half + 1 samples
  double lo = 1e300, hi = -1e300, flo = 1e300, fhi = -1e300;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < kWindowStart - 1e-9) continue;
    lo = std::min(lo, tension[i]);
    hi = std::max(hi, tension[i]);
    if (static_cast<int>(i) - half < 0 || i + half >= time.size()) continue;
    double sum = 0.0;
    for (int k = -half; k <= half; ++k) sum += tension[i + k];
    const double f = sum / (2 * half + 1);
    flo = std::min(flo, f);
    fhi = std::max(fhi, f);
  }
  out.range = hi - lo;
  out.filteredRange = fhi - flo;
  std::printf("dt = %.4f s, elements %d/%d/%d: fairlead tension range %.1f N (filtered %.1f N), wall %.2f s\n", dt,
              elements[0], elements[1], elements[2], out.range, out.filteredRange, out.wallSeconds);
  return out;
}

double relativeChange(double coarse, double fine) { return std::abs(coarse - fine) / fine; }

TEST(MooringConvergenceTest, TensionRangeConvergedInTimeStep) {
  const std::array<int, 3> mesh{40, 130, 30};  // the benchmark's 200 elements
  const RangeResult r02 = runMooring(0.02, mesh);
  const RangeResult r01 = runMooring(0.01, mesh);
  const RangeResult r005 = runMooring(0.005, mesh);
  // Issue bound 2 % per halving (measured 0.46 % and 0.30 %; what remains is the touchdown chatter,
  // whose phase depends on dt, see the file comment).
  EXPECT_LT(relativeChange(r02.range, r01.range), 0.02);
  EXPECT_LT(relativeChange(r01.range, r005.range), 0.02);
  // Gross-change guard only: the response is strongly dynamic (static solutions with the fairlead at
  // -5, 0, +5 m give 321.2, 308.3, 296.7 kN, a quasi-static range of 24 kN, against ~199 kN here; the
  // line's inertia dominates and drag limits it: without drag the range is 451 kN with near-slack
  // minima, without added mass 198 kN), and its first harmonic, 187.7 kN peak to peak, is converged in
  // step and mesh to 0.1 %.
  EXPECT_GT(r005.range, 1.5e5);
  EXPECT_LT(r005.range, 2.5e5);
}

TEST(MooringConvergenceTest, TensionRangeConvergedInMesh) {
  const std::array<std::array<int, 3>, 5> meshes{{{10, 32, 8}, {20, 65, 15}, {40, 130, 30}, {80, 260, 60}, {160, 520, 120}}};
  std::vector<RangeResult> r;
  for (const auto& m : meshes) r.push_back(runMooring(0.01, m));
  std::vector<double> change, filteredChange;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    change.push_back(relativeChange(r[i].range, r[i + 1].range));
    filteredChange.push_back(relativeChange(r[i].filteredRange, r[i + 1].filteredRange));
  }
  // Convergence: every doubling of the mesh changes the range less than the previous one.
  for (std::size_t i = 0; i + 1 < change.size(); ++i) EXPECT_LT(change[i + 1], change[i]) << "refinement " << i + 1;
  // Issue bound 2 % for the last refinement (400 -> 800 elements; measured 0.35 %).
  EXPECT_LT(change.back(), 0.02);
  // The low-frequency response (0.31 s moving average) is converged to 2 % from 100 elements on (measured
  // 0.34 %, 0.31 %, 0.006 %).
  for (std::size_t i = 1; i < filteredChange.size(); ++i) EXPECT_LT(filteredChange[i], 0.02) << "refinement " << i;
}

}  // namespace
}  // namespace tangle
