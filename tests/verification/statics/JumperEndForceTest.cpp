// Issue 30: end forces of beam lines include the shear. The flexible jumper of Lowe & Langley (2006,
// OMAE2006-92165), as MoorDyn's validation data has it (tests/Mooring/lowe_and_langley_2006/line.txt:
// 170 m, D 0.396 m, 165 kg/m, EA 500 MN, EI 120.8 kN m2, between (-100, 0, -55) and (0, 0, -5) in 100 m
// of water of 1000 kg/m3, g = 9.807 m/s2), in its static equilibrium without current.
//
// Reference: the paper's static end forces, (11.40, 0, 45.71) kN at the top and (-11.40, 0, 24.04) kN at
// the bottom, the forces the supports exert on the jumper (MoorDyn's test compares them with minus its
// node forces, within 0.2 kN: the values are digitised from the paper). tangle's `force_N`
// (LineSnapshot::endTensionForce) is the force the line exerts on its support: minus the reference.
// Tolerance 0.2 kN, the reference's own; at 34, 68 and 136 elements.
//
// Independently, without horizontal loads the horizontal end forces balance exactly: checked to 1e-4 of
// the jumper's submerged weight (the static residual is 1e-6 of the weight per node; the static end force
// adds the end node's own vertical lumped weight to the end element's section force). Before the fix the end forces were the tension
// along the end chords: 11.518 kN at the top and 11.697 kN at the bottom at 68 elements.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"

namespace tangle {
namespace {

class Jumper : public ::testing::TestWithParam<int> {};

TEST_P(Jumper, EndForcesIncludeTheShearAndMatchLoweAndLangley) {
  model::ModelSpec spec;
  spec.sourceFile = "Lowe & Langley jumper (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.waterDensity = 1000.0;
  spec.environment.gravity = 9.807;
  section::LineType jumper;
  jumper.name = "main";
  jumper.outerDiameter = jumper.buoyancyDiameter = jumper.contactDiameter = 0.396;
  jumper.massPerLength = 165.0;
  jumper.axialStiffness = 500.0e6;
  jumper.bendingStiffness = 120.8e3;
  jumper.torsionalStiffness = 120.8e3;
  spec.lineTypes["main"] = jumper;
  spec.lines = {test::simpleLine("jumper", "main", 170.0, GetParam(), model::EndKind::Pinned,
                                 Vec3(-100.0, 0.0, -55.0), model::EndKind::Pinned, Vec3(0.0, 0.0, -5.0))};
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const solver::LineSnapshot line = sim.snapshot().front();
  const Vec3 bottom = line.endTensionForceA / 1e3, top = line.endTensionForceB / 1e3;  // [kN]
  const Vec3 bottomReference(-11.40, 0.0, 24.04), topReference(11.40, 0.0, 45.71);  // on the jumper [kN]
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(-bottom[k], bottomReference[k], 0.2) << "bottom, component " << k;
    EXPECT_NEAR(-top[k], topReference[k], 0.2) << "top, component " << k;
  }
  const double weight = (165.0 - 1000.0 * 0.25 * 3.141592653589793 * 0.396 * 0.396) * 9.807 * 170.0 / 1e3;
  EXPECT_NEAR(bottom.x(), -top.x(), 1e-4 * weight);
  RecordProperty("bottom_force_kN", fmt::format("({:.3f}, {:.3f}, {:.3f})", bottom.x(), bottom.y(), bottom.z()));
  RecordProperty("top_force_kN", fmt::format("({:.3f}, {:.3f}, {:.3f})", top.x(), top.y(), top.z()));
}

INSTANTIATE_TEST_SUITE_P(LoweLangley2006, Jumper, ::testing::Values(34, 68, 136));

}  // namespace
}  // namespace tangle
