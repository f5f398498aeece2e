/// Tests of tangle::geometry::segmentDistance (Eberly 2005 region algorithm).
/// Hand-computed cases use inputs that are exact binary fractions, so the exact answer is known and
/// the tolerances are a few ulp; randomised cases are compared with an independent brute-force
/// minimiser and are seeded so that a failure can be replayed.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::geometry {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
/// Tolerance for hand-computed cases with O(1) exact binary inputs: a handful of roundings in the
/// dot/cross products and at most one division, i.e. a few ulp of 1.
constexpr double kTight = 8.0 * kEps;

/// Checks the invariants every result must satisfy: s, t in [0, 1], closest points on the
/// segments at s and t, distance = |closest0 - closest1| and squaredDistance = distance^2.
void expectConsistent(const SegmentDistanceResult& r, const Vec3& p0, const Vec3& p1, const Vec3& q0,
                      const Vec3& q1) {
  EXPECT_GE(r.s, 0.0);
  EXPECT_LE(r.s, 1.0);
  EXPECT_GE(r.t, 0.0);
  EXPECT_LE(r.t, 1.0);
  // p0 + s (p1 - p0) is one rounding per operation away from the stored point: a few ulp of the
  // coordinates' magnitude.
  const double scale = std::max({1.0, p0.cwiseAbs().maxCoeff(), p1.cwiseAbs().maxCoeff(),
                                 q0.cwiseAbs().maxCoeff(), q1.cwiseAbs().maxCoeff()});
  EXPECT_LE((r.closest0 - (p0 + r.s * (p1 - p0))).cwiseAbs().maxCoeff(), 4.0 * kEps * scale);
  EXPECT_LE((r.closest1 - (q0 + r.t * (q1 - q0))).cwiseAbs().maxCoeff(), 4.0 * kEps * scale);
  // Same formula as the implementation: equal up to the last bit of sqrt/rounding.
  EXPECT_NEAR(r.distance, (r.closest0 - r.closest1).norm(), 2.0 * kEps * std::max(r.distance, 1e-300));
  EXPECT_NEAR(r.squaredDistance, r.distance * r.distance, 4.0 * kEps * r.squaredDistance);
  EXPECT_EQ(r.parallel, r.region == -1);
}

// ------------------------------------------------------------------------------------------------
// One scenario per region of the (s,t) plane. Segment 0 is the x axis from (0,0,0) to (1,0,0)
// (s = x) unless flipped; segment 1 lies in the plane z = 1, so the common perpendicular of the two
// lines is vertical: s^ is the x where the plan view of line 1 crosses y = 0 and t^ the parameter of
// line 1 there. The constrained minimum is derived by hand for each case below.
struct RegionCase {
  const char* name;
  Vec3 p0, p1, q0, q1;
  int region;
  double s, t, squaredDistance;
};

// Hand derivations (base cases, segment 0 = (0,0,0)-(1,0,0)):
// R0: line 1 (0.25,-1,1)+t(0.5,2,0) crosses y=0 at t=0.5, x=0.5 inside both: s=t=0.5, d^2 = 1.
// R1: (1.5,-1,1)+t(1,2,0) crosses at x=2 (s^=2), t^=0.5. On s=1: Q(1,t) = (0.5+t)^2+(2t-1)^2+1,
//     dQ/dt = 10t-3 = 0 -> t = 0.3, Q = 0.64+0.16+1 = 1.8.
// R5: (-1.5,-1,1)+t(1,2,0) crosses at x=-1 (s^=-1). On s=0: Q(0,t) = (t-1.5)^2+(2t-1)^2+1,
//     dQ/dt = 10t-7 -> t = 0.7, Q = 0.64+0.16+1 = 1.8.
// R3: (1.75,-1.25,1)+t(-1,1,0) crosses at t^=1.25, x=0.5. On t=1: q1 = (0.75,-0.25,1), its
//     projection x = 0.75 is inside segment 0: s = 0.75, Q = 0.0625+1 = 1.0625.
// R7: (0.75,0.25,1)+t(1,1,0) crosses at t^=-0.25, x=0.5. On t=0: q0 projects to s = 0.75,
//     Q = 0.0625+1.
// R2a: (-0.5,-2,1)+t(1,1,0) crosses at x=1.5, t^=2. On t=1: q1 = (0.5,-1,1) projects to s=0.5,
//     Q = 1+1 = 2; on s=1: Q(1,t) = (t-1.5)^2+(t-2)^2+1 is minimal at t=1.75 -> clamped to 1,
//     Q = 2.25 > 2. Answer on edge t=1 (Qs(1,1) = 2(a+b+d) = 2(1-1+0.5) > 0).
// R2b: (0.75,-1.25,1)+t(1,1,0) crosses at x=2, t^=1.25. On s=1: Q(1,t) = (t-0.25)^2+(t-1.25)^2+1,
//     minimal at t=0.75: point (1.5,-0.5,1), Q = 0.25+0.25+1 = 1.5; on t=1: q1 = (1.75,-0.25,1)
//     projects beyond p1: Q = 0.5625+0.0625+1 = 1.625 > 1.5. Answer on edge s=1
//     (a+b+d = 1-1-0.75 < 0).
// Flipping segment 0 (s -> 1-s) maps regions 2->4, 1->5, 8->6; flipping segment 1 (t -> 1-t)
// maps 2->8, 3->7, 4->6. The corner cases 4, 6, 8 are R2a/R2b flipped: same Q, mirrored s, t.
const Vec3 kO(0.0, 0.0, 0.0);
const Vec3 kX(1.0, 0.0, 0.0);
const std::array<RegionCase, 13> kRegionCases{{
    {"R0", kO, kX, {0.25, -1, 1}, {0.75, 1, 1}, 0, 0.5, 0.5, 1.0},
    {"R1", kO, kX, {1.5, -1, 1}, {2.5, 1, 1}, 1, 1.0, 0.3, 1.8},
    {"R3", kO, kX, {1.75, -1.25, 1}, {0.75, -0.25, 1}, 3, 0.75, 1.0, 1.0625},
    {"R5", kO, kX, {-1.5, -1, 1}, {-0.5, 1, 1}, 5, 0.0, 0.7, 1.8},
    {"R7", kO, kX, {0.75, 0.25, 1}, {1.75, 1.25, 1}, 7, 0.75, 0.0, 1.0625},
    {"R2a", kO, kX, {-0.5, -2, 1}, {0.5, -1, 1}, 2, 0.5, 1.0, 2.0},
    {"R2b", kO, kX, {0.75, -1.25, 1}, {1.75, -0.25, 1}, 2, 1.0, 0.75, 1.5},
    {"R4a", kX, kO, {-0.5, -2, 1}, {0.5, -1, 1}, 4, 0.5, 1.0, 2.0},
    {"R4b", kX, kO, {0.75, -1.25, 1}, {1.75, -0.25, 1}, 4, 0.0, 0.75, 1.5},
    {"R8a", kO, kX, {0.5, -1, 1}, {-0.5, -2, 1}, 8, 0.5, 0.0, 2.0},
    {"R8b", kO, kX, {1.75, -0.25, 1}, {0.75, -1.25, 1}, 8, 1.0, 0.25, 1.5},
    {"R6a", kX, kO, {0.5, -1, 1}, {-0.5, -2, 1}, 6, 0.5, 0.0, 2.0},
    {"R6b", kX, kO, {1.75, -0.25, 1}, {0.75, -1.25, 1}, 6, 0.0, 0.25, 1.5},
}};

TEST(SegmentDistance, EveryRegionOfTheParameterPlaneMatchesHandSolution) {
  std::array<int, 9> seen{};
  for (const RegionCase& c : kRegionCases) {
    SCOPED_TRACE(c.name);
    const SegmentDistanceResult r = segmentDistance(c.p0, c.p1, c.q0, c.q1);
    EXPECT_EQ(r.region, c.region);
    EXPECT_FALSE(r.parallel);
    // Exact binary inputs, O(1) values: a few ulp (kTight).
    EXPECT_NEAR(r.s, c.s, kTight);
    EXPECT_NEAR(r.t, c.t, kTight);
    EXPECT_NEAR(r.squaredDistance, c.squaredDistance, kTight);
    EXPECT_NEAR(r.distance, std::sqrt(c.squaredDistance), kTight);
    expectConsistent(r, c.p0, c.p1, c.q0, c.q1);
    if (r.region >= 0) ++seen[static_cast<std::size_t>(r.region)];
  }
  for (int region = 0; region < 9; ++region) EXPECT_GT(seen[static_cast<std::size_t>(region)], 0) << region;
}

TEST(SegmentDistance, RegionCasesAreExactAtFieldCoordinatesAndExtremeScales) {
  // The same cases translated to offshore field coordinates (an exact binary offset of ~2 km) and
  // scaled by 2^-30 and 2^30 (exact): the answer is unchanged (scaled). Tolerance: the coordinates
  // now have ulp 4.5e-13, and the differences p1 - p0, q0 - p0 are exact (Sterbenz), so the error is
  // a few ulp of the local O(1) values; we allow 16 eps relative to the coordinate size for the
  // translated case, 8 eps relative for the scaled ones (scaling by a power of two is exact).
  const Vec3 offset(1000.5, -2000.25, -345.0);
  for (const RegionCase& c : kRegionCases) {
    SCOPED_TRACE(c.name);
    const SegmentDistanceResult r =
        segmentDistance(c.p0 + offset, c.p1 + offset, c.q0 + offset, c.q1 + offset);
    EXPECT_EQ(r.region, c.region);
    EXPECT_NEAR(r.distance, std::sqrt(c.squaredDistance), 16.0 * kEps * 2000.0);
    EXPECT_NEAR(r.s, c.s, 16.0 * kEps * 2000.0);
    EXPECT_NEAR(r.t, c.t, 16.0 * kEps * 2000.0);
    expectConsistent(r, c.p0 + offset, c.p1 + offset, c.q0 + offset, c.q1 + offset);
    for (const double scale : {std::ldexp(1.0, -30), std::ldexp(1.0, 30)}) {
      const SegmentDistanceResult rs =
          segmentDistance(scale * c.p0, scale * c.p1, scale * c.q0, scale * c.q1);
      EXPECT_EQ(rs.region, c.region);
      EXPECT_NEAR(rs.distance / scale, std::sqrt(c.squaredDistance), kTight);
      EXPECT_NEAR(rs.s, c.s, kTight);
      EXPECT_NEAR(rs.t, c.t, kTight);
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Crossing, parallel, nearly parallel and degenerate segments.

TEST(SegmentDistance, CrossingSegmentsHaveZeroDistance) {
  // Diagonals of the square [0,2]^2 meet at (1,1,0), s = t = 1/2. All intermediate values are
  // exact (products of small integers), so the answer is exactly zero.
  const Vec3 p0(0, 0, 0), p1(2, 2, 0), q0(0, 2, 0), q1(2, 0, 0);
  const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
  EXPECT_EQ(r.region, 0);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_EQ(r.s, 0.5);
  EXPECT_EQ(r.t, 0.5);
  EXPECT_EQ(r.closest0, Vec3(1, 1, 0));
  expectConsistent(r, p0, p1, q0, q1);

  // Skew-looking crossing in 3D at a non-dyadic point: X = P(1/3) on segment 0 from (0,0,0) to
  // (3,1,2); segment 1 runs through X along (2,-4,1), from X - 0.5 (2,-4,1) to X + 0.75 (2,-4,1), so
  // it meets segment 0 at s = 1/3, t = 0.4 and the exact distance of the ideal lines is 0.
  const Vec3 a0(0, 0, 0), a1(3, 1, 2);
  const Vec3 x = a0 + (1.0 / 3.0) * (a1 - a0);
  const Vec3 b0 = x - 0.5 * Vec3(2.0, -4.0, 1.0), b1 = x + 0.75 * Vec3(2.0, -4.0, 1.0);
  const SegmentDistanceResult r2 = segmentDistance(a0, a1, b0, b1);
  EXPECT_EQ(r2.region, 0);
  // X, b0, b1 are rounded (1/3 is not a double): the segments are within a few ulp (~1e-15) of
  // intersecting, and the distance is of that order.
  EXPECT_LE(r2.distance, 8.0 * kEps);
  EXPECT_NEAR(r2.s, 1.0 / 3.0, 8.0 * kEps);
  EXPECT_NEAR(r2.t, 0.4, 8.0 * kEps);
}

TEST(SegmentDistance, ParallelOverlappingReturnsMiddleOfOverlap) {
  // Segment 0 covers x in [0,2], segment 1 x in [1,3] at y = 1: overlap [1,2], middle x = 1.5,
  // so s = 0.75, t = 0.25 (t = 0.75 when segment 1 is reversed); distance exactly 1.
  const Vec3 p0(0, 0, 0), p1(2, 0, 0);
  {
    const Vec3 q0(1, 1, 0), q1(3, 1, 0);
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.region, -1);
    EXPECT_EQ(r.distance, 1.0);
    EXPECT_EQ(r.s, 0.75);
    EXPECT_EQ(r.t, 0.25);
    expectConsistent(r, p0, p1, q0, q1);
  }
  {
    const Vec3 q0(3, 1, 0), q1(1, 1, 0);
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.distance, 1.0);
    EXPECT_EQ(r.s, 0.75);
    EXPECT_EQ(r.t, 0.75);
    expectConsistent(r, p0, p1, q0, q1);
  }
  {
    // Segment 1 inside segment 0 (x in [0.5,1]), 1 above it: middle x = 0.75.
    const Vec3 q0(0.5, 0, 1), q1(1.0, 0, 1);
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.distance, 1.0);
    EXPECT_EQ(r.s, 0.375);
    EXPECT_EQ(r.t, 0.5);
  }
  {
    // Collinear overlapping segments: distance exactly 0.
    const Vec3 q0(1, 0, 0), q1(5, 0, 0);
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_EQ(r.s, 0.75);  // overlap [1,2]
    EXPECT_EQ(r.t, 0.125);
  }
}

TEST(SegmentDistance, ParallelDisjointReturnsNearestEndPoints) {
  // Segment 1 one unit above and beyond the end of segment 0: nearest pair p1 = (1,0,0) and
  // the end of segment 1 at (2,1,0): distance sqrt(2). All four orientations, plus segment 1 before
  // segment 0 and end-to-end touching (distance exactly 0).
  const Vec3 p0(0, 0, 0), p1(1, 0, 0);
  struct Case {
    Vec3 q0, q1;
    double s, t, distance;
  };
  const Case cases[] = {
      {{2, 1, 0}, {3, 1, 0}, 1.0, 0.0, std::sqrt(2.0)},
      {{3, 1, 0}, {2, 1, 0}, 1.0, 1.0, std::sqrt(2.0)},
      {{-2, 1, 0}, {-1, 1, 0}, 0.0, 1.0, std::sqrt(2.0)},
      {{-1, 1, 0}, {-2, 1, 0}, 0.0, 0.0, std::sqrt(2.0)},
      {{1, 0, 0}, {2, 0, 0}, 1.0, 0.0, 0.0},
  };
  for (const Case& c : cases) {
    const SegmentDistanceResult r = segmentDistance(p0, p1, c.q0, c.q1);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.s, c.s);
    EXPECT_EQ(r.t, c.t);
    EXPECT_NEAR(r.distance, c.distance, kTight);  // sqrt(2) is correctly rounded: 1 ulp
    expectConsistent(r, p0, p1, c.q0, c.q1);
    // Reversing segment 0 mirrors s (exact for s in {0, 1}).
    const SegmentDistanceResult rr = segmentDistance(p1, p0, c.q0, c.q1);
    EXPECT_EQ(rr.s, 1.0 - c.s);
    EXPECT_NEAR(rr.distance, c.distance, kTight);
  }
}

TEST(SegmentDistance, NearlyParallelAtOneNanoradian) {
  constexpr double kDelta = 1e-9;  // half the lateral drift over the length 2: angle ~1e-9 rad
  // Line 0 is the x axis, line 1 goes through (-1,-delta,h) and (1,delta,h): both pass through x=0
  // at y=0 (the y of the midpoint of segment 1 is exactly -delta + delta = 0), so the common
  // perpendicular is the z axis, s = t = 1/2 and the distance is exactly h. sin^2(angle) = 1e-18
  // is above kParallelTolerance: the nearly parallel branch with the t refinement is used.
  const Vec3 p0(-1, 0, 0), p1(1, 0, 0);
  for (const double h : {1.0, 1e-3, 1e-9, 0.0}) {
    SCOPED_TRACE(h);
    const Vec3 q0(-1, -kDelta, h), q1(1, kDelta, h);
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    // Error bound from the analysis in SegmentDistance.cpp: ~eps * L for h -> 0 and far smaller
    // relative error for h >> angle * L. We ask for 4 ulp of the segment length (2).
    EXPECT_NEAR(r.distance, h, 8.0 * kEps);
    expectConsistent(r, p0, p1, q0, q1);
    EXPECT_EQ(r.region, 0);
    EXPECT_FALSE(r.parallel);
    // s^, t^ have relative errors up to ~eps/angle = 2e-7 (analysis in SegmentDistance.cpp); we
    // allow 1e-6 (observed: 1 ulp).
    EXPECT_NEAR(r.s, 0.5, 1e-6);
    EXPECT_NEAR(r.t, 0.5, 1e-6);
  }
  // Nearly parallel with a lateral gap of 0.5 over 10 m, diverging by 1e-8 at the far end: the
  // lines meet ~5e8 m behind the start, so the closest points are the starts, distance 0.5.
  {
    const Vec3 a0(0, 0, 0), a1(10, 0, 0), b0(0, 0.5, 0), b1(10, 0.5 + 1e-8, 0);
    const SegmentDistanceResult r = segmentDistance(a0, a1, b0, b1);
    EXPECT_EQ(r.s, 0.0);
    EXPECT_EQ(r.t, 0.0);
    EXPECT_EQ(r.distance, 0.5);
  }
  // Nearly parallel, disjoint along the axis: the nearest end points (1,0,0) and (2,1,0).
  {
    const Vec3 a0(0, 0, 0), a1(1, 0, 0), b0(2, 1, 0), b1(3, 1 + kDelta, 0);
    const SegmentDistanceResult r = segmentDistance(a0, a1, b0, b1);
    EXPECT_EQ(r.s, 1.0);
    EXPECT_EQ(r.t, 0.0);
    EXPECT_NEAR(r.distance, std::sqrt(2.0), kTight);
  }
  // Nearly parallel vertical riser-like elements 1 km from the origin of coordinates, 5 m long,
  // 0.6 m apart, angle 1e-9 (segment 1 leans away): the closest points are the start of segment 1
  // and the point of segment 0 at the same height (s = 0.2). The exact distance is the x gap of
  // the rounded inputs, b0.x - a0.x, which is computed exactly (Sterbenz) in the test; it differs
  // from 0.6 by the rounding of 1000.6. Tolerance: a few ulp of 0.6.
  {
    const Vec3 o(1000.0, -700.0, -300.0);
    const Vec3 a0 = o, a1 = o + Vec3(0, 0, 5), b0 = o + Vec3(0.6, 0, 1), b1 = o + Vec3(0.6 + 5e-9, 0, 6);
    const SegmentDistanceResult r = segmentDistance(a0, a1, b0, b1);
    EXPECT_NEAR(r.distance, b0.x() - a0.x(), 4.0 * kEps);
    EXPECT_NEAR(r.s, 0.2, kTight);
    EXPECT_EQ(r.t, 0.0);
    expectConsistent(r, a0, a1, b0, b1);
  }
}

TEST(SegmentDistance, DegenerateSegments) {
  // Point-point: 3-4-5 triangle, exact.
  {
    const Vec3 p(1, 2, 3), q(4, 6, 3);
    const SegmentDistanceResult r = segmentDistance(p, p, q, q);
    EXPECT_TRUE(r.parallel);
    EXPECT_EQ(r.distance, 5.0);
    EXPECT_EQ(r.s, 0.0);
    EXPECT_EQ(r.t, 0.0);
    expectConsistent(r, p, p, q, q);
  }
  // Point-segment: (0.5,1,0) projects to x = 0.5 on the segment (0,0,0)-(2,0,0), t = 0.25, d = 1;
  // (3,1,0) is beyond the end: t = 1, d = sqrt(2); (0.5,0,0) lies on it: d = 0.
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  struct Case {
    Vec3 point;
    double parameter, distance;
  };
  const Case cases[] = {{{0.5, 1, 0}, 0.25, 1.0}, {{3, 1, 0}, 1.0, std::sqrt(2.0)}, {{0.5, 0, 0}, 0.25, 0.0}};
  for (const Case& c : cases) {
    const SegmentDistanceResult r1 = segmentDistance(c.point, c.point, a, b);
    EXPECT_EQ(r1.s, 0.0);
    EXPECT_EQ(r1.t, c.parameter);
    EXPECT_NEAR(r1.distance, c.distance, kTight);
    expectConsistent(r1, c.point, c.point, a, b);
    const SegmentDistanceResult r2 = segmentDistance(a, b, c.point, c.point);
    EXPECT_EQ(r2.s, c.parameter);
    EXPECT_EQ(r2.t, 0.0);
    EXPECT_NEAR(r2.distance, c.distance, kTight);
    expectConsistent(r2, a, b, c.point, c.point);
  }
}

TEST(SegmentDistance, NonFiniteInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Vec3 o(0, 0, 0), x(1, 0, 0);
  EXPECT_THROW(segmentDistance(o, Vec3(nan, 0, 0), o, x), Error);
  EXPECT_THROW(segmentDistance(o, x, Vec3(0, inf, 0), x), Error);
  EXPECT_THROW(segmentDistance(o, x, o, Vec3(0, 0, nan)), Error);
  // Finite but overflowing squared distance.
  EXPECT_THROW(segmentDistance(o, x, Vec3(1e200, 0, 0), Vec3(1e200, 1, 0)), Error);
}

// ------------------------------------------------------------------------------------------------
// Randomised comparison with a brute-force minimiser.

/// Brute-force minimum distance [m]. For fixed s the minimum of the convex Q(s, .) over [0,1] is
/// the clamped projection of P(s) on segment 1 (exact per s); g(s) = min_t Q(s,t) is convex (a
/// partial minimum of a convex function), so a dense grid followed by golden-section search in the
/// bracket of the best grid point finds its minimum to round-off. Done in both directions (over s
/// and over t) and the smallest distance seen is returned: every evaluated value is the distance of
/// an actual pair of points, so the result is never below the true minimum beyond round-off.
double bruteForceDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  auto oneWay = [](const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
    const Vec3 ma = a1 - a0;
    const Vec3 mb = b1 - b0;
    const double c = mb.squaredNorm();
    auto g = [&](double u) {
      const Vec3 p = a0 + u * ma;
      const double v = c > 0.0 ? std::clamp((p - b0).dot(mb) / c, 0.0, 1.0) : 0.0;
      return (p - (b0 + v * mb)).norm();
    };
    constexpr int kGrid = 64;
    double best = std::numeric_limits<double>::infinity();
    int bestIndex = 0;
    for (int i = 0; i <= kGrid; ++i) {
      const double value = g(static_cast<double>(i) / kGrid);
      if (value < best) {
        best = value;
        bestIndex = i;
      }
    }
    double lo = std::max(0, bestIndex - 1) / static_cast<double>(kGrid);
    double hi = std::min(kGrid, bestIndex + 1) / static_cast<double>(kGrid);
    const double invPhi = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = hi - invPhi * (hi - lo);
    double x2 = lo + invPhi * (hi - lo);
    double f1 = g(x1);
    double f2 = g(x2);
    for (int iteration = 0; iteration < 120 && hi - lo > 1e-18; ++iteration) {
      best = std::min({best, f1, f2});
      if (f1 <= f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - invPhi * (hi - lo);
        f1 = g(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + invPhi * (hi - lo);
        f2 = g(x2);
      }
    }
    return std::min({best, f1, f2, g(lo), g(hi)});
  };
  return std::min(oneWay(p0, p1, q0, q1), oneWay(q0, q1, p0, p1));
}

/// Agreement test used by both randomised tests: 1e-10 relative, or 1e-12 absolute for tiny
/// distances. The brute force evaluates distances of actual point pairs with round-off
/// ~eps * |coordinates| (~1e-14 here), far below these tolerances.
void expectMatchesBruteForce(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
  const double reference = bruteForceDistance(p0, p1, q0, q1);
  EXPECT_NEAR(r.distance, reference, std::max(1e-10 * reference, 1e-12))
      << "p0 " << p0.transpose() << " p1 " << p1.transpose() << " q0 " << q0.transpose() << " q1 "
      << q1.transpose() << " region " << r.region;
  expectConsistent(r, p0, p1, q0, q1);
}

TEST(SegmentDistance, RandomPairsMatchBruteForce) {
  // Seeded: a failure prints the pair and can be replayed with the same seed.
  constexpr std::uint64_t kSeed = 20070613;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> exponent(-2.0, 2.0);
  auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  std::array<int, 9> regionCount{};
  constexpr int kPairs = 20000;
  for (int i = 0; i < kPairs; ++i) {
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " pair " + std::to_string(i));
    // Segments of length 10^-2..10^2 around centres within 10 m, so all regions, near-misses and
    // far-apart pairs occur.
    const double scale = std::pow(10.0, exponent(rng));
    const Vec3 centre0 = 10.0 * point(), centre1 = centre0 + scale * 2.0 * point();
    const Vec3 p0 = centre0 + scale * point(), p1 = centre0 + scale * point();
    const Vec3 q0 = centre1 + scale * point(), q1 = centre1 + scale * point();
    expectMatchesBruteForce(p0, p1, q0, q1);
    const int region = segmentDistance(p0, p1, q0, q1).region;
    if (region >= 0) ++regionCount[static_cast<std::size_t>(region)];
    if (HasFailure()) break;
  }
  // Every region must have been exercised many times.
  for (int region = 0; region < 9; ++region)
    EXPECT_GT(regionCount[static_cast<std::size_t>(region)], 100) << region;
}

TEST(SegmentDistance, RandomNearlyParallelPairsMatchBruteForce) {
  // Segment 1 is segment 0 rotated by 10^-14..10^-2 rad about a random axis, rescaled, possibly
  // reversed, shifted along the axis (overlapping or not) and sideways by 10^-9..10^1 times the
  // length. This is the ill-conditioned regime: the tolerance is the same as for random pairs.
  constexpr std::uint64_t kSeed = 345;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  int parallelCount = 0;
  constexpr int kPairs = 5000;
  for (int i = 0; i < kPairs; ++i) {
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " pair " + std::to_string(i));
    const Vec3 p0 = 5.0 * point();
    const Vec3 m0 = point();
    const double angle = std::pow(10.0, -14.0 + 12.0 * uniform(rng));
    const Vec3 axis = m0.cross(point()).normalized();
    Vec3 m1 = Eigen::AngleAxisd(angle, axis) * m0 * (0.2 + 2.0 * uniform(rng));
    if (uniform(rng) < 0.5) m1 = -m1;
    const Vec3 side = m0.cross(point()).normalized() * m0.norm() * std::pow(10.0, -9.0 + 10.0 * uniform(rng));
    const Vec3 q0 = p0 + (3.0 * uniform(rng) - 1.5) * m0 + side;
    const Vec3 p1 = p0 + m0, q1 = q0 + m1;
    expectMatchesBruteForce(p0, p1, q0, q1);
    if (segmentDistance(p0, p1, q0, q1).parallel) ++parallelCount;
    if (HasFailure()) break;
  }
  // Both the parallel treatment and the region algorithm must have been used.
  EXPECT_GT(parallelCount, 0);
  EXPECT_LT(parallelCount, kPairs);
}

TEST(SegmentDistance, SwappingAndReversingSegmentsIsConsistent) {
  // For non-parallel segments the minimiser is unique: swapping the segments swaps s and t and
  // reversing a segment maps its parameter u to 1 - u. Tolerances: the three evaluations round
  // differently; the distance agrees to 1e-14 relative and the parameters to 1e-9 (parameters of
  // a well-separated unique minimum are conditioned by 1/sin^2(angle), here sin^2 > 1e-4).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p0 = point(), p1 = point(), q0 = point(), q1 = point();
    const SegmentDistanceResult r = segmentDistance(p0, p1, q0, q1);
    if (r.parallel) continue;
    const double sin2 =
        (p1 - p0).cross(q1 - q0).squaredNorm() / ((p1 - p0).squaredNorm() * (q1 - q0).squaredNorm());
    if (sin2 < kNearlyParallel) continue;
    const SegmentDistanceResult swapped = segmentDistance(q0, q1, p0, p1);
    const SegmentDistanceResult reversed = segmentDistance(p1, p0, q1, q0);
    EXPECT_NEAR(swapped.distance, r.distance, 1e-14 * std::max(1.0, r.distance));
    EXPECT_NEAR(reversed.distance, r.distance, 1e-14 * std::max(1.0, r.distance));
    EXPECT_NEAR(swapped.s, r.t, 1e-9);
    EXPECT_NEAR(swapped.t, r.s, 1e-9);
    EXPECT_NEAR(reversed.s, 1.0 - r.s, 1e-9);
    EXPECT_NEAR(reversed.t, 1.0 - r.t, 1e-9);
  }
}

}  // namespace
}  // namespace tangle::geometry
