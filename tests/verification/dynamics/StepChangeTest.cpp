// Dynamic verification of the kept matrix made for a new step length with the mass matrix alone
// (dynamics.solver.step_change: rescale, NewtonIteration::startAttempt; theory manual 8.2).
//
// Like every choice of dynamics.solver it changes which matrix the modified Newton iterations use, not the
// convergence test on the exact residual: the answer is another solution within the same tolerance. Checked
// on the mooring example (200 bars, fairlead 5 m / 10 s) for 30 s with error-controlled steps (error
// tolerance 1e-4, steps up to 0.05 s): the step length changes at nearly every step, and `refresh` assembles
// the matrix again at each change. Measured (2026-12-05): 7 527 steps either way, 337 refreshes and 915
// rescales against 1 053 refreshes, 22 609 against 22 064 residual evaluations. The fairlead tension at the
// output times (every 0.1 s, which both runs land on) within the comparison of the other solver switches: the
// range over the last 10 s within 1e-4, every output within 5e-5 of the range
// (test::expectSameFairleadResponse; the runs at Newton tolerance 1e-8, test::kComparisonTolerance).

#include <gtest/gtest.h>

#include <string>

#include "support/MooringExampleRun.hpp"

namespace tangle {
namespace {

TEST(StepChangeTest, MooringLineWithErrorControlFewerRefreshesSameResponseWithinTheConvergenceTolerance) {
  model::DynamicSolverSpec refresh;
  refresh.stepChangeRescale = false;
  constexpr double kErrorTolerance = 1e-4;
  const test::FairleadRun assembled =
      test::runMooringExample(30.0, refresh, {}, 0.0, test::kComparisonTolerance, kErrorTolerance);
  const test::FairleadRun rescaled =
      test::runMooringExample(30.0, {}, {}, 0.0, test::kComparisonTolerance, kErrorTolerance);
  ASSERT_TRUE(assembled.result.completed) << assembled.result.message;
  ASSERT_TRUE(rescaled.result.completed) << rescaled.result.message;
  EXPECT_EQ(assembled.result.matrixStepLengthChanges, 0);
  // Most changes of step length are made without an assembly, and the refreshes fall by more than those.
  EXPECT_GT(rescaled.result.matrixStepLengthChanges, rescaled.result.steps / 20);
  EXPECT_LT(rescaled.result.matrixRefreshes + rescaled.result.matrixStepLengthChanges / 2,
            assembled.result.matrixRefreshes);
  const double range = test::rangeAfter(assembled, 0, 20.0);
  const double worst = test::expectSameFairleadResponse(assembled, rescaled, 0, 5e-5 * range);
  RecordProperty("largest_tension_difference_N", std::to_string(worst));
  RecordProperty("steps", std::to_string(rescaled.result.steps));
  test::recordSolverCounts("rescale", rescaled.result);
  test::recordSolverCounts("refresh", assembled.result);
}

}  // namespace
}  // namespace tangle
