/// @file PrescribedMotionTest.cpp
/// Tabulated end motion (issue 13): the linear table's velocity at a row time is the velocity of the
/// segment that led there (before: the next segment's, and zero at the last row, which made the end
/// force drop at those instants); the cubic table is a clamped spline through the rows.

#include <gtest/gtest.h>

#include "tangle/model/PrescribedMotion.hpp"

namespace tangle::model {
namespace {

model::EndMotionSpec table(bool cubic) {
  model::EndMotionSpec s;
  s.enabled = true;
  s.cubic = cubic;
  s.table = {{0.0, 0.0, 0.0, 0.0}, {1.0, 2.0, 0.0, -1.0}, {3.0, 2.0, 4.0, -1.0}, {4.0, 5.0, 4.0, 0.0}};
  return s;
}

TEST(PrescribedMotionTable, LinearVelocityAtRowTimesIsTheArrivingSegments) {
  const PrescribedMotion m(table(false), 0.0);
  // Row t = 1 closes segment [0, 1] with slope (2, 0, -1).
  EXPECT_TRUE(m.at(1.0).velocity.isApprox(Vec3(2.0, 0.0, -1.0)));
  EXPECT_TRUE(m.at(1.0).displacement.isApprox(Vec3(2.0, 0.0, -1.0)));
  // Row t = 3 closes [1, 3] with slope (0, 2, 0).
  EXPECT_TRUE(m.at(3.0).velocity.isApprox(Vec3(0.0, 2.0, 0.0)));
  // The last row keeps the last segment's velocity (3, 0, 1); after the table the end is held.
  EXPECT_TRUE(m.at(4.0).velocity.isApprox(Vec3(3.0, 0.0, 1.0)));
  EXPECT_TRUE(m.at(4.5).velocity.isZero());
  EXPECT_TRUE(m.at(4.5).displacement.isApprox(Vec3(5.0, 4.0, 0.0)));
  // Consistency with the displacement: over any step ending at a row the mean velocity is the one given.
  const double h = 0.01;
  for (double t : {1.0, 3.0, 4.0}) {
    const Vec3 mean = (m.at(t).displacement - m.at(t - h).displacement) / h;
    EXPECT_LT((mean - m.at(t).velocity).norm(), 1e-9) << "t = " << t;
  }
  EXPECT_TRUE(m.at(2.0).displacement.isApprox(Vec3(2.0, 2.0, -1.0)));
}

TEST(PrescribedMotionTable, CubicPassesThroughRowsWithContinuousVelocity) {
  const PrescribedMotion m(table(true), 0.0);
  const auto& rows = table(true).table;
  for (const auto& r : rows)
    EXPECT_LT((m.at(r[0]).displacement - Vec3(r[1], r[2], r[3])).norm(), 1e-12) << "t = " << r[0];
  // Velocity and acceleration continuous across the inner rows, zero velocity at both ends.
  const double e = 1e-7;
  for (double t : {1.0, 3.0}) {
    EXPECT_LT((m.at(t - e).velocity - m.at(t + e).velocity).norm(), 1e-5) << t;
    EXPECT_LT((m.at(t - e).acceleration - m.at(t + e).acceleration).norm(), 1e-4) << t;
  }
  EXPECT_LT(m.at(e).velocity.norm(), 1e-5);
  EXPECT_LT(m.at(4.0 - e).velocity.norm(), 1e-5);
  // Velocity is the derivative of the displacement (central difference, O(h^2)).
  for (double t : {0.3, 1.7, 2.5, 3.6}) {
    const double h = 1e-5;
    const Vec3 fd = (m.at(t + h).displacement - m.at(t - h).displacement) / (2.0 * h);
    EXPECT_LT((fd - m.at(t).velocity).norm(), 1e-6) << t;
    const Vec3 fa = (m.at(t + h).velocity - m.at(t - h).velocity) / (2.0 * h);
    EXPECT_LT((fa - m.at(t).acceleration).norm(), 1e-5) << t;
  }
}

}  // namespace
}  // namespace tangle::model
