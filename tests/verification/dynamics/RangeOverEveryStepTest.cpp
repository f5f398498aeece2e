// Range graphs and extremes cover every accepted time step (issue 13): before, they were taken at the
// output times only, so a short impact between two output times was missing from range.csv and from
// the maxima. Source of the reference: the largest effective tension over every accepted step, taken
// by an independent step observer in the same run. Tolerance: exact equality (the same numbers).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/DynamicRecorder.hpp"

namespace tangle {
namespace {

TEST(RangeOverEveryStep, ShortImpactBetweenOutputTimesIsInTheRangeMaximum) {
  model::ModelSpec spec;
  spec.sourceFile = "range (test)";
  spec.environment.waterDepth = 100.0;
  const section::LineType cable = test::cableType("cable", 0.05, 10.0, 1.0e7);
  spec.lineTypes[cable.name] = cable;
  // A taut horizontal cable, its end B jerked 5 cm along the line within 20 ms at t = 0.25 s, between
  // the output times 0.2 s and 0.3 s.
  spec.lines.push_back(test::simpleLine("cable", "cable", 100.0, 10, model::EndKind::Fixed, Vec3(0, 0, -50),
                                        model::EndKind::Fixed, Vec3(100.2, 0, -50)));
  model::EndMotionSpec& jerk = spec.lines[0].endB.motion;
  jerk.enabled = true;
  jerk.table = {{0.0, 0, 0, 0}, {0.24, 0, 0, 0}, {0.25, 0.05, 0, 0}, {0.26, 0, 0, 0}, {1.0, 0, 0, 0}};
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 0.6;
  spec.dynamics.timeStep = 0.002;
  spec.dynamics.outputInterval = 0.1;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(spec);
  ASSERT_TRUE(sim.solveStatics().converged);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tangle-range-every-step";
  std::filesystem::remove_all(dir);
  io::DynamicRecorder recorder(dir, sim.snapshot(), 0.0);
  double stepMax = -std::numeric_limits<double>::infinity();
  double outputMax = stepMax;
  const time::DynamicResult r = sim.runDynamics(
      [&](const model::State& s, const VecX&) {
        const auto lines = sim.snapshot(true);
        recorder.record(s.time, lines);
        outputMax = std::max(outputMax, *std::max_element(lines[0].tension.begin(), lines[0].tension.end()));
      },
      false,
      [&](const model::State&, double dt) {
        const auto lines = sim.snapshot(true);
        recorder.accumulate(lines, dt);
        stepMax = std::max(stepMax, *std::max_element(lines[0].tension.begin(), lines[0].tension.end()));
      });
  ASSERT_TRUE(r.completed) << r.message;
  const auto& range = recorder.ranges()[0];
  const double rangeMax = *std::max_element(range.tensionMax.begin(), range.tensionMax.end());
  EXPECT_EQ(rangeMax, stepMax);
  // The test means something only if the peak falls between output samples: it does (+41 %).
  EXPECT_GT(rangeMax, 1.2 * outputMax) << "range max " << rangeMax << " N, output max " << outputMax << " N";
  EXPECT_EQ(recorder.stepCount(), r.steps + 1);
  recorder.writeRanges();
  recorder.close();
  EXPECT_TRUE(std::filesystem::exists(dir / "dynamics" / "cable" / "range.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tangle
