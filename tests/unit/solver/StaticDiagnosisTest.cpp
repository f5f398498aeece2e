// What a failed static analysis reports (issue 43, found on a lazy-wave pair in each other's wake): the path
// that got furthest and where it stalled, not the last path tried. The pair's current ramp had reached 0.293
// of the drag, stalling near the downstream line's anchor; the homotopy from the start shape, tried after it,
// stalled at 0.009 at the upstream line, and the message sent the analyst there ("load fraction reached
// 0.009 ... at line 'up' node 42").
//
// The model: the lazy wave of StaticsRobustnessTest (LazyWaveInCurrent) at 2 m/s with a budget too small
// for it (statics.max_iterations 3: 10 iterations a solve, 200 in all). Newton at the full load fails, the
// current ramped from still water reaches half the drag before the budget runs out, and the message
// before this change said "load fraction reached 0.000" (the ramp does not move the homotopy's fraction).
// (At 1.5 m/s the ramp reached 0.938 until 2026-12-06; since the flex joint holds the riser's twist,
// VesselSystem, that solve converges in 190 iterations, so the current is stronger here.)

#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle {
namespace {

analysis::Simulation lazyWaveWithASmallBudget() {
  return analysis::Simulation(io::readModelString(R"(
environment:
  water_depth: 1500
  current: [{z: 0, speed: 2.0, azimuth: 90}, {z: -1500, speed: 0.6, azimuth: 90}]
line_types:
  - {name: riser, outer_diameter: 0.2731, mass_per_length: 130, axial_stiffness: 3.3e9, bending_stiffness: 2.6e7, drag_normal: 1.0}
  - {name: buoyant, outer_diameter: 0.9, mass_per_length: 350, axial_stiffness: 3.3e9, bending_stiffness: 2.6e7, drag_normal: 1.0}
vessels:
  - {name: fpso, position: [0, 0, 0], heading: 0}
statics: {max_iterations: 3}
lines:
  - name: riser
    end_a: {type: anchored, position: [-2300, 0, -1500]}
    end_b: {type: vessel, vessel: fpso, position: [0, 0, -10], flex_joint: {stiffness: 5.0e4}}
    sections:
      - {type: riser, length: 500, elements: 50}
      - {type: riser, length: 800, elements: 100}
      - {type: buoyant, length: 400, elements: 100}
      - {type: riser, length: 1540, elements: 220}
)",
                                                  "diagnosis (test)"));
}

TEST(StaticDiagnosis, AFailureReportsThePathThatGotFurthestAndWhereItStalled) {
  analysis::Simulation sim = lazyWaveWithASmallBudget();
  solver::StaticSolver solver(sim.assembler(), sim.model().spec().statics);
  const solver::StaticResult result = solver.solve(sim.state());
  ASSERT_FALSE(result.converged) << result.message;
  EXPECT_FALSE(result.noEquilibrium);
  const std::string& m = result.message;
  std::smatch furthest;
  ASSERT_TRUE(std::regex_search(
      m, furthest,
      std::regex("the path that got furthest, the current ramped from still water, reached ([0-9.]+) of the "
                 "current's drag")))
      << m;
  // The ramp's first two increments of a quarter converge within the 200 iterations (0.500 measured): the
  // furthest path is the ramp, not Newton at the full load (0).
  EXPECT_GE(std::stod(furthest[1]), 0.5) << m;
  EXPECT_NE(m.find("the other paths: Newton at the full load did not converge"), std::string::npos) << m;
  // Where: the node the ramp stalled at, with its line and arc length, and what to change.
  EXPECT_TRUE(std::regex_search(m, std::regex("out-of-balance force [0-9.e+]+ N at line 'riser' node [0-9]+ "
                                              "\\(arc length [0-9.]+ m\\)")))
      << m;
  EXPECT_NE(m.find("statics.max_iterations"), std::string::npos) << m;
}

}  // namespace
}  // namespace tangle
