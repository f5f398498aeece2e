// Unit tests of hydro::ComponentSea (`waves.type: components`): one component is the Airy wave of the same
// height, period, direction and phase (AiryWave, itself checked against linear theory in AiryWaveTest) at
// points below, near and above the surface, with every stretching; components of different directions add
// (exactly without stretching, where the kinematics are linear in the components); bad components are
// refused by name. Tolerances: round-off of the same formulas evaluated in a different order, 1e-12 relative.

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/ComponentSea.hpp"

namespace tangle::hydro {
namespace {

void expectSame(const FluidKinematics& a, const FluidKinematics& b, double scale) {
  EXPECT_NEAR((a.velocity - b.velocity).norm(), 0.0, 1e-12 * scale);
  EXPECT_NEAR((a.acceleration - b.acceleration).norm(), 0.0, 1e-12 * scale);
}

TEST(ComponentSea, OneComponentIsTheAiryWave) {
  const double depth = 80.0, period = 9.0, height = 3.0, azimuth = 0.6, phase = 1.1;
  for (const Stretching stretching : {Stretching::Wheeler, Stretching::Vertical, Stretching::None}) {
    const AiryWave airy(height, period, azimuth, depth, kStandardGravity, phase, stretching);
    const ComponentSea sea({{2.0 * kPi / period, 0.5 * height, phase, azimuth}}, depth, kStandardGravity,
                           stretching);
    EXPECT_NEAR(sea.waveNumber(0), airy.waveNumber(), 1e-14);
    for (const Vec3& p :
         {Vec3(3.0, -7.0, -20.0), Vec3(-40.0, 12.0, -0.4), Vec3(10.0, 5.0, 1.2), Vec3(0, 0, -79.0)})
      for (const double t : {0.0, 2.3, 17.9}) {
        EXPECT_NEAR(sea.elevation(p.x(), p.y(), t), airy.elevation(p.x(), p.y(), t), 1e-13);
        double etaSea = 0.0, etaAiry = 0.0;
        const FluidKinematics a = sea.kinematics(p, t, etaSea), b = airy.kinematics(p, t, etaAiry);
        EXPECT_NEAR(etaSea, etaAiry, 1e-13);
        expectSame(a, b, 1.0);
      }
  }
}

TEST(ComponentSea, ComponentsOfDifferentDirectionsAdd) {
  // Without stretching the kinematics below the troughs are linear in the components.
  const double depth = 60.0;
  const ComponentSea::Component a{0.7, 0.8, 0.3, 0.0}, b{1.1, 0.4, -2.0, 2.0};
  const ComponentSea both({a, b}, depth, kStandardGravity, Stretching::None);
  const ComponentSea first({a}, depth, kStandardGravity, Stretching::None);
  const ComponentSea second({b}, depth, kStandardGravity, Stretching::None);
  EXPECT_NEAR(both.variance(), 0.5 * (0.8 * 0.8 + 0.4 * 0.4), 1e-15);
  for (const Vec3& p : {Vec3(5.0, 3.0, -2.0), Vec3(-30.0, 18.0, -25.0)})
    for (const double t : {0.0, 4.4}) {
      EXPECT_NEAR(both.elevation(p.x(), p.y(), t),
                  first.elevation(p.x(), p.y(), t) + second.elevation(p.x(), p.y(), t), 1e-14);
      const FluidKinematics sum = both.kinematics(p, t), u = first.kinematics(p, t),
                            v = second.kinematics(p, t);
      FluidKinematics added;
      added.velocity = u.velocity + v.velocity;
      added.acceleration = u.acceleration + v.acceleration;
      expectSame(sum, added, 1.0);
      // The second travels towards 2 rad: its horizontal velocity lies along (cos 2, sin 2).
      EXPECT_NEAR(v.velocity.x() * std::sin(2.0) - v.velocity.y() * std::cos(2.0), 0.0, 1e-14);
    }
}

TEST(ComponentSea, RefusesBadComponents) {
  EXPECT_THROW(ComponentSea({}, 50.0), Error);
  EXPECT_THROW(ComponentSea({{0.0, 1.0, 0.0, 0.0}}, 50.0), Error);
  EXPECT_THROW(ComponentSea({{1.0, -1.0, 0.0, 0.0}}, 50.0), Error);
  EXPECT_THROW(ComponentSea({{1.0, 1.0, std::nan(""), 0.0}}, 50.0), Error);
}

}  // namespace
}  // namespace tangle::hydro
