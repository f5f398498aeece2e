// Issue 44: the multi-section elastic catenary (catenary/MultiSectionCatenary.hpp), the starting shape of a
// line with buoyant sections (lazy and steep waves).
//
// - One uniform line cut in two sections: the same elastic catenary as solveAnchoredCatenary (Jonkman 2007,
//   independent code: analytic Jacobian, closed-form profile), with a grounded part and lifted off at the
//   anchor: H, the grounded length, the fairlead's vertical force and the positions agree to 1e-7 (of H, of
//   the weight, of the length; both solve to ~1e-9 L: the bound is headroom for round-off).
// - A lazy wave (flowline, sag bend, buoyancy section, catenary to the top) whose equivalent uniform line is
//   slack: solved, with the far end where it must be (1e-9 L), a hog over the buoyancy section, no grounded
//   buoyant section, never below the seabed. Before issue 44 this case was skipped (the equivalent line's
//   slack regime) or solved with the buoyancy section laid on the seabed, and the statics needed 11 000 -
//   16 000 Newton iterations (LazyWaveStaticsTest).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tangle/catenary/ElasticCatenary.hpp"
#include "tangle/catenary/MultiSectionCatenary.hpp"

namespace tangle::catenary {
namespace {

void expectSameAsUniformCatenary(double span, double height, bool grounded) {
  const double length = 1000.0, weight = 800.0, ea = 5.0e8;
  const CatenarySolution reference = solveAnchoredCatenary({span, height, length, weight, ea});
  EXPECT_EQ(reference.groundedLength > 0.0, grounded);
  MultiSectionCatenary m({{400.0, weight, ea}, {600.0, weight, ea}});
  ASSERT_TRUE(m.solve(span, height, 0.5 * reference.horizontalTension, 0.3));
  EXPECT_NEAR(m.horizontal, reference.horizontalTension, 1e-7 * reference.horizontalTension);
  EXPECT_NEAR(m.grounded, reference.groundedLength, 1e-7 * length);
  EXPECT_NEAR(m.farEndVertical(), reference.verticalTension, 1e-7 * weight * length);
  for (int i = 0; i <= 20; ++i) {
    const double s = length * i / 20.0;
    const CatenaryPoint p = reference.position(s);
    const auto [x, z] = m.at(s);
    EXPECT_NEAR(x, p.x, 1e-7 * length) << "s = " << s;
    EXPECT_NEAR(z, p.z, 1e-7 * length) << "s = " << s;
  }
}

TEST(MultiSectionCatenary, UniformLineWithAGroundedPartIsTheElasticCatenary) {
  expectSameAsUniformCatenary(700.0, 450.0, true);
}

TEST(MultiSectionCatenary, UniformLineLiftedOffAtTheAnchorIsTheElasticCatenary) {
  expectSameAsUniformCatenary(850.0, 480.0, false);
}

/// A 10 in steel riser in 1500 m: 500 m flowline, 800 m to the sag bend, 400 m of buoyancy (OD 0.9 m,
/// `buoyancyMass` kg/m), 1540 m up to 10 m below the surface, `span` m from the anchor horizontally.
void expectLazyWaveWithItsHog(double span, double buoyancyMass) {
  constexpr double kPi = 3.141592653589793, g = 9.80665;
  const double wRiser = 130.0 * g - 1025.0 * g * 0.25 * kPi * 0.2731 * 0.2731;
  const double wBuoy = buoyancyMass * g - 1025.0 * g * 0.25 * kPi * 0.9 * 0.9;
  MultiSectionCatenary m(
      {{500.0, wRiser, 3.3e9}, {800.0, wRiser, 3.3e9}, {400.0, wBuoy, 3.3e9}, {1540.0, wRiser, 3.3e9}});
  const double height = 1490.0;
  ASSERT_TRUE(m.solve(span, height, 1e-3 * m.weightScale, 0.5));
  const auto [xEnd, zEnd] = m.at(m.length);
  EXPECT_NEAR(xEnd, span, 1e-9 * m.length);
  EXPECT_NEAR(zEnd, height, 1e-9 * m.length);
  EXPECT_TRUE(m.groundedHeavy());
  EXPECT_LE(m.grounded, 1300.0);  // no part of the buoyancy section on the seabed
  double hog = -1e9, sag = 1e9;
  for (double s = 0.0; s <= m.length; s += 5.0) {
    const double z = m.at(s).second;
    EXPECT_GE(z, -1e-6) << "s = " << s;
    if (s >= 1300.0 && s <= 1700.0) hog = std::max(hog, z);
    if (s >= 1000.0 && s <= 1300.0) sag = std::min(sag, z);
  }
  EXPECT_GT(hog, sag + 10.0);
}

TEST(MultiSectionCatenary, LazyWaveWhoseEquivalentLineIsSlackHasItsHog) {
  // 1600 m from the anchor the equivalent uniform line is slack: the multi-section solve was skipped there.
  constexpr double g = 9.80665;
  const double meanWeight = (2840.0 * (130.0 * g - 1025.0 * g * 0.25 * 3.141592653589793 * 0.2731 * 0.2731) +
                             400.0 * (250.0 * g - 1025.0 * g * 0.25 * 3.141592653589793 * 0.81)) /
                            3240.0;
  EXPECT_EQ(solveAnchoredCatenary({1600.0, 1490.0, 3240.0, meanWeight, 3.3e9}).regime,
            CatenaryRegime::SlackGrounded);
  expectLazyWaveWithItsHog(1600.0, 250.0);
}

TEST(MultiSectionCatenary, LazyWaveDoesNotLayItsBuoyancySectionOnTheSeabed) {
  // 1900 m away with 450 kg/m of buoyancy the solve found H 32.1 kN with 1704 m grounded: the flowline, the
  // sag bend section and the buoyancy section flat on the seabed (only the section at the touchdown was
  // required to be heavy).
  expectLazyWaveWithItsHog(1900.0, 450.0);
}

TEST(MultiSectionCatenary, AGroundedBuoyantSectionIsNotHeavy) {
  MultiSectionCatenary m({{100.0, 500.0, 1e9}, {50.0, -300.0, 1e9}, {100.0, 500.0, 1e9}});
  m.setUnknowns(std::log(1e4), 160.0 / 250.0);  // grounded over the buoyant section into the third
  EXPECT_FALSE(m.groundedHeavy());
  m.setUnknowns(std::log(1e4), 90.0 / 250.0);
  EXPECT_TRUE(m.groundedHeavy());
}

}  // namespace
}  // namespace tangle::catenary
