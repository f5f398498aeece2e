/// Tests of the distributed contact formulation (DistributedContact.hpp) and its barrier law
/// (ContactLaw.hpp, BarrierPenalty).
///
/// Sources: the law's own definition (continuity, monotonicity, the barrier's growth); for the integrated
/// force, independent quadratures of the same law over the exact penetration profile of two straight
/// lines: crossing at right angles, the distance from a point of A at offset u to B's axis is
/// sqrt(d^2 + u^2) (d the axes' distance), integrated here by the composite trapezoidal rule on 200 000
/// intervals; lying side by side over a common length L, the force is f(p) L. The implementation finds the
/// contact interval by root finding, cuts it where the penetration passes the law's p0 and p1, and integrates with
/// 4 Gauss points per piece and per pass.

#include <gtest/gtest.h>

#include <cmath>

#include "support/ModelFactory.hpp"
#include "tangle/contact/ContactLaw.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {
namespace {

TEST(BarrierPenalty, IsContinuousMonotonicAndUnboundedAtTheLimit) {
  const BarrierPenalty law = BarrierPenalty::forScale(1e6, 0.2);
  EXPECT_DOUBLE_EQ(law.value(0.0), 0.0);
  EXPECT_DOUBLE_EQ(law.slope(0.0), 0.0);
  // C1 at p0, p1 and the cap: the one-sided differences of value and slope shrink with the step (a jump
  // would not: the difference at h = 1e-10 m is below a fifth of that at 1e-9 m, a continuous function's
  // a tenth).
  for (const double p : {law.depth, law.barrierStart, law.cap()}) {
    const auto jumpValue = [&](double h) { return std::abs(law.value(p + h) - law.value(p - h)); };
    const auto jumpSlope = [&](double h) { return std::abs(law.slope(p + h) - law.slope(p - h)); };
    EXPECT_LT(jumpValue(1e-10), 0.2 * jumpValue(1e-9)) << "at p = " << p;
    EXPECT_LT(jumpSlope(1e-10), 0.2 * jumpSlope(1e-9) + 1e-9 * law.slope(p)) << "at p = " << p;
  }
  // The slope is the derivative of the value, away from the points where the pieces meet.
  for (const double p : {0.5 * law.depth, 0.5 * (law.depth + law.barrierStart), 0.5 * (law.barrierStart + law.limit),
                         0.999 * law.cap(), 1.001 * law.cap()}) {
    const double h = 1e-9 * law.limit;
    const double fd = (law.value(p + h) - law.value(p - h)) / (2.0 * h);
    EXPECT_NEAR(fd, law.slope(p), 1e-5 * law.slope(p)) << "at p = " << p;
  }
  // Monotonic, linear with slope k between p0 and p1.
  double last = 0.0;
  for (int i = 1; i <= 1000; ++i) {
    const double p = law.limit * i / 1000.0;
    EXPECT_GE(law.value(p), last);
    last = law.value(p);
  }
  EXPECT_DOUBLE_EQ(law.slope(0.5 * (law.depth + law.barrierStart)), 1e6);
  EXPECT_NEAR(law.value(law.barrierStart), 1e6 * (law.barrierStart - 0.5 * law.depth), 1e-6);
  // The barrier: at the cap it adds 361 k D (file comment), hundreds of times the linear force there.
  const double linearAtCap = 1e6 * (law.cap() - 0.5 * law.depth);
  EXPECT_NEAR(law.value(law.cap()) - linearAtCap, 361.0 * 1e6 * (law.limit - law.barrierStart), 1e-6 * law.value(law.cap()));
  EXPECT_GT(law.value(law.cap()), 100.0 * linearAtCap);
  EXPECT_TRUE(law.beyondCap(law.cap()));
  EXPECT_FALSE(law.beyondCap(0.9 * law.cap()));
}

/// Two pinned lines of 6 m (12 elements) in a model with the distributed formulation; line A along
/// `dirA` through (0, 0, zA), line B along x through the origin.
struct TwoLines {
  model::Model model;
  model::State state;
  explicit TwoLines(const model::ModelSpec& spec) : model(spec), state(model.initialState()) {}
};

model::ModelSpec twoLinesSpec(const Vec3& dirA, double zA) {
  model::ModelSpec spec;
  spec.sourceFile = "distributed contact (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["c"] = test::cableType("c", 0.1, 20.0, 1e8);
  spec.lines = {test::simpleLine("a", "c", 6.0, 12, model::EndKind::Pinned, Vec3(0, 0, zA) - 3.0 * dirA,
                                 model::EndKind::Pinned, Vec3(0, 0, zA) + 3.0 * dirA),
                test::simpleLine("b", "c", 6.0, 12, model::EndKind::Pinned, Vec3(-3, 0, 0), model::EndKind::Pinned,
                                 Vec3(3, 0, 0))};
  spec.contact.enabled = true;
  spec.contact.excludeConnections = false;
  spec.contact.formulation = model::ContactFormulation::Distributed;
  return spec;
}

/// Normal force on line A [N] (z component of the pair force) at the straight initial state.
double forceOnA(TwoLines& t) {
  LineContact contact(t.model, t.model.spec().contact, 0.01);
  VecX f = VecX::Zero(t.model.dofs().fullDofCount());
  solver::AssemblyRequest request;
  contact.beginStatic(t.state);
  contact.addForces(t.state, request, f, nullptr);
  return contact.pairForce(0, 1).z();
}

TEST(DistributedContact, CrossingForceIsTheIntegralOfTheLawOverThePenetrationProfile) {
  for (const double depthFraction : {0.05, 0.2, 0.4}) {
    const double radii = 0.1;
    const double d = radii * (1.0 - depthFraction);  // axes' distance
    TwoLines t(twoLinesSpec(Vec3(0, 1, 0), d));
    // The crossing lies at the middle node of both lines (x = 0, y = 0): the C1 centrelines of straight
    // lines are the lines themselves.
    LineContact probe(t.model, t.model.spec().contact, 0.01);
    const DistributedContact& dc = *probe.distributed();
    const BarrierPenalty law = dc.law(0, t.model.lines()[1].firstElement);
    const double halfWidth = std::sqrt(radii * radii - d * d);
    const int n = 200000;
    double reference = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double u = -halfWidth + 2.0 * halfWidth * i / n;
      const double w = (i == 0 || i == n) ? 0.5 : 1.0;
      // The force per length acts along the normal from B's axis to the point; its z part (u along y).
      const double dist = std::sqrt(d * d + u * u);
      reference += w * law.value(radii - dist) * d / dist * (2.0 * halfWidth / n);
    }
    const double force = forceOnA(t);
    EXPECT_NEAR(force, reference, 5e-3 * reference) << "penetration " << depthFraction << " of the radii";
  }
}

TEST(DistributedContact, ParallelForceIsTheLawTimesTheCommonLength) {
  const double radii = 0.1, p = 0.1 * radii;
  TwoLines t(twoLinesSpec(Vec3(1, 0, 0), radii - p));
  LineContact probe(t.model, t.model.spec().contact, 0.01);
  const BarrierPenalty law = probe.distributed()->law(0, t.model.lines()[1].firstElement);
  const double force = forceOnA(t);
  // Both lines 6 m long, ends aligned: every point of each lies at the axes' distance from the other.
  EXPECT_NEAR(force, law.value(p) * 6.0, 1e-9 * law.value(p) * 6.0);
}

TEST(DistributedContact, NoForceWhileTheSurfacesAreApart) {
  TwoLines t(twoLinesSpec(Vec3(0, 1, 0), 0.1 + 1e-4));
  EXPECT_EQ(forceOnA(t), 0.0);
}

TEST(DistributedContact, ForceIsContinuousWhereTheOtherLineChangesSection) {
  // Line B (along x) changes from radius 0.05 m to 0.1 m at its middle node, x = 0; line A (radius 0.05 m)
  // crosses it at right angles at x = x0, its axis zA = 0.135 m above B's: 0.035 m clear of the thin
  // section, 0.015 m into the thick one. Both types have the same mass and stiffness, so one contact law
  // acts throughout. Source: the geometry of the shoulder (DistributedContact.hpp, m_shoulders): B's radius
  // runs from 0.05 to 0.1 m over x in [-0.025, 0.025] along the smootherstep S(u) = u^3 (10 - 15 u + 6 u^2),
  // u = (x + 0.025) / 0.05. A point of B at x touches A when r_B(x) + 0.05 > sqrt(zA^2 + (x - x0)^2), i.e.
  // |x - x0| < w(x) = sqrt((r_B(x) + 0.05)^2 - zA^2): contact begins at x0 = min over x of x - w(x), found
  // below on a 1 um grid (-0.0448 m, on the shoulder's upper part at x = 0.018 m; on the thick part alone
  // 0.025 - 0.0654 = -0.0404 m), and from x0 = 0.025 + w = 0.0904 m on A meets only the thick part: the force
  // it has in the middle of an element further on (x0 = 1.25 m; the footprint within one element, as for
  // x0 <= 0.4346 m). In between the force grows continuously (B's radius under A only grows as A moves on);
  // without the shoulder it jumped by the thick part's share where a projection crossed the node. Steps: at
  // most 1/10 of the full force per 0.5 mm of travel (the rise is spread over 135 mm, 270 steps).
  const double zA = 0.135;
  const double reach = std::sqrt(0.15 * 0.15 - zA * zA);
  double onset = 0.025 - reach;
  for (int i = 0; i <= 50000; ++i) {
    const double x = -0.025 + 1e-6 * i, u = (x + 0.025) / 0.05;
    const double rB = 0.05 + 0.05 * u * u * u * (10.0 + u * (6.0 * u - 15.0));
    const double w2 = (rB + 0.05) * (rB + 0.05) - zA * zA;
    if (w2 > 0.0) onset = std::min(onset, x - std::sqrt(w2));
  }
  auto spec = [&](double x0) {
    model::ModelSpec s = twoLinesSpec(Vec3(0, 1, 0), zA);
    s.lineTypes["thick"] = test::cableType("thick", 0.2, 20.0, 1e8);
    s.lines[0].endA.position.x() = x0;
    s.lines[0].endB.position.x() = x0;
    s.lines[1].sections = {{"c", 3.0, 6}, {"thick", 3.0, 6}};
    return s;
  };
  TwoLines thick(spec(1.25));
  const double full = forceOnA(thick);
  ASSERT_GT(full, 0.0);
  double last = 0.0;
  for (int i = 0; i <= 320; ++i) {
    const double x0 = -0.06 + 0.16 * i / 320.0;
    TwoLines t(spec(x0));
    const double force = forceOnA(t);
    if (x0 < onset - 1e-4) {
      EXPECT_EQ(force, 0.0) << "at x0 = " << x0;
    } else if (x0 > onset + 1e-4) {
      EXPECT_GT(force, 0.0) << "at x0 = " << x0;
    }
    if (x0 > 0.025 + reach + 1e-4) {
      EXPECT_NEAR(force, full, 1e-6 * full) << "at x0 = " << x0;
    }
    EXPECT_GE(force, last - 1e-9 * full) << "at x0 = " << x0;
    EXPECT_LT(force - last, 0.1 * full) << "at x0 = " << x0;
    last = force;
  }
}

}  // namespace
}  // namespace tangle::contact
