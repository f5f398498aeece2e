// Issue 45: a line type's minimum breaking load (line_types[].minimum_breaking_load) and the warning where the
// tension exceeds it. A chain catenary, solved first without an MBL for its top tension T: with an MBL of T / 2
// the largest tension over MBL is 2 (to round-off: the same equilibrium) at the fairlead, and the warning says
// so there; with an MBL of 10 T the ratio is 0.1 and nothing is said; without an MBL nothing is measured. The
// reader refuses a negative MBL by key.
// The strain warning against each line type's own limit (line_types[].maximum_strain): the chain's top
// strain eps = T / EA is warned of with a limit of eps / 2 and not with 2 eps; a flexible pipe (a beam)
// stretched 1.5 % between pinned ends is warned of at the beams' default of 1 %, which the old 5 % limit for
// every line missed (issue 45: a flexible at 1.7 % strain ran without a word).

#include <gtest/gtest.h>

#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/results/RunText.hpp"

namespace tangle {
namespace {

std::string chainModel(const std::string& mbl, const std::string& maximumStrain = "") {
  return R"(
environment: {water_depth: 100}
line_types:
  - {name: chain, outer_diameter: 0.137, mass_per_length: 115, axial_stiffness: 4.9e8)" +
         (mbl.empty() ? std::string() : ", minimum_breaking_load: " + mbl) +
         (maximumStrain.empty() ? std::string() : ", maximum_strain: " + maximumStrain) + R"(}
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

// Where two line types meet the node takes the smaller MBL of its two elements, and the warning names that
// element's line type: a chain (MBL 50 N) from end A, then a wire (MBL 1000 N), with the largest tension, 100
// N, at the node between them: 2 times the chain's MBL, named 'chain'. (Until 2026-12-06 the name was always
// that of the element on the end-B side: 'wire', with the chain's MBL.)
TEST(BreakingLoad, AtAJunctionTheWeakerLineTypeIsNamed) {
  const model::Model m(io::readModelString(R"(
environment: {water_depth: 100}
line_types:
  - {name: chain, outer_diameter: 0.137, mass_per_length: 115, axial_stiffness: 4.9e8, minimum_breaking_load: 50}
  - {name: wire, outer_diameter: 0.09, mass_per_length: 40, axial_stiffness: 6.0e8, minimum_breaking_load: 1000}
lines:
  - name: leg
    end_a: {type: anchored, position: [190, 0, -100]}
    end_b: {type: pinned, position: [0, 0, -10]}
    sections: [{type: chain, length: 100, elements: 10}, {type: wire, length: 100, elements: 10}]
)",
                                           "junction (test)"));
  std::vector<double> tension(21, 1.0);
  tension[10] = 100.0;  // the node between the sections
  const results::BreakingLoadUse use = results::breakingLoadUse(m, 0, tension);
  EXPECT_NEAR(use.ratio, 2.0, 1e-12);
  EXPECT_NEAR(use.arc, 100.0, 1e-9);
  EXPECT_EQ(use.mbl, 50.0);
  EXPECT_EQ(use.lineType, "chain");
}

/// The strain warnings after the statics of `yaml`.
std::string strainWarningsOf(const std::string& yaml) {
  analysis::Simulation sim(io::readModelString(yaml, "strain (test)"));
  EXPECT_TRUE(sim.solveStatics().converged);
  return results::strainWarnings(sim.model(), sim.snapshot());
}

TEST(StrainWarning, EachLineTypeIsWarnedOfAgainstItsOwnLimit) {
  const double strain = topTension() / 4.9e8;
  const std::string over = strainWarningsOf(chainModel("", std::to_string(0.5 * strain)));
  EXPECT_NE(over.find("warning: line 'leg': axial strain"), std::string::npos) << over;
  EXPECT_NE(over.find("the maximum_strain of line type 'chain'"), std::string::npos) << over;
  EXPECT_EQ(strainWarningsOf(chainModel("", std::to_string(2.0 * strain))), "");
  EXPECT_EQ(strainWarningsOf(chainModel("")), "");  // 0.2 %: below the cables' default of 5 %

  const std::string flexible = R"(
environment: {water_depth: 300}
line_types:
  - {name: flexible, outer_diameter: 0.3, mass_per_length: 100, axial_stiffness: 5.0e8, bending_stiffness: 1.0e4}
lines:
  - name: jumper
    end_a: {type: pinned, position: [0, 0, -100]}
    end_b: {type: pinned, position: [101.5, 0, -100]}
    sections: [{type: flexible, length: 100, elements: 20}]
)";
  const std::string beam = strainWarningsOf(flexible);
  EXPECT_NE(beam.find("axial strain 1.5"), std::string::npos) << beam;
  EXPECT_NE(beam.find("above 1 % (the default for a beam of line type 'flexible')"), std::string::npos) << beam;
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
