// Progress lines of a static solve (issue 44: a 91 s lazy-wave statics showed nothing while it ran). With no
// delay and no interval every Newton iteration prints a line that says how far the solve is; without a
// progress object nothing is printed.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/ConsoleProgress.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle {
namespace {

/// A jumper of 68 beams between two pins, from a straight start shape: a few Newton iterations.
analysis::Simulation jumper() {
  model::ModelSpec spec;
  spec.sourceFile = "jumper (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["main"] = test::beamType("main", 0.396, 165.0, 500.0e6, 120.8e3, 1.2, 1.0);
  spec.lines = {test::simpleLine("jumper", "main", 170.0, 68, model::EndKind::Pinned,
                                 Vec3(-100.0, 0.0, -55.0), model::EndKind::Pinned, Vec3(0.0, 0.0, -5.0))};
  return analysis::Simulation(std::move(spec));
}

int countLines(const std::string& text, const std::string& word) {
  int n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find(word) != std::string::npos) ++n;
  return n;
}

TEST(StaticProgress, EveryIterationIsReportedWhenDue) {
  analysis::Simulation sim = jumper();
  core::ConsoleProgress progress(0.0, 0.0);
  solver::StaticSolver solver(sim.assembler(), sim.model().spec().statics);
  solver.setProgress(&progress, "(test)");
  testing::internal::CaptureStderr();
  const solver::StaticResult result = solver.solve(sim.state());
  const std::string printed = testing::internal::GetCapturedStderr();
  ASSERT_TRUE(result.converged) << result.message;
  const int lines = countLines(printed, "statics (test): ");
  EXPECT_GE(lines, 1) << printed;
  EXPECT_LE(lines, result.iterations) << printed;
  EXPECT_EQ(lines, countLines(printed, "Newton iterations, load fraction ")) << printed;
  EXPECT_NE(printed.find("out-of-balance"), std::string::npos) << printed;
}

TEST(StaticProgress, NothingIsPrintedWithoutAProgressObjectOrBeforeTheDelay) {
  {
    analysis::Simulation sim = jumper();
    testing::internal::CaptureStderr();
    EXPECT_TRUE(sim.solveStatics(false).converged);
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("statics"), std::string::npos);
  }
  analysis::Simulation sim = jumper();
  testing::internal::CaptureStderr();
  EXPECT_TRUE(sim.solveStatics(true).converged);  // a solve of well under the 3 s delay
  EXPECT_EQ(testing::internal::GetCapturedStderr().find("statics"), std::string::npos);
}

}  // namespace
}  // namespace tangle
