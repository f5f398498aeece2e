/// @file CurrentProfileTest.cpp
/// Piecewise-linear current profile (tangle::hydro::CurrentProfile).

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/CurrentProfile.hpp"

namespace tangle::hydro {
namespace {

// Tolerance 1e-14 m/s everywhere: one linear interpolation and one cos/sin (few ulps of O(1) values).
constexpr double kTol = 1e-14;

TEST(CurrentProfile, DefaultIsNoCurrent) {
  const CurrentProfile none;
  EXPECT_TRUE(none.isZero());
  EXPECT_EQ(none.velocity(-10.0), Vec3::Zero());
  EXPECT_EQ(none.velocity(2.0), Vec3::Zero());
}

// Source: convention of the project: azimuth anticlockwise from +x, direction the current flows towards.
TEST(CurrentProfile, UniformCurrentAndAzimuthDirection) {
  const CurrentProfile east = CurrentProfile::uniform(1.5, 0.0);
  const CurrentProfile north = CurrentProfile::uniform(1.5, degToRad(90.0));
  const CurrentProfile southWest = CurrentProfile::uniform(2.0, degToRad(225.0));
  for (double z : {-500.0, -20.0, 0.0, 3.0}) {
    EXPECT_LT((east.velocity(z) - Vec3(1.5, 0.0, 0.0)).norm(), kTol);
    EXPECT_LT((north.velocity(z) - Vec3(0.0, 1.5, 0.0)).norm(), kTol);
    EXPECT_LT((southWest.velocity(z) - Vec3(-std::sqrt(2.0), -std::sqrt(2.0), 0.0)).norm(), kTol);
  }
  EXPECT_FALSE(east.isZero());
}

// Source: linear interpolation by hand; constant beyond the end levels; z > 0 keeps the surface value.
TEST(CurrentProfile, PiecewiseLinearInterpolationUnsortedInput) {
  const CurrentProfile profile({{-50.0, 0.5, 0.0}, {0.0, 1.0, 0.0}, {-100.0, 0.2, 0.0}});
  ASSERT_EQ(profile.levels().size(), 3u);
  EXPECT_EQ(profile.levels().front().z, -100.0);  // sorted, deepest first
  EXPECT_NEAR(profile.velocity(0.0).x(), 1.0, kTol);
  EXPECT_NEAR(profile.velocity(-25.0).x(), 0.75, kTol);
  EXPECT_NEAR(profile.velocity(-50.0).x(), 0.5, kTol);
  EXPECT_NEAR(profile.velocity(-80.0).x(), 0.5 + 0.6 * (0.2 - 0.5), kTol);
  EXPECT_NEAR(profile.velocity(-100.0).x(), 0.2, kTol);
  EXPECT_NEAR(profile.velocity(-300.0).x(), 0.2, kTol);  // below deepest level: constant
  EXPECT_NEAR(profile.velocity(4.0).x(), 1.0, kTol);     // above surface: surface value (documented)
  for (double z : {-300.0, -60.0, 4.0}) {
    EXPECT_EQ(profile.velocity(z).y(), 0.0);
    EXPECT_EQ(profile.velocity(z).z(), 0.0);
  }
}

// Source: documented rule: azimuth interpolated linearly along the shorter arc (350 deg -> 10 deg passes
// through 0 deg, not 180 deg).
TEST(CurrentProfile, AzimuthInterpolatedAlongShorterArc) {
  const CurrentProfile profile({{0.0, 1.0, degToRad(350.0)}, {-100.0, 1.0, degToRad(10.0)}});
  const Vec3 mid = profile.velocity(-50.0);
  EXPECT_NEAR(mid.x(), 1.0, kTol);
  EXPECT_NEAR(mid.y(), 0.0, kTol);
  const Vec3 quarter = profile.velocity(-25.0);  // 355 deg
  EXPECT_NEAR(std::atan2(quarter.y(), quarter.x()), degToRad(-5.0), kTol);
  EXPECT_NEAR(quarter.norm(), 1.0, kTol);
  // Speed and direction vary together.
  const CurrentProfile turning({{0.0, 2.0, 0.0}, {-10.0, 1.0, degToRad(90.0)}});
  const Vec3 v = turning.velocity(-5.0);
  EXPECT_NEAR(v.norm(), 1.5, kTol);
  EXPECT_NEAR(std::atan2(v.y(), v.x()), degToRad(45.0), kTol);
}

TEST(CurrentProfile, RejectsInvalidLevels) {
  EXPECT_THROW(CurrentProfile(std::vector<CurrentLevel>{}), Error);
  EXPECT_THROW(CurrentProfile({{1.0, 1.0, 0.0}}), Error);                     // above still water
  EXPECT_THROW(CurrentProfile({{-1.0, -0.1, 0.0}}), Error);                   // negative speed
  EXPECT_THROW(CurrentProfile({{-1.0, 1.0, 0.0}, {-1.0, 2.0, 0.0}}), Error);  // duplicate level
  EXPECT_THROW(CurrentProfile({{std::nan(""), 1.0, 0.0}}), Error);
  EXPECT_THROW(CurrentProfile({{-1.0, 1.0, std::nan("")}}), Error);
  try {
    CurrentProfile({{0.0, 1.0, 0.0}, {-5.0, -2.0, 0.0}});
    FAIL() << "expected tangle::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("speed"), std::string::npos) << e.what();
  }
}

}  // namespace
// A current changing in time: linear in time between its profiles, component by component; the first profile
// before its time (and as the steady velocity(z)), the last after its own. Exact values by hand.
TEST(CurrentProfile, HistoryInterpolatesInTime) {
  const CurrentProfile east = CurrentProfile::uniform(1.0, 0.0);
  const CurrentProfile north({{-100.0, 0.0, kPi / 2.0}, {0.0, 2.0, kPi / 2.0}});
  const CurrentProfile h = CurrentProfile::withHistory({10.0, 20.0}, {east, north});
  EXPECT_TRUE(h.changes());
  EXPECT_FALSE(east.changes());
  EXPECT_NEAR((h.velocity(-50.0) - Vec3(1.0, 0.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((h.velocity(-50.0, 0.0) - Vec3(1.0, 0.0, 0.0)).norm(), 0.0, 1e-15);
  // Halfway in time at z = -50 (north's speed there is 1 m/s): the mean of (1, 0) and (0, 1).
  EXPECT_NEAR((h.velocity(-50.0, 15.0) - Vec3(0.5, 0.5, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((h.velocity(0.0, 17.5) - Vec3(0.25, 1.5, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((h.velocity(-50.0, 99.0) - Vec3(0.0, 1.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_FALSE(h.isZero());
  EXPECT_THROW(CurrentProfile::withHistory({10.0, 10.0}, {east, north}), Error);
  EXPECT_THROW(CurrentProfile::withHistory({10.0}, {east, north}), Error);
}

}  // namespace tangle::hydro
