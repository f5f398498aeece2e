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
// Where the step resolves the seabed spring (dt 0.01 s: omega dt = 0.45), the same predictor extrapolates
// the free cable nodes' accelerations linearly from the last two steps (GeneralizedAlpha, theory 8.2):
//  - at 1e-8, 30 s, against the constant acceleration: the same response, with the same bounds;
//  - the benchmark deck of issue 48 (bench/moordyn/chain-1130m.txt: the example's geometry as one chain with
//    MoorDyn's critical axial damping, converted, so at a converted deck's tolerance of 1e-5 of the line's
//    weight), the fairlead moved 5 m / 10 s, 20 s at 0.01 s: the residual evaluations saved, most steps
//    converging on their first correction. Measured: 2.88 against 2.35 per step (the coupled host on it, 100
//    s: 2.83 against 2.23). Bound: at least 10 % fewer, a count. (On the mooring example itself at 1e-5,
//    without axial damping, the gain is 2.50 -> 2.44: its chain rings axially, which no extrapolation
//    follows.)
// Beam nodes are moved where their bending holds them far less than the seabed does (12 EI / L^3 per element
// at most a tenth of k L; time::SeabedPredictor):
//  - examples/flexibles-at-touchdown (8 in flexibles, EI 3e4 N m^2, 10 m elements: 720 N/m of bending
//    against 1e6 N/m of seabed per node), its first 30 s at its dt 0.1 s (before the riser meets the
//    flowline at 47.5 s) and its tolerance: the residual evaluations saved. Measured: 5.50 against 6.25 per
//    step (-12 %). Bound: at least 5 % fewer, a count. (The same response is SolverEquivalence's, which
//    compares the example's first 5 s at 1e-8 with the plainest path and the constant acceleration.)
//  - examples/scr-fatigue (steel, EI 2.2e7 N m^2, 2.5 m elements at the touchdown: 1.7e7 N/m of bending
//    against 2.5e5 N/m of seabed), 10 s at its dt 0.05 s: its nodes are left as predicted, so the run is
//    the constant acceleration's bit for bit (moving them took 10 % more residual evaluations).

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "support/MooringExampleRun.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/io/MoorDynDeck.hpp"

namespace tangle {
namespace {

constexpr double kLargeStep = 0.05;      // [s]: the seabed correction acts
constexpr double kResolvingStep = 0.01;  // [s]: the acceleration is extrapolated

/// The mooring example for 30 s at step dt [s] and test::kComparisonTolerance, the default predictor against
/// the constant acceleration: the fairlead tension at every step within 5e-5 of its range.
void expectSameResponseAsConstantAcceleration(double dt) {
  const test::FairleadRun plain = test::runMooringExample(30.0, test::extrapolatedPredictor(), {}, dt);
  const test::FairleadRun predicted = test::runMooringExample(30.0, {}, {}, dt);
  ASSERT_TRUE(plain.result.completed) << plain.result.message;
  ASSERT_TRUE(predicted.result.completed) << predicted.result.message;
  const double range = test::rangeAfter(plain, 0, 20.0);
  const double worst = test::expectSameFairleadResponse(plain, predicted, 0, 5e-5 * range);
  ::testing::Test::RecordProperty("largest_tension_difference_N", std::to_string(worst));
  ::testing::Test::RecordProperty("range_N", std::to_string(range));
}

/// Residual evaluations per step of a run [-].
double evaluationsPerStep(const time::DynamicResult& r) {
  return static_cast<double>(r.newtonIterations) / r.steps;
}

/// Both runs complete on the same steps, and `predicted` takes fewer residual evaluations per step than
/// `plain` (the constant acceleration) times `bound`; the two counts are recorded as
/// evaluations_per_step_extrapolated and evaluations_per_step_<name>.
void expectFewerEvaluations(const time::DynamicResult& plain, const time::DynamicResult& predicted,
                            double bound, const std::string& name) {
  ASSERT_TRUE(plain.completed) << plain.message;
  ASSERT_TRUE(predicted.completed) << predicted.message;
  ASSERT_EQ(plain.steps, predicted.steps);
  const double perStepPlain = evaluationsPerStep(plain);
  const double perStepPredicted = evaluationsPerStep(predicted);
  EXPECT_LT(perStepPredicted, bound * perStepPlain);
  ::testing::Test::RecordProperty("evaluations_per_step_extrapolated", std::to_string(perStepPlain));
  ::testing::Test::RecordProperty("evaluations_per_step_" + name, std::to_string(perStepPredicted));
}

TEST(SeabedPredictorTest, MooringLineSameResponseWithinTheConvergenceTolerance) {
  expectSameResponseAsConstantAcceleration(kLargeStep);
}

TEST(SeabedPredictorTest, FewerResidualEvaluationsAtLargeSteps) {
  constexpr double kTolerance = 1e-4;
  const test::FairleadRun plain =
      test::runMooringExample(40.0, test::extrapolatedPredictor(), {}, kLargeStep, kTolerance);
  const test::FairleadRun seabed = test::runMooringExample(40.0, {}, {}, kLargeStep, kTolerance);
  expectFewerEvaluations(plain.result, seabed.result, 0.95, "seabed");
}

TEST(SeabedPredictorTest, ExtrapolatedAccelerationSameResponseWithinTheConvergenceTolerance) {
  expectSameResponseAsConstantAcceleration(kResolvingStep);
}

/// The benchmark chain deck converted, its fairlead (the coupled point: a pinned end at the origin's x, y)
/// moved 5 m / 10 s along x without a ramp, run for `duration` s on the Newton path `solver`.
time::DynamicResult runChainDeck(double duration, const model::DynamicSolverSpec& solver) {
  const io::MoorDynConversion converted = io::convertMoorDynDeck(
      io::readMoorDynDeck(std::string(test::kSourceDir) + "/bench/moordyn/chain-1130m.txt"));
  model::ModelSpec spec = io::readModelString(converted.yaml, "chain-1130m.yaml");
  int moved = 0;
  for (model::LineSpec& line : spec.lines)
    for (model::EndSpec* end : {&line.endA, &line.endB})
      if (end->kind == model::EndKind::Pinned) {
        end->motion.enabled = true;
        end->motion.amplitude = Vec3(5.0, 0.0, 0.0);
        end->motion.period = 10.0;
        ++moved;
      }
  EXPECT_EQ(moved, 1);
  spec.dynamics.duration = duration;
  spec.dynamics.rampTime = 0.0;
  return test::simulationAfterStatics(std::move(spec), solver)
      ->runDynamics([](const model::State&, const VecX&) {});
}

TEST(SeabedPredictorTest, ExtrapolatedAccelerationFewerResidualEvaluationsAtSmallSteps) {
  const time::DynamicResult plain = runChainDeck(20.0, test::extrapolatedPredictor());
  const time::DynamicResult linear = runChainDeck(20.0, {});
  expectFewerEvaluations(plain, linear, 0.9, "linear");
}

/// An example's dynamics for `duration` s on the Newton path `solver`, at its own step and tolerance.
time::DynamicResult runExampleFor(const std::string& example, double duration,
                                  const model::DynamicSolverSpec& solver, std::vector<double>* endTensions) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/" + example + "/model.yaml");
  spec.dynamics.duration = duration;
  const std::unique_ptr<analysis::Simulation> sim = test::simulationAfterStatics(std::move(spec), solver);
  return sim->runDynamics([&](const model::State&, const VecX&) {
    if (!endTensions) return;
    const std::vector<double> row = test::endTensionRow(*sim);
    endTensions->insert(endTensions->end(), row.begin(), row.end());
  });
}

TEST(SeabedPredictorTest, SoftBeamsFewerResidualEvaluationsAtLargeSteps) {
  const time::DynamicResult plain =
      runExampleFor("flexibles-at-touchdown", 30.0, test::extrapolatedPredictor(), nullptr);
  const time::DynamicResult seabed = runExampleFor("flexibles-at-touchdown", 30.0, {}, nullptr);
  expectFewerEvaluations(plain, seabed, 0.95, "seabed");
}

TEST(SeabedPredictorTest, SteelRiserLeftAsPredicted) {
  std::vector<double> plainTensions, seabedTensions;
  const time::DynamicResult plain =
      runExampleFor("scr-fatigue", 10.0, test::extrapolatedPredictor(), &plainTensions);
  const time::DynamicResult seabed = runExampleFor("scr-fatigue", 10.0, {}, &seabedTensions);
  ASSERT_TRUE(plain.completed) << plain.message;
  ASSERT_TRUE(seabed.completed) << seabed.message;
  EXPECT_EQ(plain.newtonIterations, seabed.newtonIterations);
  ASSERT_EQ(plainTensions.size(), seabedTensions.size());
  ASSERT_FALSE(plainTensions.empty());
  for (std::size_t i = 0; i < plainTensions.size(); ++i)
    ASSERT_EQ(plainTensions[i], seabedTensions[i]) << "end tension " << i % 2 << " at output " << i / 2;
}

}  // namespace
}  // namespace tangle
