// The smooth (C1) centreline of point-to-point contact (SmoothCentreline.hpp): interpolation, C1
// continuity at nodes, exactness for quadratic shapes, the closest-point search and the exact
// derivatives of the distance.
//
// Sources: the three-point difference on non-uniform spacing is exact for quadratics, and a cubic
// Hermite curve with exact end values and tangents reproduces a quadratic exactly; so nodes placed on a
// parabola x(sigma) at their rest arc lengths sigma give c(s) = x(sigma_i + s L_i) to round-off
// (tolerance 1e-12 m on 1 m coordinates). Derivatives: central differences with h = 1e-6 m (truncation
// ~h^2, round-off ~1e-16/h), tolerance 1e-6 of the largest entry.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/contact/SmoothCentreline.hpp"

namespace tangle {
namespace {

/// Two lines of three sections with unequal element lengths (1.0, 0.5, 2.0 m elements).
model::Model twoLines() {
  model::ModelSpec spec;
  spec.sourceFile = "centreline (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["c"] = test::solidRodType("c", 0.1, 2.1e11, 7850.0);  // beams: smooth centreline
  for (const char* name : {"a", "b"}) {
    model::LineSpec l = test::simpleLine(name, "c", 3.0, 3, model::EndKind::Pinned, Vec3(0, 0, 0), model::EndKind::Pinned,
                                         Vec3(8, 0, 0));
    l.sections.push_back({"c", 1.0, 2});
    l.sections.push_back({"c", 4.0, 2});
    spec.lines.push_back(l);
  }
  return model::Model(spec);
}

/// Two beams of 25 m on 5 m elements from x = -12.5 to 12.5 m (pinned ends; the tests place the nodes).
model::Model twoStraightBeams() {
  model::ModelSpec spec;
  spec.sourceFile = "centreline (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["c"] = test::solidRodType("c", 0.1, 2.1e11, 7850.0);
  for (const char* name : {"a", "b"})
    spec.lines.push_back(test::simpleLine(name, "c", 25.0, 5, model::EndKind::Pinned, Vec3(-12.5, 0, 0),
                                          model::EndKind::Pinned, Vec3(12.5, 0, 0)));
  return model::Model(spec);
}

Vec3 parabola(double sigma) { return Vec3(0.9 * sigma, 0.3 + 0.05 * sigma * sigma, -0.02 * sigma * sigma + 0.1 * sigma); }

TEST(SmoothCentreline, ACableKeepsItsPolyline) {
  model::ModelSpec spec;
  spec.sourceFile = "centreline (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["c"] = test::cableType("c", 0.1, 20.0, 1e8);
  spec.lines = {test::simpleLine("a", "c", 3.0, 3, model::EndKind::Pinned, Vec3(0, 0, 0), model::EndKind::Pinned, Vec3(3, 0, 0))};
  const model::Model m(spec);
  EXPECT_FALSE(contact::hasSmoothCentreline(m, 1));
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(3, 1, 0)};
  const contact::CentrelineStencil st = contact::centrelineStencil(m, 1, 0.25);
  EXPECT_LT((st.point(x) - Vec3(1.25, 0.25, 0)).norm(), 1e-15);
  EXPECT_LT((st.tangent(x) - Vec3(1, 1, 0)).norm(), 1e-15);
  EXPECT_EQ(st.secondDerivative(x).norm(), 0.0);
}

TEST(SmoothCentreline, ReproducesAQuadraticShapeWithUnequalElementsAndIsC1AtNodes) {
  const model::Model m = twoLines();
  const model::Line& line = m.lines()[0];
  std::vector<Vec3> x(m.nodeCount(), Vec3::Zero());
  for (int i = 0; i < line.nodeCount; ++i) x[line.firstNode + i] = parabola(line.arcLength[i]);
  // Interior elements only: at the line ends the tangent is the chord (not exact for a parabola).
  for (int e = line.firstElement + 1; e < line.firstElement + line.elementCount - 1; ++e) {
    const int i = e - line.firstElement;
    const double length = line.arcLength[i + 1] - line.arcLength[i];
    for (double s : {0.0, 0.3, 0.5, 1.0}) {
      const contact::CentrelineStencil st = contact::centrelineStencil(m, e, s);
      EXPECT_LT((st.point(x) - parabola(line.arcLength[i] + s * length)).norm(), 1e-12) << "element " << e << " s " << s;
      double sum = 0.0;
      for (double n : st.N) sum += n;
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
  // C1 at every interior node: the tangent per unit rest length is the same from both elements, also
  // for a shape that is not quadratic.
  for (int i = 0; i < line.nodeCount; ++i)
    x[line.firstNode + i] = Vec3(std::cos(line.arcLength[i]), std::sin(1.3 * line.arcLength[i]), 0.1 * i * i);
  for (int e = line.firstElement; e < line.firstElement + line.elementCount - 1; ++e) {
    const double l0 = m.elements()[e].restLength, l1 = m.elements()[e + 1].restLength;
    const contact::CentrelineStencil before = contact::centrelineStencil(m, e, 1.0);
    const contact::CentrelineStencil after = contact::centrelineStencil(m, e + 1, 0.0);
    EXPECT_LT((before.point(x) - after.point(x)).norm(), 1e-14);
    EXPECT_LT((before.tangent(x) / l0 - after.tangent(x) / l1).norm(), 1e-12) << "node after element " << e;
  }
}

TEST(SmoothCentreline, ClosestPointsAreStationaryAndTheDistanceDerivativesAreExact) {
  const model::Model m = twoLines();
  const model::Line& la = m.lines()[0];
  const model::Line& lb = m.lines()[1];
  std::vector<Vec3> x0(m.nodeCount(), Vec3::Zero());
  // A curved along x (bowed in z), B curved crossing it at about 60 deg, 0.05 m below.
  for (int i = 0; i < la.nodeCount; ++i) {
    const double s = la.arcLength[i] - 4.0;
    x0[la.firstNode + i] = Vec3(s, 0.02 * s * s, 0.3 - 0.03 * s * s);
  }
  const Vec3 dir(std::cos(1.05), std::sin(1.05), 0.0);
  for (int i = 0; i < lb.nodeCount; ++i) {
    const double s = lb.arcLength[i] - 4.3;
    x0[lb.firstNode + i] = s * dir + Vec3(0.1, 0.0, 0.25 + 0.04 * s * s);
  }
  // The pair near the crossing: search every pair, keep the smallest distance with free parameters.
  auto solve = [&](const std::vector<Vec3>& x) {
    contact::CentrelineDistance best;
    best.distance = 1e300;
    for (int ea = la.firstElement; ea < la.firstElement + la.elementCount; ++ea)
      for (int eb = lb.firstElement; eb < lb.firstElement + lb.elementCount; ++eb) {
        const contact::CentrelineDistance d = contact::centrelineDistance(m, x, ea, eb, 0.5, 0.5);
        if (d.sFree && d.tFree && d.distance < best.distance) best = d;
      }
    return best;
  };
  const contact::CentrelineDistance d = solve(x0);
  ASSERT_LT(d.distance, 1.0);
  // Stationary: the separation is normal to both tangents.
  const Vec3 u = d.pointA - d.pointB;
  EXPECT_LT(std::abs(u.normalized().dot(d.a.tangent(x0).normalized())), 1e-10);
  EXPECT_LT(std::abs(u.normalized().dot(d.b.tangent(x0).normalized())), 1e-10);

  const contact::CentrelineKinematics k = contact::centrelineKinematics(x0, d, 1.0, true);
  auto elementOf = [&](const contact::CentrelineStencil& st) {
    for (int e = 0; e < static_cast<int>(m.elements().size()); ++e)
      if (m.elements()[e].node1 == st.node[1] && m.elements()[e].node2 == st.node[2]) return e;
    return -1;
  };
  const int ea = elementOf(d.a), eb = elementOf(d.b);
  const double h = 1e-6;
  double worstGradient = 0.0, worstHessian = 0.0;
  for (int slot = 0; slot < 8; ++slot)
    for (int c = 0; c < 3; ++c) {
      std::vector<Vec3> xp = x0, xm = x0;
      xp[k.node[slot]][c] += h;
      xm[k.node[slot]][c] -= h;
      // Re-solve from the converged parameters on the same element pair.
      const auto kp = contact::centrelineKinematics(xp, contact::centrelineDistance(m, xp, ea, eb, d.s, d.t), 1.0, false);
      const auto km = contact::centrelineKinematics(xm, contact::centrelineDistance(m, xm, ea, eb, d.s, d.t), 1.0, false);
      // Several slots can hold the same node (none here: the pair is far from the line ends and the
      // lines are different), so a slot's derivative is the node's.
      worstGradient = std::max(worstGradient, std::abs((kp.distance - km.distance) / (2 * h) - k.gradient[3 * slot + c]));
      // Hessian column: derivative of the node-summed gradient.
      for (int r = 0; r < 8; ++r) {
        const Vec3 fd = (kp.gradient.segment<3>(3 * r) - km.gradient.segment<3>(3 * r)) / (2 * h);
        const Vec3 an = k.hessian.block<3, 1>(3 * r, 3 * slot + c);
        worstHessian = std::max(worstHessian, (fd - an).cwiseAbs().maxCoeff());
      }
    }
  EXPECT_LT(worstGradient, 1e-8);
  EXPECT_LT(worstHessian, 1e-6 * k.hessian.cwiseAbs().maxCoeff()) << "largest entry " << k.hessian.cwiseAbs().maxCoeff();
}

// The bounds that let the contact's step limit skip far pairs (LineContact::beyondReach): over the whole
// search range of every piece (s in [0, 1] widened by kParameterOverlap at interior nodes), for randomly
// kinked nodes on unequal elements, the curve's distance from its chord stays within
// searchRangeDeviationBound and sum_k |N_k| within centrelineWeightBound. Both are bounds, not estimates:
// checked at 441 points per piece without tolerance beyond round-off (1e-12).
TEST(SmoothCentreline, NearlyParallelPiecesConvergeToTheValleyFloorNearTheStart) {
  // Two beams side by side: a straight along x, b bent towards it, y_b = 0.3 - 0.002 (x - 0.7)^2, both on
  // 5 m elements from x = -12.5 m. Along the valley (s and t together) the distance falls away from
  // x = 0.7 m: V's Hessian is indefinite, the search's non-convex branch. Its answer is the valley's floor
  // near the start, where the gradient across the valley (along the Hessian's eigenvector of the largest
  // eigenvalue, s and t nearly opposite) vanishes: the distance there is y_b(x), to 1e-4 m along this
  // valley's shallow slope. Tolerance: 1e-9 of |u| |c'| (round-off of 1e-13 on coordinates of 10 m, relative
  // to 1.5). (The former step, scaled by each parameter's |c'|^2 alone, overshot the valley twofold and
  // bounced between its walls.)
  const model::Model m = twoStraightBeams();
  const model::Line& la = m.lines()[0];
  const model::Line& lb = m.lines()[1];
  std::vector<Vec3> x(m.nodeCount(), Vec3::Zero());
  const auto yb = [](double at) { return 0.3 - 0.002 * (at - 0.7) * (at - 0.7); };
  for (int i = 0; i < la.nodeCount; ++i) {
    const double at = -12.5 + 5.0 * i;
    x[la.firstNode + i] = Vec3(at, 0.0, 0.0);
    x[lb.firstNode + i] = Vec3(at, yb(at), 0.0);
  }
  const int ea = la.firstElement + 2, eb = lb.firstElement + 2;  // x from -2.5 to 2.5 m (interior)
  for (const auto& [s0, t0] : std::vector<std::pair<double, double>>{{0.4, 0.9}, {0.9, 0.4}, {0.2, 0.3}}) {
    const contact::CentrelineDistance d = contact::centrelineDistance(m, x, ea, eb, s0, t0);
    const Vec3 u = d.pointA - d.pointB;
    const Vec3 ca = d.a.tangent(x), cb = d.b.tangent(x);
    Eigen::Matrix2d h;  // V's Hessian in (s, t)
    h << ca.dot(ca) + u.dot(d.a.secondDerivative(x)), -ca.dot(cb), -ca.dot(cb),
        cb.dot(cb) - u.dot(d.b.secondDerivative(x));
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(h);
    ASSERT_LT(eigen.eigenvalues()(0), 0.0);                      // the indefinite case
    const Eigen::Vector2d across = eigen.eigenvectors().col(1);  // the largest eigenvalue's
    EXPECT_LT(std::abs(across(0) * u.dot(ca) - across(1) * u.dot(cb)), 1e-9 * u.norm() * ca.norm())
        << "start " << s0 << ", " << t0;
    EXPECT_TRUE(d.sFree && d.tFree);
    EXPECT_LT(std::abs(0.5 * (d.s + d.t) - 0.5 * (s0 + t0)), 0.1);  // near the start along the valley
    EXPECT_NEAR(d.distance, yb(d.pointA.x()), 1e-4);
  }
}

// centrelineMinimum: the least distance of two nearly parallel pieces over their whole search ranges. A is
// straight along x, B's nodes lie on y = f(x) (z = 0), both on 5 m elements from x = -12.5 m; the pieces
// from x = -2.5 to 2.5 m (interior, so both ranges are [-0.05, 1.05]). B's nodes are evenly spaced in x, so
// its Catmull-Rom piece has x linear in t and x_B(t) runs over A's range: every point of B's piece has its
// foot on A's (straight) piece, and the least distance is min over t of |y_B(t)|, found by a scan of 220 001
// points of B's piece (its error, y'' (dt / 2)^2 / 2 < 1e-11 m here, is below the tolerance). Tolerance
// 1e-9 m: Brent's method on the valley's floor to 1e-9 in s (5e-9 m along the pieces) moves the distance by
// its square at an interior minimum, and not at all at a range's end. Three shapes: bent towards A (the
// minimum at the range's end, where centrelineDistance stops on the valley's floor near its start, 2.5 m
// away); a cubic whose piece dips inside the range; and straight and parallel (flat along the valley: any
// point of the overlap is a minimum).
TEST(SmoothCentreline, CentrelineMinimumIsTheLeastDistanceOverTheWholeRanges) {
  const model::Model m = twoStraightBeams();
  const model::Line& la = m.lines()[0];
  const model::Line& lb = m.lines()[1];
  const int ea = la.firstElement + 2, eb = lb.firstElement + 2;
  const std::vector<std::function<double(double)>> shapes{
      [](double x) { return 0.3 - 0.002 * (x - 0.7) * (x - 0.7); },
      [](double x) {
        return 0.3 + 0.004 * (x - 0.4) * (x - 0.4) - 0.0012 * (x - 0.4) * (x - 0.4) * (x - 0.4);
      },
      [](double) { return 0.3; }};
  for (std::size_t shape = 0; shape < shapes.size(); ++shape) {
    std::vector<Vec3> x(m.nodeCount(), Vec3::Zero());
    for (int i = 0; i < la.nodeCount; ++i) {
      const double at = -12.5 + 5.0 * i;
      x[la.firstNode + i] = Vec3(at, 0.0, 0.0);
      x[lb.firstNode + i] = Vec3(at, shapes[shape](at), 0.0);
    }
    const contact::ElementCurve curveB = contact::elementCurve(m, eb);
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 220000; ++k) {
      const Vec3 p = contact::centrelinePoint(curveB, -0.05 + 1.1 * k / 220000.0, x);
      ASSERT_GE(p.x(), -2.75 - 1e-12);
      ASSERT_LE(p.x(), 2.75 + 1e-12);
      least = std::min(least, std::hypot(p.y(), p.z()));
    }
    for (const auto& [s0, t0] :
         std::vector<std::pair<double, double>>{{0.4, 0.9}, {0.9, 0.4}, {0.2, 0.3}, {1.0, 0.0}, {0.5, 0.5}}) {
      const contact::CentrelineDistance d = contact::centrelineMinimum(m, x, ea, eb, s0, t0);
      EXPECT_NEAR(d.distance, least, 1e-9) << "shape " << shape << ", start " << s0 << ", " << t0;
      EXPECT_NEAR(d.distance, (d.pointA - d.pointB).norm(), 1e-15);
      EXPECT_GE(d.s, -0.05);
      EXPECT_LE(d.s, 1.05);
      EXPECT_GE(d.t, -0.05);
      EXPECT_LE(d.t, 1.05);
    }
  }
}

TEST(SmoothCentreline, TheCurveStaysWithinItsBoundsOverTheWholeSearchRange) {
  const model::Model m = twoLines();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  std::vector<Vec3> x(m.nodeCount(), Vec3::Zero());
  double largestRatio = 0.0;  // deviation / bound: the bound is not far from tight where it matters
  for (int trial = 0; trial < 20; ++trial) {
    for (const model::Line& line : m.lines())
      for (int i = 0; i < line.nodeCount; ++i)
        x[line.firstNode + i] =
            Vec3(line.arcLength[i], 0.0, 0.0) + Vec3(jitter(rng), jitter(rng), jitter(rng));
    for (int e = 0; e < static_cast<int>(m.elements().size()); ++e) {
      const contact::ElementCurve c = contact::elementCurve(m, e);
      ASSERT_TRUE(c.smooth);
      const double deviation = contact::searchRangeDeviationBound(c, x);
      const double weights = contact::centrelineWeightBound(c);
      const Vec3 &x1 = x[c.node[1]], &x2 = x[c.node[2]];
      for (int k = 0; k <= 440; ++k) {
        const double s = -contact::kParameterOverlap + (1.0 + 2.0 * contact::kParameterOverlap) * k / 440.0;
        const std::array<double, 4> n = contact::centrelineWeights(c, s);
        const Vec3 p = contact::combineNodes(c.node, n, x);
        // Distance from p to the chord (the segment x1 x2).
        const double along = std::clamp((p - x1).dot(x2 - x1) / (x2 - x1).squaredNorm(), 0.0, 1.0);
        const double away = (p - (x1 + along * (x2 - x1))).norm();
        EXPECT_LE(away, deviation + 1e-12) << "element " << e << " s " << s;
        largestRatio = std::max(largestRatio, away / deviation);
        EXPECT_LE(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]) + std::abs(n[3]), weights + 1e-12)
            << "element " << e << " s " << s;
      }
    }
  }
  RecordProperty("largest_deviation_over_bound", std::to_string(largestRatio));
  EXPECT_GT(largestRatio, 0.3);  // a bound 3 times the worst case would skip few pairs
}

}  // namespace
}  // namespace tangle
