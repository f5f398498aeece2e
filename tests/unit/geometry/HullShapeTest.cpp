// The signed distances of geometry::HullShape, one test per region of each solid (as GeometricTools' tests
// of DistSegmentSegment have one per region): the exact Euclidean distance outside (to a face, an edge or a
// corner), minus the distance to the nearest face inside, and the outward normal (the distance's gradient,
// checked against central differences where it is smooth). Tolerances near round-off.

#include <gtest/gtest.h>

#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/HullShape.hpp"

namespace tangle::geometry {
namespace {

constexpr double kTol = 1e-12;

void expectGradient(const HullShape& s, const Vec3& p) {
  const double h = 1e-6;
  Vec3 g;
  for (int k = 0; k < 3; ++k) {
    Vec3 d = Vec3::Zero();
    d[k] = h;
    g[k] = (s.distance(p + d).distance - s.distance(p - d).distance) / (2.0 * h);
  }
  EXPECT_LT((g - s.distance(p).normal).norm(), 1e-6) << "at " << p.transpose();
}

TEST(HullShape, BoxFaceEdgeCornerAndInside) {
  const HullShape b = HullShape::box(Vec3(1, 2, 3), Vec3(4, 6, 8));  // spans x -1..3, y -1..5, z -1..7
  // Face region: straight out of the +x face.
  ShapeDistance d = b.distance(Vec3(5, 2, 3));
  EXPECT_NEAR(d.distance, 2.0, kTol);
  EXPECT_LT((d.normal - Vec3::UnitX()).norm(), kTol);
  // Edge region: beyond the edge x = 3, y = 5.
  d = b.distance(Vec3(6, 9, 3));
  EXPECT_NEAR(d.distance, 5.0, kTol);
  EXPECT_LT((d.normal - Vec3(0.6, 0.8, 0)).norm(), kTol);
  // Corner region: beyond (-1, -1, -1).
  d = b.distance(Vec3(-2, -3, -3));
  EXPECT_NEAR(d.distance, 3.0, kTol);
  EXPECT_LT((d.normal - Vec3(-1, -2, -2) / 3.0).norm(), kTol);
  // Inside, nearest the -z face (0.5 deep).
  d = b.distance(Vec3(1, 2, -0.5));
  EXPECT_NEAR(d.distance, -0.5, kTol);
  EXPECT_LT((d.normal + Vec3::UnitZ()).norm(), kTol);
  for (const Vec3& p : {Vec3(5, 2, 3), Vec3(6, 9, 3), Vec3(-2, -3, -3), Vec3(1, 2, -0.5)})
    expectGradient(b, p);
}

TEST(HullShape, CylinderSideRimEndAndInside) {
  const HullShape c = HullShape::cylinder(Vec3(0, 0, 0), Vec3(0, 0, 10), 4.0);  // radius 2
  ShapeDistance d = c.distance(Vec3(5, 0, 5));                                  // beside the side
  EXPECT_NEAR(d.distance, 3.0, kTol);
  EXPECT_LT((d.normal - Vec3::UnitX()).norm(), kTol);
  d = c.distance(Vec3(0, 1, 13));  // above the end face
  EXPECT_NEAR(d.distance, 3.0, kTol);
  EXPECT_LT((d.normal - Vec3::UnitZ()).norm(), kTol);
  d = c.distance(Vec3(0, 5, -4));  // beyond the rim of end A
  EXPECT_NEAR(d.distance, 5.0, kTol);
  EXPECT_LT((d.normal - Vec3(0, 0.6, -0.8)).norm(), kTol);
  d = c.distance(Vec3(1.5, 0, 5));  // inside, nearest the side
  EXPECT_NEAR(d.distance, -0.5, kTol);
  EXPECT_LT((d.normal - Vec3::UnitX()).norm(), kTol);
  d = c.distance(Vec3(0.5, 0, 9.8));  // inside, nearest end B
  EXPECT_NEAR(d.distance, -0.2, kTol);
  EXPECT_LT((d.normal - Vec3::UnitZ()).norm(), kTol);
  for (const Vec3& p : {Vec3(5, 0.3, 5), Vec3(0, 1, 13), Vec3(0, 5, -4), Vec3(1.5, 0.1, 5)})
    expectGradient(c, p);
}

TEST(HullShape, CapsuleAndSphere) {
  const HullShape c = HullShape::capsule(Vec3(0, 0, 0), Vec3(10, 0, 0), 2.0);
  EXPECT_NEAR(c.distance(Vec3(5, 3, 0)).distance, 2.0, kTol);
  EXPECT_NEAR(c.distance(Vec3(13, 0, 4)).distance, 4.0, kTol);  // beyond the cap of end B: |(3, 0, 4)| - 1
  EXPECT_NEAR(c.distance(Vec3(5, 0, 0.25)).distance, -0.75, kTol);
  const HullShape sphere = HullShape::capsule(Vec3(1, 1, 1), Vec3(1, 1, 1), 4.0);
  const ShapeDistance d = sphere.distance(Vec3(1, 4, 5));
  EXPECT_NEAR(d.distance, 3.0, kTol);
  EXPECT_LT((d.normal - Vec3(0, 0.6, 0.8)).norm(), kTol);
  expectGradient(c, Vec3(13, 0.5, 4));
  expectGradient(sphere, Vec3(1, 4, 5));
}

TEST(HullShape, SurfacePointsLieOnTheSurfaceNoFurtherApartThanTheSpacing) {
  for (const HullShape& s :
       {HullShape::box(Vec3(0, 0, 0), Vec3(10, 4, 3)), HullShape::cylinder(Vec3(0, 0, 0), Vec3(0, 5, 5), 6.0),
        HullShape::capsule(Vec3(0, 0, 0), Vec3(7, 0, 0), 3.0)}) {
    const std::vector<Vec3> points = s.surfacePoints(1.0);
    ASSERT_FALSE(points.empty());
    for (const Vec3& p : points) {
      EXPECT_NEAR(s.distance(p).distance, 0.0, 1e-9) << s.describe() << " at " << p.transpose();
      EXPECT_LE((p - s.centre()).norm(), s.reach(s.centre()) + 1e-9);
    }
    // Every point has a neighbour within the spacing (edges, rings and generators are sampled that finely).
    for (const Vec3& p : points) {
      double nearest = 1e30;
      for (const Vec3& q : points)
        if (&q != &p) nearest = std::min(nearest, (q - p).norm());
      EXPECT_LE(nearest, 1.0 + 1e-9) << s.describe();
    }
  }
  // A box: its 8 corners and the inner points of its edges at 1 m: 8 + 4 (9 + 3 + 2) = 64 points.
  EXPECT_EQ(HullShape::box(Vec3(0, 0, 0), Vec3(10, 4, 3)).surfacePoints(1.0).size(), 64u);
}

TEST(HullShape, RefusesDegenerateShapes) {
  EXPECT_THROW(HullShape::box(Vec3(0, 0, 0), Vec3(1, 0, 1)), Error);
  EXPECT_THROW(HullShape::cylinder(Vec3(0, 0, 0), Vec3(0, 0, 0), 1.0), Error);
  EXPECT_THROW(HullShape::capsule(Vec3(0, 0, 0), Vec3(1, 0, 0), -1.0), Error);
  EXPECT_THROW(HullShape::box(Vec3(0, 0, 0), Vec3(1, 1, 1)).surfacePoints(0.0), Error);
}

}  // namespace
}  // namespace tangle::geometry
