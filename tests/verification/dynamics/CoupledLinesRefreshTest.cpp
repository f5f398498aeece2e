// Dynamic verification of the refresh of the lines from one on in a block of lines coupled by a contact
// (NewtonIteration::refreshBlocks, SkylineLdlt::factorizeEnvelopeFrom; theory manual 8.2).
//
// examples/flexibles-at-touchdown: a slack riser laid across a flowline on the seabed. While they touch, the
// contact couples the two lines into one block of the kept matrix (its envelope factorisation), and the
// riser, converging slowly at nearly every step, had the whole matrix made again: both lines' beam tangents
// and every row. Now the lines from the riser on are made again (their elements, seabed and loads, and the
// contact's terms, whose nodes join the part), and the factor's rows from the riser's first; the flowline's
// entries are kept. Every step still passes the whole model's convergence test, so the result is another
// solution within the same tolerance. Both cases run at test::kComparisonTolerance against whole refreshes
// (`refresh: whole`), and the latitude of the converged answer is measured as the difference between two
// whole-refresh runs at 1e-8 and 1e-9 of the lines' weight (the same answer reached by other iterates):
// - Resting: the riser's top at the end of the example's drift (y = 0), resting across the flowline from the
//   statics on (4.96 kN of contact), moved 3 m / 30 s along y for 60 s: sustained contact, no impact, every
//   refresh of the coupled block the riser's alone (before this path: none, the whole block at every one).
//   Measured: the lines refreshed alone 0.0022 N from the whole refreshes at any step (tensions about
//   280 kN), the latitude 0.018 N; 105 refreshes alone and 114 whole against 220 whole. Bound: the latitude.
// - The example's first 60 s (the impacts at 47.5-49 s and 11 s of resting): the rattling is chaotic and
//   the latitude wide, measured 3352 N, the lines refreshed alone 1813 N from the whole refreshes (473
//   refreshes alone and 88 whole, against 552 whole). Bound: the latitude: it runs through, and stays as
//   near as the tolerance itself allows.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
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

/// The example's text with each `from` replaced by its `to` (each must be there once).
std::string editedExample(const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(std::string(test::kExamplesDir) + "/flexibles-at-touchdown/model.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  for (const auto& [from, to] : edits) {
    const std::size_t at = yaml.find(from);
    EXPECT_NE(at, std::string::npos) << "the example no longer has: " << from;
    if (at != std::string::npos) yaml.replace(at, from.size(), to);
  }
  return yaml;
}

TensionRun runFlexibles(const model::DynamicSolverSpec& solver, double tolerance, bool resting) {
  const std::string yaml = resting ? editedExample({{"position: [300, -150, -10]", "position: [300, 0, -10]"},
                                                    {"motion: {amplitude: [0, 150, 0], period: 1200}",
                                                     "motion: {amplitude: [0, 3, 0], period: 30}"},
                                                    {"duration: 300", "duration: 60"}})
                                   : editedExample({{"duration: 300", "duration: 60"}});
  model::ModelSpec spec = io::readModelString(yaml, "flexibles-at-touchdown (edited)");
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

/// Runs the case with whole refreshes (at the comparison tolerance and a tenth of it) and with the default
/// path, and checks the default within the latitude of the two whole runs (the file comment).
void expectTheResponseOfWholeRefreshes(bool resting) {
  const TensionRun whole = runFlexibles(test::wholeRefresh(), test::kComparisonTolerance, resting);
  const TensionRun wholeTighter =
      runFlexibles(test::wholeRefresh(), 0.1 * test::kComparisonTolerance, resting);
  const TensionRun lines = runFlexibles({}, test::kComparisonTolerance, resting);
  ASSERT_TRUE(whole.result.completed) << whole.result.message;
  ASSERT_TRUE(wholeTighter.result.completed) << wholeTighter.result.message;
  ASSERT_TRUE(lines.result.completed) << lines.result.message;
  // The switch works: no lines refreshed alone with `refresh: whole`; with the default, the riser is, while
  // it rests on the flowline (and, before the example's impact, the lines' independent blocks).
  EXPECT_EQ(whole.result.blockRefreshes, 0);
  EXPECT_GT(lines.result.blockRefreshes, resting ? lines.result.matrixRefreshes / 2 : 0);
  const double latitude = largestDifference(whole, wholeTighter);
  const double difference = largestDifference(whole, lines);
  ::testing::Test::RecordProperty("latitude_N", std::to_string(latitude));
  ::testing::Test::RecordProperty("difference_N", std::to_string(difference));
  ::testing::Test::RecordProperty("whole_refreshes_default", std::to_string(lines.result.matrixRefreshes));
  ::testing::Test::RecordProperty("block_refreshes_default", std::to_string(lines.result.blockRefreshes));
  ::testing::Test::RecordProperty("whole_refreshes_whole", std::to_string(whole.result.matrixRefreshes));
  EXPECT_LE(difference, latitude) << "latitude " << latitude << " N";
}

TEST(CoupledLinesRefresh, ARiserRestingAcrossAFlowlineRefreshedAloneGivesTheResponseOfWholeRefreshes) {
  expectTheResponseOfWholeRefreshes(true);
}

TEST(CoupledLinesRefresh, TheExamplesImpactsRefreshedAloneStayWithinTheTolerancesLatitude) {
  expectTheResponseOfWholeRefreshes(false);
}

}  // namespace
}  // namespace tangle
