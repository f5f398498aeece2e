// Dynamic verification of the predictor's correction on the seabed (issue 48; time::SeabedPredictor, theory
// manual 8.2).
//
// At a step the touchdown nodes' seabed oscillation is not resolved by (omega dt >= 1, omega^2 = k L / m),
// the predictor balances each grounded node's inertia against the change of its seabed reaction over the
// step. The prediction only moves where Newton's iterations start: every step passes the same convergence
// test, so the response is the same within the tolerance's latitude. Checked on the mooring example (200
// bars, fairlead 5 m / 10 s, undamped seabed 1e5 N/m/m; wire on the seabed: omega = 45 rad/s) at dt 0.05 s,
// where the correction acts (omega dt = 2.2):
//  - at test::kComparisonTolerance (1e-8 of the line's weight), 30 s, against the constant-acceleration
//    predictor (`dynamics.solver.predictor: extrapolated`): the fairlead tension at every step and its range
//    over the last 10 s, with the bounds of the other solver switches' tests (5e-5 and 1e-4 of the range:
//    PartIterationTest);
//  - at the large-step settings docs/model-format.md recommends (tolerance 1e-4), 40 s: the residual
//    evaluations it saves. Measured over 200 s: 3.74 against 4.16 per step (-10 %); 40 s: 3.63 against
//    4.03 (-10 %). Bound: at least 5 % fewer, a count (not a time), so the machine's load cannot move it.

#include <gtest/gtest.h>

#include <string>

#include "support/MooringExampleRun.hpp"

namespace tangle {
namespace {

constexpr double kLargeStep = 0.05;  // [s]

TEST(SeabedPredictorTest, MooringLineSameResponseWithinTheConvergenceTolerance) {
  const test::FairleadRun plain =
      test::runMooringExample(30.0, test::extrapolatedPredictor(), {}, kLargeStep);
  const test::FairleadRun seabed = test::runMooringExample(30.0, {}, {}, kLargeStep);
  ASSERT_TRUE(plain.result.completed) << plain.result.message;
  ASSERT_TRUE(seabed.result.completed) << seabed.result.message;
  const double range = test::rangeAfter(plain, 0, 20.0);
  const double worst = test::expectSameFairleadResponse(plain, seabed, 0, 5e-5 * range);
  RecordProperty("largest_tension_difference_N", std::to_string(worst));
  RecordProperty("range_N", std::to_string(range));
}

TEST(SeabedPredictorTest, FewerResidualEvaluationsAtLargeSteps) {
  constexpr double kTolerance = 1e-4;
  const test::FairleadRun plain =
      test::runMooringExample(40.0, test::extrapolatedPredictor(), {}, kLargeStep, kTolerance);
  const test::FairleadRun seabed = test::runMooringExample(40.0, {}, {}, kLargeStep, kTolerance);
  ASSERT_TRUE(plain.result.completed) << plain.result.message;
  ASSERT_TRUE(seabed.result.completed) << seabed.result.message;
  ASSERT_EQ(plain.result.steps, seabed.result.steps);
  const double perStepPlain = static_cast<double>(plain.result.newtonIterations) / plain.result.steps;
  const double perStepSeabed = static_cast<double>(seabed.result.newtonIterations) / seabed.result.steps;
  EXPECT_LT(perStepSeabed, 0.95 * perStepPlain);
  RecordProperty("evaluations_per_step_extrapolated", std::to_string(perStepPlain));
  RecordProperty("evaluations_per_step_seabed", std::to_string(perStepSeabed));
}

}  // namespace
}  // namespace tangle
