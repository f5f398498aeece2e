/// Tests of the grouping of static contact samples into the places where two lines touch
/// (StaticContactReport.hpp, groupContactZones). A flexible riser over an SCR in current touched it near
/// the seabed (z = -996 m) and near the top (z = -161 m): the report gave one pair "over 1.83 m" with an
/// arc range of 496-1554 m, read as a kilometre of contact. The expected zones here follow from the
/// samples by hand (sums, ranges, force-weighted centres), exact but for round-off.

#include <gtest/gtest.h>

#include <vector>

#include "tangle/contact/StaticContactReport.hpp"

namespace tangle::contact {
namespace {

StaticContactSample lengthSample(int line1, int line2, double arc1, double arc2, double z, double perLength,
                                 double length) {
  StaticContactSample s;
  s.line1 = line1;
  s.line2 = line2;
  s.arc1 = arc1;
  s.arc2 = arc2;
  s.position = Vec3(arc1, 0.0, z);
  s.normal = perLength * length;
  s.force = Vec3(0.0, 0.0, -s.normal);
  s.length = length;
  s.perLength = perLength;
  return s;
}

TEST(ContactZones, TwoPlacesOfOnePairAreTwoZones) {
  // Line 0 on line 1 near the seabed (arcs 496-497 m) and near the top (1553-1554 m), samples given out of
  // order; lines' longest elements 20 m: joined across 40 m.
  const std::vector<StaticContactSample> samples = {lengthSample(0, 1, 1553.5, 1854.0, -160.0, 4000.0, 0.5),
                                                    lengthSample(0, 1, 496.5, 796.0, -996.0, 6000.0, 0.5),
                                                    lengthSample(0, 1, 497.0, 796.5, -995.0, 2000.0, 0.5),
                                                    lengthSample(0, 1, 1554.0, 1854.5, -161.0, 4000.0, 0.25)};
  const std::vector<StaticContactZone> zones = groupContactZones(samples, {40.0, 40.0});
  ASSERT_EQ(zones.size(), 2u);
  const StaticContactZone &low = zones[0], &high = zones[1];
  EXPECT_DOUBLE_EQ(low.normal, 3000.0 + 1000.0);
  EXPECT_DOUBLE_EQ(low.length, 1.0);
  EXPECT_DOUBLE_EQ(low.peakPerLength, 6000.0);
  EXPECT_DOUBLE_EQ(low.arc1From, 496.5);
  EXPECT_DOUBLE_EQ(low.arc1To, 497.0);
  EXPECT_DOUBLE_EQ(low.arc2From, 796.0);
  EXPECT_DOUBLE_EQ(low.arc2To, 796.5);
  EXPECT_NEAR(low.centre.z(), (3000.0 * -996.0 + 1000.0 * -995.0) / 4000.0, 1e-9);
  EXPECT_NEAR(low.force.z(), -4000.0, 1e-9);
  EXPECT_EQ(low.samples, 2);
  EXPECT_EQ(low.points, 0);
  EXPECT_DOUBLE_EQ(high.normal, 2000.0 + 1000.0);
  EXPECT_DOUBLE_EQ(high.length, 0.75);
  EXPECT_DOUBLE_EQ(high.arc1From, 1553.5);
  EXPECT_DOUBLE_EQ(high.arc1To, 1554.0);
  EXPECT_NEAR(high.centre.z(), (2000.0 * -160.0 + 1000.0 * -161.0) / 3000.0, 1e-9);
}

TEST(ContactZones, SamplesWithinTheJoinDistanceAreOnePlace) {
  // 10 m apart along line 0, joined across 10 m (at the bound) and across 20 m; split across 9.99 m.
  const std::vector<StaticContactSample> samples = {lengthSample(0, 1, 100.0, 50.0, -10.0, 1000.0, 1.0),
                                                    lengthSample(0, 1, 110.0, 60.0, -10.0, 1000.0, 1.0),
                                                    lengthSample(0, 1, 120.0, 70.0, -10.0, 1000.0, 1.0)};
  EXPECT_EQ(groupContactZones(samples, {10.0, 10.0}).size(), 1u);
  EXPECT_EQ(groupContactZones(samples, {20.0, 20.0}).size(), 1u);
  EXPECT_EQ(groupContactZones(samples, {9.99, 9.99}).size(), 3u);
}

TEST(ContactZones, PairsAreKeptApartAndAPointContactCountsAsAPoint) {
  // Pairs (0, 2) and (1, 2) with interleaved samples at the same arcs on their line 1, and a crossing (a
  // point contact) of pair (0, 1).
  StaticContactSample crossing;
  crossing.line1 = 0;
  crossing.line2 = 1;
  crossing.arc1 = 30.0;
  crossing.arc2 = 40.0;
  crossing.normal = 5000.0;
  crossing.force = Vec3(0.0, 5000.0, 0.0);
  crossing.position = Vec3(1.0, 2.0, 3.0);
  const std::vector<StaticContactSample> samples = {
      lengthSample(1, 2, 10.0, 10.0, -5.0, 100.0, 1.0), lengthSample(0, 2, 10.0, 12.0, -5.0, 300.0, 1.0),
      crossing, lengthSample(1, 2, 11.0, 11.0, -5.0, 200.0, 1.0)};
  const std::vector<StaticContactZone> zones = groupContactZones(samples, {5.0, 5.0, 5.0});
  ASSERT_EQ(zones.size(), 3u);
  EXPECT_EQ(zones[0].line1, 0);
  EXPECT_EQ(zones[0].line2, 1);
  EXPECT_EQ(zones[0].points, 1);
  EXPECT_EQ(zones[0].samples, 0);
  EXPECT_DOUBLE_EQ(zones[0].length, 0.0);
  EXPECT_DOUBLE_EQ(zones[0].peakPerLength, 0.0);
  EXPECT_DOUBLE_EQ(zones[0].normal, 5000.0);
  EXPECT_TRUE(zones[0].centre.isApprox(Vec3(1.0, 2.0, 3.0)));
  EXPECT_EQ(zones[1].line1, 0);
  EXPECT_EQ(zones[1].line2, 2);
  EXPECT_DOUBLE_EQ(zones[1].normal, 300.0);
  EXPECT_EQ(zones[2].line1, 1);
  EXPECT_EQ(zones[2].line2, 2);
  EXPECT_DOUBLE_EQ(zones[2].normal, 300.0);
  EXPECT_EQ(zones[2].samples, 2);
}

TEST(ContactZones, AWrapTouchingOneArcOfLineOneFromTwoArcsOfLineTwoIsTwoPlaces) {
  // Line 1 (a rope) passes line 0 (a post) twice at the same height: samples at arcs 10-11 m of the post
  // from arcs 20-21 m and 80-80.5 m of the rope, interleaved along the post; joined across 2 m on each line.
  const std::vector<StaticContactSample> samples = {
      lengthSample(0, 1, 10.0, 20.0, -5.0, 1000.0, 0.5), lengthSample(0, 1, 10.2, 80.0, -5.0, 3000.0, 0.5),
      lengthSample(0, 1, 10.5, 20.5, -5.0, 1000.0, 0.5), lengthSample(0, 1, 10.7, 80.5, -5.0, 3000.0, 0.5),
      lengthSample(0, 1, 11.0, 21.0, -5.0, 1000.0, 0.5)};
  const std::vector<StaticContactZone> zones = groupContactZones(samples, {2.0, 2.0});
  ASSERT_EQ(zones.size(), 2u);
  // In the order of their first sample along line 0: the pass at 20-21 m of the rope first.
  EXPECT_DOUBLE_EQ(zones[0].normal, 3 * 500.0);
  EXPECT_DOUBLE_EQ(zones[0].arc1From, 10.0);
  EXPECT_DOUBLE_EQ(zones[0].arc1To, 11.0);
  EXPECT_DOUBLE_EQ(zones[0].arc2From, 20.0);
  EXPECT_DOUBLE_EQ(zones[0].arc2To, 21.0);
  EXPECT_EQ(zones[0].samples, 3);
  EXPECT_DOUBLE_EQ(zones[1].normal, 2 * 1500.0);
  EXPECT_DOUBLE_EQ(zones[1].arc1From, 10.2);
  EXPECT_DOUBLE_EQ(zones[1].arc1To, 10.7);
  EXPECT_DOUBLE_EQ(zones[1].arc2From, 80.0);
  EXPECT_DOUBLE_EQ(zones[1].arc2To, 80.5);
  EXPECT_EQ(zones[1].samples, 2);
}

TEST(ContactZones, TheJoinAlongLineTwoHoldsAtItsBoundAndAChainIsOnePlace) {
  // Along line 0 the samples follow 1 m apart; along line 1 they step 3 m: joined with 3 m on line 1 (at the
  // bound), split with 2.99 m. A chain: no two ends of it within the join, still one place.
  const std::vector<StaticContactSample> samples = {
      lengthSample(0, 1, 0.0, 0.0, -1.0, 100.0, 1.0), lengthSample(0, 1, 1.0, 3.0, -1.0, 100.0, 1.0),
      lengthSample(0, 1, 2.0, 6.0, -1.0, 100.0, 1.0), lengthSample(0, 1, 3.0, 9.0, -1.0, 100.0, 1.0)};
  EXPECT_EQ(groupContactZones(samples, {1.0, 3.0}).size(), 1u);
  EXPECT_EQ(groupContactZones(samples, {1.0, 2.99}).size(), 4u);
  EXPECT_EQ(groupContactZones(samples, {0.99, 3.0}).size(), 4u);
}

TEST(ContactZones, ALineTouchingItselfIsOnePlaceWhicheverPassASampleComesFrom) {
  // A hose looped over itself: its arcs 10-11 m lie on its arcs 50-51 m. The pass along 10-11 m gives samples
  // (10, 50) with the force on the 10 m side (up), the pass along 50-51 m samples (50, 10) with the force on
  // the 50 m side (down). One place, arcs 10-11 against 50-51 m, force on the 10 m side: both passes' up.
  std::vector<StaticContactSample> samples = {lengthSample(2, 2, 10.0, 50.0, -5.0, 1000.0, 0.5),
                                              lengthSample(2, 2, 50.0, 10.0, -5.0, 1000.0, 0.5),
                                              lengthSample(2, 2, 11.0, 51.0, -5.0, 1000.0, 0.5),
                                              lengthSample(2, 2, 51.0, 11.0, -5.0, 1000.0, 0.5)};
  for (std::size_t k = 0; k < samples.size(); ++k) samples[k].force = Vec3(0.0, 0.0, k % 2 == 0 ? 500.0 : -500.0);
  const std::vector<StaticContactZone> zones = groupContactZones(samples, {2.0, 2.0, 2.0});
  ASSERT_EQ(zones.size(), 1u);
  EXPECT_DOUBLE_EQ(zones[0].normal, 4 * 500.0);
  EXPECT_DOUBLE_EQ(zones[0].force.z(), 4 * 500.0);
  EXPECT_DOUBLE_EQ(zones[0].arc1From, 10.0);
  EXPECT_DOUBLE_EQ(zones[0].arc1To, 11.0);
  EXPECT_DOUBLE_EQ(zones[0].arc2From, 50.0);
  EXPECT_DOUBLE_EQ(zones[0].arc2To, 51.0);
  EXPECT_EQ(zones[0].samples, 4);
}

TEST(ContactZones, NoSamplesNoZones) { EXPECT_TRUE(groupContactZones({}, {1.0}).empty()); }

}  // namespace
}  // namespace tangle::contact
