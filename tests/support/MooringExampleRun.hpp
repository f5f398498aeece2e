#pragma once
// Dynamic runs of the mooring example (examples/mooring-dynamics) recording the fairlead tension of every
// line at every step, optionally with another Newton path (dynamics.solver: `assembly: whole`, every Newton
// iteration on the whole model; `matrix_refresh: when_slow`, no refresh by the renewal rule): the set-up
// of the verification tests of the iterations on a part, by independent blocks and of the refresh rule
// (issue 8).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "DynamicRun.hpp"
#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle::test {

/// A run: its result, the time of every step [s] and each line's fairlead (end B) tension then [N].
struct FairleadRun {
  time::DynamicResult result;
  std::vector<double> time;
  std::vector<std::vector<double>> tension;
};

/// Newton tolerance of the comparison runs [-]: 1e-8 of the line's weight, where every solver switch gives the
/// converged answer to within a few newtons (measured on the in-line line, 30 s: 7 N at a step, 2.6e-5 of the
/// fairlead tension range between any two switches). At the default 1e-6 the latitude is the touchdown
/// chatter's (3-5 Hz, no seabed damping), which shifts its phase: 1e-6 against 1e-8 moved a step's tension by
/// 753 N (3.8e-3 of the 199 kN range) and the range by 1.8e-3, and the switches at 1e-6 differed by up to
/// 1088 N and 2.7e-3 from each other: no sharp check of a switch at that tolerance.
inline constexpr double kComparisonTolerance = 1.0e-8;

/// The Newton paths the fast default is compared with (dynamics.solver).
inline model::DynamicSolverSpec wholeAssembly() {
  model::DynamicSolverSpec s;
  s.partIterations = false;
  return s;
}
inline model::DynamicSolverSpec wholeRefresh() {
  model::DynamicSolverSpec s;
  s.blockRefresh = false;
  return s;
}
inline model::DynamicSolverSpec whenSlow() {
  model::DynamicSolverSpec s;
  s.renewalRule = false;
  return s;
}
inline model::DynamicSolverSpec extrapolatedPredictor() {
  model::DynamicSolverSpec s;
  s.seabedPredictor = false;
  return s;
}

/// Runs the mooring example for `duration` s with output at every step, at the tolerance
/// kComparisonTolerance. With azimuths [deg], its line is copied around a point instead: fairleads on a 20 m
/// circle, anchors 1000 m further out, each fairlead moved as the example's (5 m / 10 s along x). `solver`:
/// the Newton path (dynamics.solver; the default: the fast path). `timeStep` [s] (0: the example's 0.01 s)
/// and `tolerance` [-] replace the example's step and the comparison tolerance. With `errorTolerance` > 0 the
/// steps follow the local error estimate (dynamics.error_tolerance, up to 0.05 s), and the tension is
/// recorded at the output times of every 0.1 s, which every run lands on.
inline FairleadRun runMooringExample(double duration, const model::DynamicSolverSpec& solver = {},
                                     const std::vector<double>& azimuthsDeg = {}, double timeStep = 0.0,
                                     double tolerance = kComparisonTolerance, double errorTolerance = 0.0) {
  model::ModelSpec spec = io::readModelFile(std::string(kExamplesDir) + "/mooring-dynamics/model.yaml");
  if (!azimuthsDeg.empty()) {
    const model::LineSpec base = spec.lines.at(0);
    spec.lines.clear();
    for (std::size_t k = 0; k < azimuthsDeg.size(); ++k) {
      model::LineSpec line = base;
      line.name = "line" + std::to_string(k + 1);
      const double az = azimuthsDeg[k] * 3.141592653589793 / 180.0;
      const Vec3 out(std::cos(az), std::sin(az), 0.0);
      line.endB.position = Vec3(0.0, 0.0, base.endB.position.z()) + 20.0 * out;
      line.endA.position = Vec3(0.0, 0.0, base.endA.position.z()) + 1020.0 * out;
      spec.lines.push_back(line);
    }
  }
  spec.dynamics.duration = duration;
  if (timeStep > 0.0) spec.dynamics.timeStep = timeStep;
  spec.dynamics.tolerance = tolerance;
  spec.dynamics.outputInterval = spec.dynamics.timeStep;  // every step
  if (errorTolerance > 0.0) {
    spec.dynamics.errorTolerance = errorTolerance;
    spec.dynamics.maxTimeStep = 0.05;
    spec.dynamics.outputInterval = 0.1;
  }
  const std::size_t lines = spec.lines.size();
  const std::unique_ptr<analysis::Simulation> sim = simulationAfterStatics(std::move(spec), solver);
  FairleadRun run;
  run.tension.resize(lines);
  run.result = sim->runDynamics([&](const model::State& state, const VecX&) {
    run.time.push_back(state.time);
    const std::vector<solver::LineSnapshot> snap = sim->snapshot(true);
    for (std::size_t l = 0; l < lines; ++l) run.tension[l].push_back(snap.at(l).endForceB.norm());
  });
  return run;
}

/// Records a run's solver counts as properties of the running test, suffixed by `run`: iterations_<run>,
/// refreshes_<run> and step_length_changes_<run> (the dynamics summary's newton_iterations, matrix_refreshes
/// and matrix_step_length_changes).
inline void recordSolverCounts(const std::string& run, const time::DynamicResult& r) {
  ::testing::Test::RecordProperty("iterations_" + run, std::to_string(r.newtonIterations));
  ::testing::Test::RecordProperty("refreshes_" + run, std::to_string(r.matrixRefreshes));
  ::testing::Test::RecordProperty("step_length_changes_" + run, std::to_string(r.matrixStepLengthChanges));
}

/// Range (max - min) of a line's fairlead tension from time `start` on [N].
inline double rangeAfter(const FairleadRun& r, std::size_t line, double start) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < r.time.size(); ++i)
    if (r.time[i] >= start - 1e-9) {
      lo = std::min(lo, r.tension[line][i]);
      hi = std::max(hi, r.tension[line][i]);
    }
  return hi - lo;
}

/// Largest difference [N] of a line's fairlead tension between two runs, step by step. The runs must have
/// taken the same steps (a failure is recorded otherwise, and the difference is infinite).
inline double largestTensionDifference(const FairleadRun& a, const FairleadRun& b, std::size_t line) {
  if (a.time != b.time) {
    ADD_FAILURE() << "the runs took different steps (" << a.time.size() << " and " << b.time.size() << ")";
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < a.time.size(); ++i)
    worst = std::max(worst, std::abs(a.tension[line][i] - b.tension[line][i]));
  return worst;
}

/// The check of a solver switch's verification tests (parts, blocks, refresh rule): `other` has the response
/// of `reference` on a line within the convergence tolerance's latitude: its fairlead tension range over the
/// last 10 s of the 30 s runs (from 20 s) within 1e-4 of the reference's (4 times the largest difference
/// measured between switches at kComparisonTolerance), and every step's tension within `stepBound` [N].
/// Returns the largest step difference [N].
inline double expectSameFairleadResponse(const FairleadRun& reference, const FairleadRun& other,
                                         std::size_t line, double stepBound) {
  const double range = rangeAfter(reference, line, 20.0);
  EXPECT_NEAR(rangeAfter(other, line, 20.0), range, 1e-4 * range) << "line " << line + 1;
  const double worst = largestTensionDifference(reference, other, line);
  EXPECT_LT(worst, stepBound) << "line " << line + 1;
  return worst;
}

}  // namespace tangle::test
