// Dynamic verification of the Newton iterations on a part of the model (issue 8; theory manual 8.2).
//
// After the first correction of a step, GeneralizedAlpha moves only the nodes whose correction changes a
// force by more than 0.2 of the allowed out-of-balance (the touchdown zone of a mooring line) and
// re-evaluates only the elements around them (Assembler::assemblePart, which gives the whole model's
// entries bit for bit: tests/unit/solver/AssemblyPartTest.cpp). Every step still passes the whole
// model's convergence test, so the result is a different solution within the same tolerance, not an
// approximation of it. Checked here on the mooring example (examples/mooring-dynamics, 200 bars, fairlead
// 5 m / 10 s, ramped over 10 s), 30 s at its dt 0.01 s: against the whole-model iterations
// (`dynamics.solver.assembly: whole`) the fairlead tension of every step and its range over the last period agree
// to within what the convergence tolerance leaves open. Both run at test::kComparisonTolerance (1e-8 of the
// line's weight), where that latitude is a few newtons; at the default 1e-6 it is the touchdown chatter's
// phase (3-5 Hz, undamped seabed), up to 753 N against the converged answer, too loose to see a switch
// that changes the physics (MooringExampleRun.hpp). Measured, parts against whole: 3.4 N at a step
// (1.7e-5 of the 199 kN range), range 1e-5. Bounds: 5e-5 of the range (10 N) at any step, 1e-4 for the
// range over the last period (about three times what round-off on another machine may add).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/MooringExampleRun.hpp"

namespace tangle {
namespace {

using test::rangeAfter;

TEST(PartIterationTest, MooringLineSameResponseWithinTheConvergenceTolerance) {
  const test::FairleadRun whole = test::runMooringExample(30.0, test::wholeAssembly());
  const test::FairleadRun parts = test::runMooringExample(30.0);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(parts.result.completed) << parts.result.message;
  // The switch works both ways: no part without it; with it, a good share of the iterations on parts
  // (measured: 26 % over 200 s).
  EXPECT_EQ(whole.result.partIterations, 0);
  EXPECT_GT(parts.result.partIterations, parts.result.newtonIterations / 10);
  ASSERT_EQ(whole.time.size(), parts.time.size());
  const double range = rangeAfter(whole, 0, 20.0);
  const double worst = test::expectSameFairleadResponse(whole, parts, 0, 5e-5 * range);
  RecordProperty("largest_tension_difference_N", std::to_string(worst));
  RecordProperty("range_N", std::to_string(range));
}

}  // namespace
}  // namespace tangle
