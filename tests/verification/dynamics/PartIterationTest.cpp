// Dynamic verification of the Newton iterations on a part of the model (issue 8; theory manual 8.2).
//
// After the first correction of a step, GeneralizedAlpha moves only the nodes whose correction changes a
// force by more than 0.2 of the allowed out-of-balance (the touchdown zone of a mooring line) and
// re-evaluates only the elements around them (Assembler::assemblePart, which gives the whole model's
// entries bit for bit: tests/unit/solver/AssemblyPartTest.cpp). Every step still passes the whole
// model's convergence test, so the result is a different solution within the same tolerance, not an
// approximation of it. Checked here on the mooring example (examples/mooring-dynamics, 200 bars, fairlead
// 5 m / 10 s, ramped over 10 s), 30 s at its dt 0.01 s: against the whole-model iterations
// (TANGLE_WHOLE_ASSEMBLY) the fairlead tension of every step and its range over the last period agree
// to within what the convergence tolerance leaves open. That latitude, measured on the same 30 s with
// whole-model iterations only (the renewal rule refreshing the matrix in both runs, CSV output of 6
// digits): tolerance 1.2e-6 instead of 1e-6 of the line's weight changes the fairlead tension of some step
// by 112 N (0.6e-3 of the 199 kN range: the touchdown chatter, 3-5 Hz, shifts its phase) and the range by
// 0.6e-4; 0.8e-6 by 231 N (1.2e-3) and 3.2e-4. Measured with parts against whole: 384 N (1.9e-3, 1.7 times
// the largest tolerance spread; 183 N before the renewal rule) and 1.5e-4. Bounds: 3e-3 of the range for
// any step's tension (2.6 times the tolerance spread) and 1e-3 for the range over the last period.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/MooringExampleRun.hpp"

namespace tangle {
namespace {

using test::rangeAfter;

TEST(PartIterationTest, MooringLineSameResponseWithinTheConvergenceTolerance) {
  const test::FairleadRun whole = test::runMooringExample(30.0, "TANGLE_WHOLE_ASSEMBLY");
  const test::FairleadRun parts = test::runMooringExample(30.0);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(parts.result.completed) << parts.result.message;
  // The switch works both ways: no part without it; with it, a good share of the iterations on parts
  // (measured: 26 % over 200 s).
  EXPECT_EQ(whole.result.partIterations, 0);
  EXPECT_GT(parts.result.partIterations, parts.result.newtonIterations / 10);
  ASSERT_EQ(whole.time.size(), parts.time.size());
  const double range = rangeAfter(whole, 0, 20.0);
  const double worst = test::expectSameFairleadResponse(whole, parts, 0, 3e-3 * range);
  RecordProperty("largest_tension_difference_N", std::to_string(worst));
  RecordProperty("range_N", std::to_string(range));
}

}  // namespace
}  // namespace tangle
