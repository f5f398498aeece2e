// Dynamic verification of the Newton corrections by independent blocks (issue 8; theory manual 8.2).
//
// Lines not coupled to each other (moorings with prescribed fairleads) make the kept iteration matrix block
// diagonal; GeneralizedAlpha then solves and corrects, at each Newton iteration, only the blocks whose
// out-of-balance is not yet within the tolerance: a line that has converged is left as it is while the
// others iterate on. Every step still passes the whole model's convergence test, so the result is another
// solution within the same tolerance. Checked on three copies of the mooring example's line
// (examples/mooring-dynamics, 200 bars) around a point, fairleads on a 20 m circle at azimuths 0, 120 and
// 250 deg, each moved 5 m / 10 s along x (in-line for the first, across for the others), 30 s at dt 0.01 s:
// against whole-model iterations (`assembly: whole`: every block solved, no part) the fairlead tension of
// every step and its range over the last period agree to within what the convergence tolerance leaves open.
// Both run at test::kComparisonTolerance (1e-8 of each line's weight), where that latitude is a few newtons
// (MooringExampleRun.hpp; at the default 1e-6 the in-line line's touchdown chatter leaves hundreds).
// Measured, blocks (with parts) against whole: 1.7 N on the in-line line (range 199 kN), 0.045 N and
// 0.033 N on the other two (ranges 65 and 42 kN). Bounds: PartIterationTest's on the in-line line (5e-5 of
// the range, 10 N, at any step; 1e-4 for the range), 0.5 N on the cross lines (ten times the measured
// difference: round-off on another machine).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "support/MooringExampleRun.hpp"

namespace tangle {
namespace {

using test::rangeAfter;

/// The three lines' fairlead tensions of `other` against `reference` (test::expectSameFairleadResponse) with
/// the bounds of the file comment, each line's largest step difference recorded.
void expectSameResponseOfThreeLines(const test::FairleadRun& reference, const test::FairleadRun& other) {
  const std::array<double, 3> stepBound{5e-5 * rangeAfter(reference, 0, 20.0), 0.5, 0.5};  // [N], see above
  for (std::size_t l = 0; l < 3; ++l) {
    const double worst = test::expectSameFairleadResponse(reference, other, l, stepBound[l]);
    ::testing::Test::RecordProperty("largest_tension_difference_N_line" + std::to_string(l + 1),
                                    std::to_string(worst));
  }
}

TEST(BlockIterationTest, IndependentLinesSameResponseWithinTheConvergenceTolerance) {
  const std::vector<double> azimuths{0.0, 120.0, 250.0};  // [deg]
  const test::FairleadRun whole = test::runMooringExample(30.0, test::wholeAssembly(), azimuths);
  const test::FairleadRun blocks = test::runMooringExample(30.0, {}, azimuths);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(blocks.result.completed) << blocks.result.message;
  // The switch works both ways: every block solved without it; with it, converged lines are left out.
  EXPECT_EQ(whole.result.blocksLeft, 0);
  EXPECT_GT(blocks.result.blocksLeft, blocks.result.newtonIterations / 10);
  ASSERT_EQ(whole.time.size(), blocks.time.size());
  expectSameResponseOfThreeLines(whole, blocks);
}

// The same three lines with the kept matrix refreshed per block (NewtonIteration::refreshBlocks: a line whose
// out-of-balance falls by less than 4x in an iteration has its own matrix assembled and factorised again,
// the others kept) against refreshes of the whole matrix (`refresh: whole`): the same response within
// the convergence tolerance, with the bounds above (the same latitude: another sequence of iterates
// converged to the same tolerance).
TEST(BlockIterationTest, SlowLinesRefreshedAloneSameResponseWithinTheConvergenceTolerance) {
  const std::vector<double> azimuths{0.0, 120.0, 250.0};  // [deg]
  const test::FairleadRun whole = test::runMooringExample(30.0, test::wholeRefresh(), azimuths);
  const test::FairleadRun blocks = test::runMooringExample(30.0, {}, azimuths);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(blocks.result.completed) << blocks.result.message;
  // The switch works both ways.
  EXPECT_EQ(whole.result.blockRefreshes, 0);
  EXPECT_GT(blocks.result.blockRefreshes, 0);
  RecordProperty("whole_refreshes", std::to_string(whole.result.matrixRefreshes));
  RecordProperty("block_run_whole_refreshes", std::to_string(blocks.result.matrixRefreshes));
  RecordProperty("block_refreshes", std::to_string(blocks.result.blockRefreshes));
  ASSERT_EQ(whole.time.size(), blocks.time.size());
  expectSameResponseOfThreeLines(whole, blocks);
}

}  // namespace
}  // namespace tangle
