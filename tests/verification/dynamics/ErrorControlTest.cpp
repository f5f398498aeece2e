// Error-controlled time steps (dynamics.error_tolerance, docs/theory.md 8.5): a user asks for an accuracy
// and gets the largest steps that meet it.
//
// Case: the mooring example (1130 m chain-wire-chain line, fairlead moved 5 m at 10 s period), 40 s.
// Quantity: the fairlead tension range (max - min over every accepted step from t = 20 s, after the 10 s
// ramp and the start-up transient), the number a mooring analyst designs with.
// Reference: fixed steps of 2.5e-3 s (a quarter of the example's step; 1e-2 s differs from it by 0.2 %,
// so the reference is converged to ~0.01 %).
// Requirement (issue 8): the range within 1 % of the converged one at the requested accuracy. Measured
// (this test): tolerance 1e-3 -> -0.52 % in 3328 steps (the example's fixed 0.01 s takes 4000 steps for
// -0.2 %); tolerance 1e-2 -> -1.48 % in 734 steps: 1e-2 does NOT meet 1 % here, so docs/model-format.md
// recommends 1e-3 for tension ranges. Also checked: the looser request takes fewer steps and errs more
// (the controller follows the request), and with the default (0) the steps are exactly the fixed steps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

struct Range {
  double min = 1e300, max = -1e300;
  int steps = 0;
  int rejections = 0;
  double width() const { return max - min; }
};

Range fairleadRange(double dt, double tolerance) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/mooring-dynamics/model.yaml");
  spec.dynamics.duration = 40.0;
  spec.dynamics.timeStep = dt;
  spec.dynamics.errorTolerance = tolerance;
  analysis::Simulation sim(std::move(spec));
  EXPECT_TRUE(sim.solveStatics().converged);
  Range r;
  const time::DynamicResult run = sim.runDynamics(
      [](const model::State&, const VecX&) {}, false,
      [&](const model::State& s, double) {
        if (s.time < 20.0) return;
        const double t = sim.sectionSnapshot()[0].endTensionB;
        r.min = std::min(r.min, t);
        r.max = std::max(r.max, t);
      });
  EXPECT_TRUE(run.completed) << run.message;
  r.steps = run.steps;
  r.rejections = run.errorRejections;
  return r;
}

TEST(ErrorControl, FairleadTensionRangeWithinOnePercentAtTheRequestedAccuracy) {
  const Range reference = fairleadRange(2.5e-3, 0.0);
  EXPECT_EQ(reference.steps, 16000);  // fixed steps when error control is off
  const Range loose = fairleadRange(0.01, 1e-2);
  const Range tight = fairleadRange(0.01, 1e-3);
  EXPECT_NEAR(tight.width(), reference.width(), 0.01 * reference.width());
  // Fewer steps than the example's fixed 0.01 s (4000 steps) for the requested accuracy.
  EXPECT_LT(tight.steps, 4000);
  // The looser request: fewer steps, larger error.
  EXPECT_LT(loose.steps, tight.steps);
  EXPECT_GT(std::abs(loose.width() - reference.width()), std::abs(tight.width() - reference.width()));
  RecordProperty("reference_range_N", std::to_string(reference.width()));
  RecordProperty("loose_range_error", std::to_string(loose.width() / reference.width() - 1.0));
  RecordProperty("loose_steps", loose.steps);
  RecordProperty("tight_range_error", std::to_string(tight.width() / reference.width() - 1.0));
  RecordProperty("tight_steps", tight.steps);
}

}  // namespace
}  // namespace tangle
