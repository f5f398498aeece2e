// Issue 44: statics of a lazy-wave riser in seconds.
//
// A 10 in steel riser in 1500 m (OD 0.2731 m, 130 kg/m with contents, EA 3.3e9 N, EI 2.6e7 N m^2): 500 m of
// flowline from the anchor, 800 m to the sag bend, 400 m of buoyancy modules (smeared: OD 0.9 m, 250 or
// 450 kg/m, net uplift 3943 or 1982 N/m), 1540 m up to a pin 10 m below the surface; 470 beams. With the
// single equivalent catenary as the start (one mean weight: the buoyancy section laid on the seabed) these
// statics took 11 270 - 16 158 Newton iterations and 17-20 s CPU (measured 2026-11-29, three of six
// variants of span and buoyancy): the multi-section start (MultiSectionCatenary.hpp) was skipped when the
// equivalent uniform line is slack, or laid the buoyancy section on the seabed under a grounded riser
// section. With each section on its own catenary and nothing buoyant grounded they take 4-8 iterations. The
// bound, 30 iterations, is the one a riser analyst can expect of a start that is already the cable solution:
// a few for the bending stiffness and the seabed contact.
//
// Check of the answer: the top tension against the multi-section elastic catenary (the cable solution,
// Irvine 1981 per segment) within 0.5 %: the riser's bending stiffness changes it only near the ends and the
// sag and hog bends (bending length sqrt(EI / T) = 10-12 m of 3240 m), and the seabed is a stiff spring
// under the laid part rather than the catenary's rigid plane. The same equilibrium was reached by the slow
// path (max tension 1106.693 kN both ways on the 1600 m span).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/catenary/MultiSectionCatenary.hpp"

namespace tangle {
namespace {

struct LazyWaveCase {
  double span;          // horizontal distance from the anchor to the top [m]
  double buoyancyMass;  // mass per length of the buoyancy section [kg/m]
};

class LazyWaveStatics : public ::testing::TestWithParam<LazyWaveCase> {};

TEST_P(LazyWaveStatics, ConvergesInFewIterationsToTheCableSolution) {
  const LazyWaveCase c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "lazy-wave riser (test)";
  spec.environment.waterDepth = 1500.0;
  section::LineType riser = test::cableType("riser", 0.2731, 130.0, 3.3e9);
  riser.bendingStiffness = 2.6e7;
  riser.torsionalStiffness = 2.0e7;
  riser.dragNormal = 1.0;
  section::LineType buoyant = riser;
  buoyant.name = "buoyant";
  buoyant.outerDiameter = buoyant.buoyancyDiameter = buoyant.contactDiameter = 0.9;
  buoyant.massPerLength = c.buoyancyMass;
  spec.lineTypes["riser"] = riser;
  spec.lineTypes["buoyant"] = buoyant;
  model::LineSpec line =
      test::simpleLine("lazy_wave", "riser", 500.0, 50, model::EndKind::Anchored, Vec3(-c.span, 0, -1500.0),
                       model::EndKind::Pinned, Vec3(0, 0, -10.0));
  line.sections = {
      {"riser", 500.0, 50}, {"riser", 800.0, 100}, {"buoyant", 400.0, 100}, {"riser", 1540.0, 220}};
  spec.lines = {line};
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  EXPECT_LE(statics.iterations, 30);

  const double g = sim.model().environment().gravity, rho = sim.model().environment().waterDensity;
  std::vector<catenary::CatenarySection> sections;
  for (const auto& [type, length] :
       {std::pair{riser, 1300.0}, std::pair{buoyant, 400.0}, std::pair{riser, 1540.0}})
    sections.push_back({length, type.submergedWeight(rho, g), type.axialStiffness});
  catenary::MultiSectionCatenary cable(sections);
  // The anchor end rests one contact radius above the seabed (as the model places it).
  const Vec3 anchor = sim.model().endPosition(sim.model().lines()[0].spec->endA);
  ASSERT_TRUE(cable.solve(c.span, -10.0 - anchor.z(), 1e-3 * cable.weightScale, 0.5));
  const double expected = std::hypot(cable.horizontal, cable.farEndVertical());
  const double top = sim.snapshot(false).at(0).endTensionB;
  EXPECT_NEAR(top, expected, 0.005 * expected);
  ::testing::Test::RecordProperty(
      "statics", fmt::format("{} iterations; top tension {:.1f} kN (cable solution {:.1f} kN)",
                             statics.iterations, top / 1000.0, expected / 1000.0));
}

INSTANTIATE_TEST_SUITE_P(SpansAndBuoyancy, LazyWaveStatics,
                         ::testing::Values(LazyWaveCase{1600.0, 250.0}, LazyWaveCase{1600.0, 450.0},
                                           LazyWaveCase{1900.0, 450.0}, LazyWaveCase{2300.0, 250.0}),
                         [](const ::testing::TestParamInfo<LazyWaveCase>& p) {
                           return fmt::format("span{}_buoyancy{}", static_cast<int>(p.param.span),
                                              static_cast<int>(p.param.buoyancyMass));
                         });

}  // namespace
}  // namespace tangle
