/// @file HeadingTableTest.cpp
/// Periodic linear interpolation of heading tables (tangle::vessel::interpolate).

#include <gtest/gtest.h>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/vessel/HeadingTable.hpp"

namespace tangle::vessel {
namespace {

// Tolerance 1e-12: linear interpolation of O(1) values, only rounding errors (a few ulp) expected.
constexpr double kTol = 1e-12;

model::HeadingTable table() {
  model::HeadingTable t;
  t.heading = {degToRad(30.0), degToRad(90.0), degToRad(270.0)};
  t.values = {Vec3(1.0, 2.0, 3.0), Vec3(3.0, -2.0, 0.0), Vec3(-1.0, 0.0, 1.0)};
  return t;
}

// Source: hand computation of linear interpolation between the tabulated points.
TEST(HeadingTable, ReproducesTablePointsAndInterpolatesLinearly) {
  const model::HeadingTable t = table();
  for (std::size_t i = 0; i < 3; ++i) EXPECT_LT((interpolate(t, t.heading[i]) - t.values[i]).norm(), kTol);
  // 60 deg: halfway between 30 and 90 deg.
  EXPECT_LT((interpolate(t, degToRad(60.0)) - Vec3(2.0, 0.0, 1.5)).norm(), kTol);
  // 135 deg: a quarter of the way from 90 to 270 deg.
  EXPECT_LT((interpolate(t, degToRad(135.0)) - Vec3(2.0, -1.5, 0.25)).norm(), kTol);
}

// Source: the wrap-around segment runs from 270 deg to 390 deg (= 30 deg), 120 deg long.
TEST(HeadingTable, WrapsAroundBetweenLastAndFirstHeading) {
  const model::HeadingTable t = table();
  // 330 deg: halfway from 270 to 390.
  const Vec3 mid(0.0, 1.0, 2.0);
  EXPECT_LT((interpolate(t, degToRad(330.0)) - mid).norm(), kTol);
  // 0 deg: three quarters of the way -> (-1 + 0.75*2, 0 + 0.75*2, 1 + 0.75*2).
  const Vec3 atZero(0.5, 1.5, 2.5);
  EXPECT_LT((interpolate(t, 0.0) - atZero).norm(), kTol);
  // Headings outside [0, 2 pi) are wrapped.
  EXPECT_LT((interpolate(t, degToRad(-30.0)) - mid).norm(), kTol);
  EXPECT_LT((interpolate(t, degToRad(720.0)) - atZero).norm(), kTol);
  // Slope of the wrap-around segment: (values[0] - values[2]) / (120 deg).
  const HeadingSample s = interpolateWithSlope(t, degToRad(350.0));
  EXPECT_LT((s.slope - Vec3(2.0, 2.0, 2.0) / degToRad(120.0)).norm(), kTol);
}

// Source: definition (continuity of a linear interpolant at a knot, both sides of the wrap point).
TEST(HeadingTable, IsContinuousAcrossTheWrapPoint) {
  const model::HeadingTable t = table();
  const double d = 1e-9;
  EXPECT_LT((interpolate(t, 2.0 * kPi - d) - interpolate(t, d)).norm(), 1e-8);
  EXPECT_LT((interpolate(t, degToRad(30.0) - d) - interpolate(t, degToRad(30.0) + d)).norm(), 1e-8);
}

TEST(HeadingTable, SingleEntryIsConstant) {
  model::HeadingTable t;
  t.heading = {1.0};
  t.values = {Vec3(4.0, 5.0, 6.0)};
  for (double h : {0.0, 1.0, 3.0, -7.0}) {
    const HeadingSample s = interpolateWithSlope(t, h);
    EXPECT_EQ(s.value, Vec3(4.0, 5.0, 6.0));
    EXPECT_EQ(s.slope, Vec3::Zero());
  }
}

TEST(HeadingTable, RejectsInvalidTables) {
  model::HeadingTable empty;
  EXPECT_THROW(interpolate(empty, 0.0), Error);
  model::HeadingTable unsorted = table();
  std::swap(unsorted.heading[0], unsorted.heading[1]);
  EXPECT_THROW(interpolate(unsorted, 0.0), Error);
  model::HeadingTable duplicate = table();
  duplicate.heading[1] = duplicate.heading[0];
  EXPECT_THROW(interpolate(duplicate, 0.0), Error);
  model::HeadingTable outOfRange = table();
  outOfRange.heading[2] = 2.0 * kPi;
  EXPECT_THROW(interpolate(outOfRange, 0.0), Error);
  model::HeadingTable mismatch = table();
  mismatch.values.pop_back();
  EXPECT_THROW(interpolate(mismatch, 0.0), Error);
}

}  // namespace
}  // namespace tangle::vessel
