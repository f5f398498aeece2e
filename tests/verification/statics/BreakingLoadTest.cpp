// Issue 45: a line type's minimum breaking load (line_types[].minimum_breaking_load) and the warning where the
// tension exceeds it. A chain catenary, solved first without an MBL for its top tension T: with an MBL of T / 2
// the largest tension over MBL is 2 (to round-off: the same equilibrium) at the fairlead, and the warning says
// so there; with an MBL of 10 T the ratio is 0.1 and nothing is said; without an MBL nothing is measured. The
// reader refuses a negative MBL by key.

#include <gtest/gtest.h>

#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/results/RunText.hpp"

namespace tangle {
namespace {

std::string chainModel(const std::string& mbl) {
  return R"(
environment: {water_depth: 100}
line_types:
  - {name: chain, outer_diameter: 0.137, mass_per_length: 115, axial_stiffness: 4.9e8)" +
         (mbl.empty() ? std::string() : ", minimum_breaking_load: " + mbl) + R"(}
lines:
  - name: leg
    end_a: {type: anchored, position: [400, 0, -100]}
    end_b: {type: pinned, position: [0, 0, -10]}
    sections: [{type: chain, length: 450, elements: 45}]
)";
}

/// The top tension of the model without an MBL [N].
double topTension() {
  analysis::Simulation sim(io::readModelString(chainModel(""), "chain (test)"));
  EXPECT_TRUE(sim.solveStatics().converged);
  return sim.snapshot()[0].tension.back();
}

TEST(BreakingLoad, TensionAboveTheMinimumBreakingLoadIsWarnedOfWhereItIs) {
  const double top = topTension();
  for (const double factor : {0.5, 10.0}) {
    analysis::Simulation sim(io::readModelString(chainModel(std::to_string(factor * top)), "chain (test)"));
    ASSERT_TRUE(sim.solveStatics().converged);
    const std::vector<solver::LineSnapshot> lines = sim.snapshot();
    const results::BreakingLoadUse use = results::breakingLoadUse(sim.model(), 0, lines[0].tension);
    EXPECT_NEAR(use.ratio, 1.0 / factor, 1e-6 / factor);
    EXPECT_NEAR(use.arc, 450.0, 1e-9);  // the fairlead, end B
    EXPECT_EQ(use.lineType, "chain");
    const std::string warnings = results::breakingLoadWarnings(sim.model(), {use}, "at the static equilibrium");
    if (factor < 1.0) {
      EXPECT_NE(warnings.find("line 'leg'"), std::string::npos) << warnings;
      EXPECT_NE(warnings.find("exceeds the minimum breaking load of line type 'chain'"), std::string::npos)
          << warnings;
      EXPECT_NE(warnings.find("200 %"), std::string::npos) << warnings;
    } else {
      EXPECT_TRUE(warnings.empty()) << warnings;
    }
  }
  // Without an MBL nothing is measured.
  analysis::Simulation sim(io::readModelString(chainModel(""), "chain (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  EXPECT_EQ(results::breakingLoadUse(sim.model(), 0, sim.snapshot()[0].tension).ratio, 0.0);
}

TEST(BreakingLoad, ANegativeMinimumBreakingLoadIsRefusedByKey) {
  try {
    io::readModelString(chainModel("-5.0e6"), "chain (test)");
    FAIL() << "a negative MBL was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("minimum_breaking_load"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tangle
