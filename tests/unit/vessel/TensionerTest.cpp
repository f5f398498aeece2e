/// @file TensionerTest.cpp
/// Constant-tension tensioner with end stops (tangle::vessel::tensionerForce).

#include <gtest/gtest.h>

#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/vessel/Tensioner.hpp"

namespace tangle::vessel {
namespace {

model::TensionerSpec spec() {
  model::TensionerSpec s;
  s.enabled = true;
  s.tension = 2.0e6;
  s.stroke = 10.0;
  s.stopStiffness = 1.0e7;
  return s;
}

// Source: the law in Tensioner.hpp (hand values). Tolerance 1e-6 N on forces of ~1e6 N: a few ulp.
TEST(Tensioner, ConstantTensionWithinStroke) {
  for (double s : {-5.0, -2.0, 0.0, 3.0, 5.0}) {
    const TensionerForce f = tensionerForce(spec(), s);
    EXPECT_NEAR(f.force, 2.0e6, 1e-6);
    EXPECT_EQ(f.stiffness, 0.0);
  }
}

TEST(Tensioner, GasSpringWithinStrokeContinuousAtTheStops) {
  model::TensionerSpec p = spec();
  p.stiffness = 5.0e4;
  // Within the stroke: T + k_g s (hand values).
  EXPECT_NEAR(tensionerForce(p, -2.0).force, 2.0e6 - 1.0e5, 1e-6);
  EXPECT_EQ(tensionerForce(p, 3.0).stiffness, 5.0e4);
  // Beyond the lower stop (s = 5.1): T + k_g S/2 + k 0.1; stiffness k, the force's slope (the gas spring is
  // held at its stroke's end; until 2026-12-06 the stiffness was k_g + k, not the derivative of the force).
  EXPECT_NEAR(tensionerForce(p, 5.1).force, 2.0e6 + 2.5e5 + 1.0e6, 1e-6);
  EXPECT_EQ(tensionerForce(p, 5.1).stiffness, 1.0e7);
  for (double s : {-7.0, 0.5, 6.0}) {
    const double fd = (tensionerForce(p, s + 1e-3).force - tensionerForce(p, s - 1e-3).force) / 2e-3;
    EXPECT_NEAR(fd, tensionerForce(p, s).stiffness, 1e-3) << "s = " << s;
  }
  // Continuous at both stops (the jump over 2e-9 m is at most (k_g + k) 2e-9 plus rounding).
  for (double stop : {-5.0, 5.0})
    EXPECT_NEAR(tensionerForce(p, stop - 1e-9).force, tensionerForce(p, stop + 1e-9).force, 0.05);
}

TEST(Tensioner, EndStopsAddForceAndAreContinuous) {
  const model::TensionerSpec p = spec();
  // Fully extended (end 0.1 m beyond the lower stop): tension grows by k * 0.1.
  EXPECT_NEAR(tensionerForce(p, 5.1).force, 2.0e6 + 1.0e6, 1e-6);
  EXPECT_EQ(tensionerForce(p, 5.1).stiffness, 1.0e7);
  // Fully collapsed (0.3 m beyond the upper stop): tension drops by k * 0.3, may turn negative.
  EXPECT_NEAR(tensionerForce(p, -5.3).force, 2.0e6 - 3.0e6, 1e-6);
  EXPECT_EQ(tensionerForce(p, -5.3).stiffness, 1.0e7);
  // Continuity at both stops: jump over 2e-9 m is k * 1e-9 at most (0.01 N) plus rounding.
  for (double edge : {-5.0, 5.0}) {
    EXPECT_NEAR(tensionerForce(p, edge - 1e-9).force, tensionerForce(p, edge + 1e-9).force, 0.02);
  }
  // Stiffness = d(force)/d(stroke): central differences away from the kinks, exact for a linear law
  // (tolerance: rounding eps * 3e6 / 1e-3 ~ 1e-6 relative).
  for (double s : {-7.0, 0.5, 6.0}) {
    const double fd = (tensionerForce(p, s + 1e-3).force - tensionerForce(p, s - 1e-3).force) / 2e-3;
    EXPECT_NEAR(fd, tensionerForce(p, s).stiffness, 1e-3);
  }
}

TEST(Tensioner, RejectsInvalidInput) {
  model::TensionerSpec p = spec();
  p.stroke = -1.0;
  EXPECT_THROW(tensionerForce(p, 0.0), Error);
  p = spec();
  p.tension = -1.0;
  EXPECT_THROW(tensionerForce(p, 0.0), Error);
  EXPECT_THROW(tensionerForce(spec(), std::numeric_limits<double>::quiet_NaN()), Error);
}

}  // namespace
}  // namespace tangle::vessel
