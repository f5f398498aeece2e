// Dynamic verification of the refresh of the lines from one on in a block of lines coupled by a contact
// (NewtonIteration::refreshBlocks, SkylineLdlt::factorizeEnvelopeFrom; theory manual 8.2).
//
// examples/flexibles-at-touchdown: a slack riser laid across a flowline on the seabed (impacts at 47.5-49 s,
// then resting across it). While they touch, the contact couples the two lines into one block of the kept
// matrix (its envelope factorisation), and the riser, converging slowly at nearly every step, had the whole
// matrix made again: both lines' beam tangents and every row. Now the lines from the riser on are made
// again (their elements, seabed and loads, and the contact's terms, whose nodes join the part), and the
// factor's rows from the riser's first; the flowline's entries are kept. Every step still passes the whole
// model's convergence test, so the result is another solution within the same tolerance.
// Checked over the first 60 s (the impacts and 11 s of resting contact) at test::kComparisonTolerance
// against whole refreshes (`refresh: whole`): the top tensions of both lines at every step agree within
// the latitude that tolerance leaves, measured as the difference between two whole-refresh runs at 1e-8
// and 1e-9 of the lines' weight (the same converged answer reached by other iterates). The impacts make it
// wide: measured 3352 N (top tensions about 280 kN; the rattling's phase follows any change of the iterates),
// and the lines refreshed alone 1813 N from the whole refreshes (473 refreshes alone and 88 whole, against
// 552 whole).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "support/DynamicRun.hpp"
#include "support/MooringExampleRun.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

struct TensionRun {
  time::DynamicResult result;
  std::vector<double> time;
  std::vector<std::vector<double>> tensions;  // per step: every line's end A and end B tension [N]
};

TensionRun runFlexibles(const model::DynamicSolverSpec& solver, double tolerance) {
  model::ModelSpec spec =
      io::readModelFile(std::string(test::kExamplesDir) + "/flexibles-at-touchdown/model.yaml");
  spec.dynamics.duration = 60.0;
  spec.dynamics.tolerance = tolerance;
  spec.dynamics.outputInterval = spec.dynamics.timeStep;  // every step
  const std::unique_ptr<analysis::Simulation> sim = test::simulationAfterStatics(std::move(spec), solver);
  TensionRun run;
  run.result = sim->runDynamics([&](const model::State& state, const VecX&) {
    run.time.push_back(state.time);
    run.tensions.push_back(test::endTensionRow(*sim));
  });
  return run;
}

/// The largest difference of any end tension at any step [N] (infinite when the runs took other steps).
double largestDifference(const TensionRun& a, const TensionRun& b) {
  if (a.time != b.time) {
    ADD_FAILURE() << "the runs took different steps (" << a.time.size() << " and " << b.time.size() << ")";
    return INFINITY;
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < a.time.size(); ++i)
    for (std::size_t k = 0; k < a.tensions[i].size(); ++k)
      worst = std::max(worst, std::abs(a.tensions[i][k] - b.tensions[i][k]));
  return worst;
}

TEST(CoupledLinesRefresh, TheRiserRefreshedAloneGivesTheResponseOfWholeRefreshes) {
  const TensionRun whole = runFlexibles(test::wholeRefresh(), test::kComparisonTolerance);
  const TensionRun wholeTighter = runFlexibles(test::wholeRefresh(), 0.1 * test::kComparisonTolerance);
  const TensionRun lines = runFlexibles({}, test::kComparisonTolerance);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(wholeTighter.result.completed) << wholeTighter.result.message;
  ASSERT_TRUE(lines.result.completed) << lines.result.message;
  // The switch works: no lines refreshed alone with `refresh: whole`; with the default, the riser is, while
  // it rests on the flowline (the lines are independent blocks before the impact: those refreshes too).
  EXPECT_EQ(whole.result.blockRefreshes, 0);
  EXPECT_GT(lines.result.blockRefreshes, 0);
  const double latitude = largestDifference(whole, wholeTighter);
  const double difference = largestDifference(whole, lines);
  RecordProperty("latitude_N", std::to_string(latitude));
  RecordProperty("difference_N", std::to_string(difference));
  RecordProperty("whole_refreshes_default", std::to_string(lines.result.matrixRefreshes));
  RecordProperty("block_refreshes_default", std::to_string(lines.result.blockRefreshes));
  RecordProperty("whole_refreshes_whole", std::to_string(whole.result.matrixRefreshes));
  EXPECT_LE(difference, latitude) << "latitude " << latitude << " N";
}

}  // namespace
}  // namespace tangle
