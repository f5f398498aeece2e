/// @file ElasticCatenaryTest.cpp
/// Tests of the analytic elastic catenary and of the initial-shape generator.
/// References: Jonkman (2007) NREL/TP-500-41958 (elastic catenary with a frictionless seabed),
/// Irvine (1981) "Cable Structures" (inextensible catenary relations), and an independent RK4
/// integration of the cable equilibrium ODE.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tangle/core/Error.hpp"
#include "tangle/catenary/ElasticCatenary.hpp"

namespace tangle::catenary {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// End-B position recomputed from (H, V) with the textbook Jonkman (2007) equations, written in the
/// logarithmic form ln(a + sqrt(1 + a^2)) rather than through the solver's cancellation-free forms,
/// so that it is an independent evaluation of the equations.
std::array<double, 2> jonkmanEnd(const CatenaryInput& in, double h, double v) {
  const double w = in.weight;
  const double length = in.length;
  const double c = std::isinf(in.axialStiffness) ? 0.0 : 1.0 / in.axialStiffness;
  const auto lnRoot = [](double a) { return std::log(a + std::sqrt(1.0 + a * a)); };
  const double vb = v - w * length;
  if (vb >= 0.0) {  // fully suspended
    const double x = h / w * (lnRoot(v / h) - lnRoot(vb / h)) + h * length * c;
    const double z = h / w * (std::sqrt(1.0 + (v / h) * (v / h)) - std::sqrt(1.0 + (vb / h) * (vb / h))) +
                     c * (v * length - w * length * length / 2.0);
    return {x, z};
  }
  const double lb = length - v / w;  // grounded portion, CB = 0
  const double x = lb + h / w * lnRoot(v / h) + h * length * c;
  const double z = h / w * (std::sqrt(1.0 + (v / h) * (v / h)) - 1.0) + v * v * c / (2.0 * w);
  return {x, z};
}

/// Cable equilibrium ODE integrated with RK4 from the fairlead (s = L) down to the touchdown
/// (s = L - V/w, or the anchor if V >= wL), then along the frictionless seabed at constant tension
/// H. State (x, z, Tz): dTz/ds = w, d(x, z)/ds = (H, Tz)/T (1 + T/EA). Returns the anchor position
/// reached from the fairlead at (X, Z), should be (0, 0), and the touchdown distance.
struct ShootingResult {
  double xAnchor = 0.0;
  double zAnchor = 0.0;    // height where the line becomes horizontal (touchdown) or of the anchor
  double touchdown = 0.0;  // x where the line becomes horizontal (touchdown) or of the anchor
};

ShootingResult shoot(const CatenaryInput& in, double h, double v, int steps) {
  const double w = in.weight;
  const double ea = in.axialStiffness;
  const double sEnd = std::max(0.0, in.length - v / w);
  const double ds = -(in.length - sEnd) / steps;  // integrate downward in s
  const auto rhs = [&](const std::array<double, 3>& y) -> std::array<double, 3> {
    const double t = std::hypot(h, y[2]);
    const double stretch = 1.0 + t / ea;
    return {h / t * stretch, y[2] / t * stretch, w};
  };
  std::array<double, 3> y{in.span, in.height, v};
  for (int i = 0; i < steps; ++i) {
    std::array<double, 3> k1 = rhs(y), k2, k3, k4, tmp;
    for (int j = 0; j < 3; ++j) tmp[j] = y[j] + 0.5 * ds * k1[j];
    k2 = rhs(tmp);
    for (int j = 0; j < 3; ++j) tmp[j] = y[j] + 0.5 * ds * k2[j];
    k3 = rhs(tmp);
    for (int j = 0; j < 3; ++j) tmp[j] = y[j] + ds * k3[j];
    k4 = rhs(tmp);
    for (int j = 0; j < 3; ++j) y[j] += ds / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  const double seabed = sEnd * (1.0 + h / ea);  // grounded part, tension H
  return {y[0] - seabed, y[1], y[0]};
}

/// Solves the shooting problem (anchor reached at (0, 0)) for (H, V) by Newton with a central
/// finite-difference Jacobian, starting from a given guess.
std::array<double, 2> solveByShooting(const CatenaryInput& in, double h, double v) {
  constexpr int kSteps = 4000;
  for (int it = 0; it < 50; ++it) {
    const ShootingResult r = shoot(in, h, v, kSteps);
    if (std::hypot(r.xAnchor, r.zAnchor) < 1e-10 * in.length) break;
    const double dh = 1e-6 * h;
    const double dv = 1e-6 * std::abs(v) + 1e-6 * in.weight * in.length;
    const ShootingResult hp = shoot(in, h + dh, v, kSteps), hm = shoot(in, h - dh, v, kSteps);
    const ShootingResult vp = shoot(in, h, v + dv, kSteps), vm = shoot(in, h, v - dv, kSteps);
    const double j11 = (hp.xAnchor - hm.xAnchor) / (2 * dh), j12 = (vp.xAnchor - vm.xAnchor) / (2 * dv);
    const double j21 = (hp.zAnchor - hm.zAnchor) / (2 * dh), j22 = (vp.zAnchor - vm.zAnchor) / (2 * dv);
    const double det = j11 * j22 - j12 * j21;
    h -= (j22 * r.xAnchor - j12 * r.zAnchor) / det;
    v -= (-j21 * r.xAnchor + j11 * r.zAnchor) / det;
  }
  return {h, v};
}

/// Representative cases: grounded chain, steep short line, taut-ish, anchor uplift, near slack.
std::vector<CatenaryInput> representativeCases() {
  return {
      {950.0, 330.0, 1130.0, 1100.0, 5.8e8},   // benchmark-like chain, grounded
      {850.0, 330.0, 1130.0, 1100.0, 5.8e8},   // long grounded portion
      {1100.0, 330.0, 1130.0, 1100.0, 5.8e8},  // chord 1148 m > L: taut, stretched, suspended
      {300.0, 500.0, 600.0, 500.0, 1e9},       // steep, fully suspended with anchor uplift
      {200.5, 100.0, 300.0, 2000.0, 2e8},      // just past the slack limit X = L - Ls = 200.05 m: small H
      {1000.0, 1.0, 1000.5, 50.0, 1e6},        // very shallow, stretchy
      {1.0, 99.0, 99.5, 100.0, 1e9},           // almost vertical
  };
}

// ---------------------------------------------------------------------------------------------
// Single segment: equations, references, invariants.
// ---------------------------------------------------------------------------------------------

// Source: Jonkman (2007) equations. The solver's (H, V) must reproduce X and Z through the
// textbook form of the equations; tolerance 1e-9 relative as specified (Newton converges to ~1e-13).
TEST(ElasticCatenary, AnchoredSolutionSatisfiesJonkmanEquations) {
  for (const CatenaryInput& in : representativeCases()) {
    const CatenarySolution sol = solveAnchoredCatenary(in);
    ASSERT_GT(sol.horizontalTension, 0.0) << "X = " << in.span;
    const auto [x, z] = jonkmanEnd(in, sol.horizontalTension, sol.verticalTension);
    EXPECT_NEAR(x, in.span, 1e-9 * in.span) << "X = " << in.span;
    EXPECT_NEAR(z, in.height, 1e-9 * in.height) << "X = " << in.span;
    // The profile function ends at the fairlead too (same tolerance).
    const CatenaryPoint end = sol.position(in.length);
    EXPECT_NEAR(end.x, in.span, 1e-9 * in.span);
    EXPECT_NEAR(end.z, in.height, 1e-9 * in.height);
    const CatenaryPoint start = sol.position(0.0);
    EXPECT_EQ(start.x, 0.0);
    EXPECT_EQ(start.z, 0.0);
    EXPECT_LE(sol.iterations, 60);
  }
}

// Source: Jonkman (2007) fully suspended equations, for a free two-point line with end B below,
// level with and above end A. Tolerance 1e-9 relative as specified.
TEST(ElasticCatenary, SuspendedSolutionSatisfiesJonkmanEquations) {
  const std::vector<CatenaryInput> cases = {
      {400.0, -150.0, 600.0, 800.0, 3e8}, {400.0, 0.0, 600.0, 800.0, 3e8},
      {400.0, 150.0, 600.0, 800.0, 3e8},  {400.0, 150.0, 420.0, 800.0, 3e8},
      {10.0, -20.0, 600.0, 800.0, 3e8},   {500.0, 100.0, 450.0, 800.0, 3e6}};
  for (const CatenaryInput& in : cases) {
    const CatenarySolution sol = solveSuspendedCatenary(in);
    EXPECT_EQ(sol.regime, CatenaryRegime::Suspended);
    // jonkmanEnd's suspended branch applies only for V >= wL; write the equations directly here.
    const double h = sol.horizontalTension, v = sol.verticalTension, w = in.weight, l = in.length;
    const double va = v - w * l;
    const auto lnRoot = [](double a) { return std::log(a + std::sqrt(1.0 + a * a)); };
    const double x = h / w * (lnRoot(v / h) - lnRoot(va / h)) + h * l / in.axialStiffness;
    const double z = h / w * (std::sqrt(1 + v * v / (h * h)) - std::sqrt(1 + va * va / (h * h))) +
                     (v * l - w * l * l / 2) / in.axialStiffness;
    EXPECT_NEAR(x, in.span, 1e-9 * in.span) << "Z = " << in.height << " L = " << l;
    EXPECT_NEAR(z, in.height, 1e-9 * std::max(std::abs(in.height), in.span)) << "Z = " << in.height;
    EXPECT_GT(h, 0.0);
  }
}

// Source: Irvine (1981), classic inextensible catenary touching down horizontally: with a = H/w, the
// suspended length is Ls = sqrt(Z (Z + 2a)) and X = L - Ls + a acosh(1 + Z/a). With EA = infinity
// the elastic equations reduce to these exactly, so the tolerance is round-off (1e-10 relative).
TEST(ElasticCatenary, InextensibleGroundedMatchesClassicCatenary) {
  const CatenaryInput in{950.0, 330.0, 1130.0, 1100.0, kInf};
  const CatenarySolution sol = solveAnchoredCatenary(in);
  ASSERT_EQ(sol.regime, CatenaryRegime::Grounded);
  const double a = sol.horizontalTension / in.weight;
  const double suspended = std::sqrt(in.height * (in.height + 2.0 * a));
  EXPECT_NEAR(sol.verticalTension / in.weight, suspended, 1e-10 * in.length);
  EXPECT_NEAR(in.length - suspended + a * std::acosh(1.0 + in.height / a), in.span, 1e-10 * in.span);
  EXPECT_NEAR(sol.groundedLength, in.length - suspended, 1e-10 * in.length);
  EXPECT_NEAR(sol.touchdownDistance, in.length - suspended, 1e-10 * in.length);
  // Classic: T_fairlead = H + w Z for an inextensible catenary.
  EXPECT_NEAR(sol.fairleadTension, sol.horizontalTension + in.weight * in.height,
              1e-10 * sol.fairleadTension);

  // EA -> large converges to it: the elastic terms are O(T L / EA) ~ 6e5 * 1e3 / 1e14 = 6e-6 m on
  // lengths of 1e3 m, so H and V agree to ~1e-8 relative; 1e-6 leaves margin for conditioning.
  CatenaryInput stiff = in;
  stiff.axialStiffness = 1e14;
  const CatenarySolution near = solveAnchoredCatenary(stiff);
  EXPECT_NEAR(near.horizontalTension, sol.horizontalTension, 1e-6 * sol.horizontalTension);
  EXPECT_NEAR(near.verticalTension, sol.verticalTension, 1e-6 * sol.verticalTension);
}

// Source: Irvine (1981), classic two-point inextensible catenary: sqrt(L^2 - Z^2) = 2a sinh(X / 2a).
// Exact for EA = infinity; tolerance round-off (1e-10 relative).
TEST(ElasticCatenary, InextensibleSuspendedMatchesClassicCatenary) {
  for (double z : {-120.0, 0.0, 80.0}) {
    const CatenaryInput in{300.0, z, 400.0, 600.0, kInf};
    const CatenarySolution sol = solveSuspendedCatenary(in);
    const double a = sol.horizontalTension / in.weight;
    EXPECT_NEAR(std::sqrt(in.length * in.length - z * z), 2.0 * a * std::sinh(in.span / (2.0 * a)),
                1e-10 * in.length)
        << "Z = " << z;
    // The lowest point (s0 = L - V/w) is where the tangent is horizontal: z(s0) is the minimum.
    const double s0 = in.length - sol.verticalTension / in.weight;
    if (s0 > 0.0 && s0 < in.length) {
      const double zMin = sol.position(s0).z;
      for (double s = 0.0; s <= in.length; s += 5.0) EXPECT_GE(sol.position(s).z, zMin - 1e-9);
    }
  }
}

// Source: independent numerical solution, RK4 integration of the cable equilibrium ODE (4000
// steps, truncation error ~(ds/a)^4 ~ 1e-11) with shooting on (H, V) by finite-difference Newton,
// started 5% away from the analytic solution. Tolerance 1e-7 relative: the shooting stops at
// residual 1e-10 L and the central-difference Jacobian only affects convergence, not the root.
TEST(ElasticCatenary, AgreesWithShootingIntegrationOfTheCableOde) {
  const std::vector<CatenaryInput> cases = {
      {950.0, 330.0, 1130.0, 1100.0, 5.8e8},  // grounded
      {300.0, 500.0, 600.0, 500.0, 1e9},      // suspended with anchor uplift
      {1000.0, 1.0, 1000.5, 50.0, 1e6},       // shallow, stretchy
  };
  for (const CatenaryInput& in : cases) {
    const CatenarySolution sol = solveAnchoredCatenary(in);
    const auto [h, v] = solveByShooting(in, 1.05 * sol.horizontalTension, 0.95 * sol.verticalTension);
    EXPECT_NEAR(h, sol.horizontalTension, 1e-7 * sol.horizontalTension) << "X = " << in.span;
    EXPECT_NEAR(v, sol.verticalTension, 1e-7 * sol.verticalTension) << "X = " << in.span;
    if (sol.regime == CatenaryRegime::Grounded) {
      // The shooting reached the anchor at x = 0, so its x at touchdown is the touchdown distance.
      EXPECT_NEAR(shoot(in, h, v, 4000).touchdown, sol.touchdownDistance, 1e-7 * in.span)
          << "X = " << in.span;
    }
  }
}

// Source: the project's benchmark mooring (345 m water depth, anchor at ~1000 m radius), as a
// representative single segment of 76 mm studless chain: w = 1100 N/m, EA = 5.8e8 N, L = 1130 m,
// fairlead 15 m below the surface (Z = 330 m), X chosen for a 55 t (539.4 kN) fairlead tension.
// Invariants are exact identities of the solution (tolerance round-off, 1e-12 relative).
TEST(ElasticCatenary, BenchmarkChainLineInvariants) {
  const double target = 55.0e3 * 9.80665;
  CatenaryInput in{0.0, 330.0, 1130.0, 1100.0, 5.8e8};
  double lo = 800.0, hi = 1100.0;  // fairlead tension increases with X
  for (int i = 0; i < 100; ++i) {
    in.span = 0.5 * (lo + hi);
    (solveAnchoredCatenary(in).fairleadTension < target ? lo : hi) = in.span;
  }
  const CatenarySolution sol = solveAnchoredCatenary(in);
  EXPECT_NEAR(sol.fairleadTension, target, 1e-6 * target);
  // Sanity: the span is that of a ~1000 m anchor radius with a fairlead at a few tens of m radius.
  EXPECT_GT(in.span, 900.0);
  EXPECT_LT(in.span, 1000.0);
  EXPECT_EQ(sol.regime, CatenaryRegime::Grounded);
  EXPECT_GT(sol.groundedLength, 0.0);
  const double h = sol.horizontalTension, v = sol.verticalTension;
  EXPECT_NEAR(sol.fairleadTension * sol.fairleadTension, h * h + v * v,
              1e-12 * sol.fairleadTension * sol.fairleadTension);
  EXPECT_NEAR(v, in.weight * (in.length - sol.groundedLength), 1e-12 * v);
  EXPECT_EQ(sol.anchorTension, h);  // frictionless seabed: anchor tension horizontal, = H
  EXPECT_NEAR(sol.touchdownDistance, sol.groundedLength * (1.0 + h / in.axialStiffness), 1e-12 * in.span);
  // Effective tension at the fairlead exceeds H by w Z plus a small elastic term (< 1%).
  EXPECT_NEAR(sol.fairleadTension - h, in.weight * in.height, 0.01 * in.weight * in.height);
  EXPECT_NEAR(sol.tension(in.length), sol.fairleadTension, 1e-9 * sol.fairleadTension);
  EXPECT_EQ(sol.tension(0.5 * sol.groundedLength), h);
  // Grounded points lie on the seabed, suspended ones above it and below the fairlead.
  EXPECT_EQ(sol.position(0.5 * sol.groundedLength).z, 0.0);
  for (double s = sol.groundedLength + 1.0; s < in.length; s += 10.0) {
    const CatenaryPoint p = sol.position(s);
    EXPECT_GT(p.z, 0.0);
    EXPECT_LT(p.z, in.height);
  }
}

// Source: the cable ODE itself. The profile must satisfy |dp/ds| = 1 + T/EA (stretched length per
// unstretched length) and dz/dx = Tz/H (tangent along the tension). Central differences with
// ds = 1e-3 m: truncation ~ds^2 |p'''| ~ 1e-6 / a, tolerance 1e-6 relative.
TEST(ElasticCatenary, ProfileIsConsistentWithTensionAndStretch) {
  for (const CatenaryInput& in : representativeCases()) {
    const CatenarySolution sol = solveAnchoredCatenary(in);
    const double ds = 1e-3;
    for (int i = 1; i < 20; ++i) {
      const double s = in.length * i / 20.0;
      if (std::abs(s - sol.groundedLength) < 10 * ds || s + ds > in.length) continue;
      const CatenaryPoint p = sol.position(s + ds), m = sol.position(s - ds);
      const double dx = (p.x - m.x) / (2 * ds), dz = (p.z - m.z) / (2 * ds);
      const double t = sol.tension(s);
      EXPECT_NEAR(std::hypot(dx, dz), 1.0 + t / in.axialStiffness, 1e-6) << "X = " << in.span << " s = " << s;
      const double tz = s <= sol.groundedLength ? 0.0 : sol.verticalTension - in.weight * (in.length - s);
      EXPECT_NEAR(dz * sol.horizontalTension, dx * tz, 1e-6 * t) << "X = " << in.span << " s = " << s;
    }
  }
}

// Slack line (L > X + Z): no tension can be carried horizontally, H = 0; the line hangs vertically
// below the fairlead (V = w Ls, Z = Ls + w Ls^2 / 2EA) and the rest lies on the seabed.
TEST(ElasticCatenary, SlackLineHasZeroHorizontalTension) {
  const CatenaryInput in{500.0, 300.0, 1000.0, 1000.0, 1e8};
  const CatenarySolution sol = solveAnchoredCatenary(in);
  EXPECT_EQ(sol.regime, CatenaryRegime::SlackGrounded);
  EXPECT_EQ(sol.horizontalTension, 0.0);
  const double ls = sol.verticalTension / in.weight;
  EXPECT_NEAR(ls + in.weight * ls * ls / (2 * in.axialStiffness), in.height, 1e-9 * in.height);
  EXPECT_NEAR(sol.groundedLength, in.length - ls, 1e-9);
  EXPECT_NEAR(sol.position(in.length).x, in.span, 1e-12);
  EXPECT_NEAR(sol.position(in.length).z, in.height, 1e-9 * in.height);
  EXPECT_EQ(sol.position(0.5 * sol.groundedLength).z, 0.0);
  EXPECT_EQ(sol.tension(0.0), 0.0);

  // Just past the slack limit X = L - Ls the Newton solution exists, with H -> 0 and V -> w Ls.
  CatenaryInput taut = in;
  taut.span = in.length - ls + 1e-3;
  const CatenarySolution near = solveAnchoredCatenary(taut);
  EXPECT_EQ(near.regime, CatenaryRegime::Grounded);
  EXPECT_GT(near.horizontalTension, 0.0);
  EXPECT_LT(near.horizontalTension, 1e-3 * sol.verticalTension);
  EXPECT_NEAR(near.verticalTension, sol.verticalTension, 1e-3 * sol.verticalTension);
  const auto [x, z] = jonkmanEnd(taut, near.horizontalTension, near.verticalTension);
  EXPECT_NEAR(x, taut.span, 1e-9 * taut.span);
  EXPECT_NEAR(z, taut.height, 1e-9 * taut.height);
}

// Closed-form edge cases: line stretched along the seabed (Z = 0, X > L): H = EA (X - L) / L;
// vertical taut line (X = 0, Z > L): Z = L + (2V - wL) L / 2EA; vertical fold between two free
// points at the same height: V = wL/2 by symmetry.
TEST(ElasticCatenary, ClosedFormEdgeCases) {
  const CatenarySolution seabed = solveAnchoredCatenary({1001.0, 0.0, 1000.0, 1000.0, 1e8});
  EXPECT_EQ(seabed.regime, CatenaryRegime::Grounded);
  EXPECT_NEAR(seabed.horizontalTension, 1e8 * 1.0 / 1000.0, 1e-6);
  EXPECT_EQ(seabed.verticalTension, 0.0);
  EXPECT_NEAR(seabed.position(1000.0).x, 1001.0, 1e-9);

  const CatenaryInput vertical{0.0, 100.5, 100.0, 1000.0, 1e7};
  const CatenarySolution v = solveAnchoredCatenary(vertical);
  EXPECT_EQ(v.regime, CatenaryRegime::Vertical);
  EXPECT_NEAR(v.verticalTension, 0.5 * 1e7 / 100.0 + 0.5 * 1000.0 * 100.0, 1e-6);
  EXPECT_NEAR(v.position(100.0).z, 100.5, 1e-9);
  EXPECT_NEAR(v.anchorTension, v.verticalTension - 1000.0 * 100.0, 1e-6);

  const CatenarySolution fold = solveSuspendedCatenary({0.0, 0.0, 100.0, 1000.0, 1e7});
  EXPECT_EQ(fold.regime, CatenaryRegime::Vertical);
  EXPECT_NEAR(fold.verticalTension, 0.5 * 1000.0 * 100.0, 1e-6);
  EXPECT_NEAR(fold.position(100.0).z, 0.0, 1e-9);
  // Lowest point: 50 m of line stretched by w (50)^2 / 2EA.
  EXPECT_NEAR(fold.position(50.0).z, -(50.0 + 1000.0 * 2500.0 / 2e7), 1e-9);
}

// Errors: invalid inputs and inextensible lines that cannot reach are tangle::Error; a Newton that
// runs out of iterations is tangle::ConvergenceError with the inputs in the message.
TEST(ElasticCatenary, ErrorsCarryContext) {
  EXPECT_THROW(solveAnchoredCatenary({900.0, 300.0, 1000.0, 0.0, 1e8}), Error);
  EXPECT_THROW(solveAnchoredCatenary({900.0, 300.0, -1.0, 100.0, 1e8}), Error);
  EXPECT_THROW(solveAnchoredCatenary({900.0, 300.0, 1000.0, 100.0, 0.0}), Error);
  EXPECT_THROW(solveAnchoredCatenary({900.0, -1.0, 1000.0, 100.0, 1e8}), Error);
  EXPECT_THROW(solveAnchoredCatenary({std::nan(""), 300.0, 1000.0, 100.0, 1e8}), Error);
  EXPECT_THROW(solveAnchoredCatenary({960.0, 300.0, 1000.0, 100.0, kInf}), Error);  // chord 1005.8 > L
  EXPECT_THROW(solveSuspendedCatenary({0.0, 120.0, 100.0, 100.0, kInf}), Error);
  // With elasticity the same geometry has a (stretched) solution.
  EXPECT_NO_THROW(solveAnchoredCatenary({960.0, 300.0, 1000.0, 100.0, 1e8}));

  CatenaryOptions tight;
  tight.maxIterations = 1;
  try {
    solveAnchoredCatenary({950.0, 330.0, 1130.0, 1100.0, 5.8e8}, tight);
    FAIL() << "expected ConvergenceError";
  } catch (const ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("L = 1130"), std::string::npos);
  }
  const CatenarySolution sol = solveAnchoredCatenary({950.0, 330.0, 1130.0, 1100.0, 5.8e8});
  EXPECT_THROW(sol.position(1131.0), Error);
  EXPECT_THROW(sol.tension(-1.0), Error);
  CatenaryOptions bad;
  bad.tolerance = 0.0;
  EXPECT_THROW(solveAnchoredCatenary({950.0, 330.0, 1130.0, 1100.0, 5.8e8}, bad), Error);
}

// Robustness: a deterministic sweep of random geometries (slack to taut, shallow to steep, stiff to
// stretchy) always converges and satisfies the equations to 1e-9 relative.
TEST(ElasticCatenary, RandomSweepAlwaysConverges) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    CatenaryInput in;
    in.length = 10.0 + 2000.0 * unit(rng);
    in.height = in.length * 1.2 * unit(rng);
    in.span = in.length * 1.2 * unit(rng);
    in.weight = std::pow(10.0, 4.0 * unit(rng) - 0.5);
    in.axialStiffness = std::pow(10.0, 5.0 + 5.0 * unit(rng));
    CatenarySolution sol;
    ASSERT_NO_THROW(sol = solveAnchoredCatenary(in)) << "case " << i;
    const CatenaryPoint end = sol.position(in.length);
    EXPECT_NEAR(end.x, in.span, 1e-9 * std::max(in.span, 1e-3 * in.length)) << "case " << i;
    EXPECT_NEAR(end.z, in.height, 1e-9 * std::max(in.height, 1e-3 * in.length)) << "case " << i;
    if (sol.regime == CatenaryRegime::Grounded || sol.regime == CatenaryRegime::Suspended) {
      // The textbook log form cancels for very taut lines (asinh(V/H) - asinh((V - wL)/H) with
      // V, H >> wL): its own round-off is ~1e-16 (H + V) / (wL) relative, added to the 1e-9.
      const double conditioning =
          1e-14 * (sol.horizontalTension + sol.verticalTension) / (in.weight * in.length);
      const double rel = 1e-9 + conditioning;
      const auto [x, z] = jonkmanEnd(in, sol.horizontalTension, sol.verticalTension);
      EXPECT_NEAR(x, in.span, rel * std::max(in.span, 1e-3 * in.length)) << "case " << i;
      EXPECT_NEAR(z, in.height, rel * std::max(in.height, 1e-3 * in.length)) << "case " << i;
    }
    CatenaryInput free = in;
    free.height = (2.0 * unit(rng) - 1.0) * in.height;
    ASSERT_NO_THROW(sol = solveSuspendedCatenary(free)) << "free case " << i;
    EXPECT_NEAR(sol.position(in.length).x, free.span, 1e-9 * std::max(free.span, 1e-3 * in.length));
    EXPECT_NEAR(sol.position(in.length).z, free.height, 1e-9 * in.length);
  }
}

// ---------------------------------------------------------------------------------------------
// Initial-shape generator.
// ---------------------------------------------------------------------------------------------

std::vector<double> uniformArcLengths(double length, int n) {
  std::vector<double> s;
  for (int i = 0; i <= n; ++i) s.push_back(length * i / n);
  return s;
}

void expectValidShape(const InitialShape& shape, const Vec3& a, const Vec3& b, double depth) {
  ASSERT_GE(shape.positions.size(), 2u);
  EXPECT_EQ(shape.positions.front(), a);  // exact
  EXPECT_EQ(shape.positions.back(), b);
  for (std::size_t i = 0; i < shape.positions.size(); ++i) {
    EXPECT_TRUE(shape.positions[i].allFinite()) << "point " << i;
    if (i > 0 && i + 1 < shape.positions.size()) {
      EXPECT_GE(shape.positions[i].z(), -depth) << "point " << i;
    }
  }
}

const std::vector<CatenarySection> kChainWireChain = {
    {200.0, 1100.0, 5.8e8}, {730.0, 300.0, 6.0e8}, {200.0, 1100.0, 5.8e8}};

// Mooring from an anchor on the seabed to a fairlead: equals the single-segment solution of the
// equivalent line (mean w, series EA) rotated into the vertical plane of the ends (tolerance 1e-9 m:
// only the round-off end correction differs).
TEST(InitialLineShape, AnchoredLineFollowsEquivalentCatenary) {
  const double depth = 345.0;
  const Vec3 anchor(600.0, 800.0, -depth);  // 1000 m radius
  const Vec3 fairlead(30.0, 40.0, -15.0);   // 50 m radius, 15 m draft
  const std::vector<double> s = uniformArcLengths(1130.0, 113);
  const InitialShape shape = initialLineShape(anchor, fairlead, kChainWireChain, depth, s);
  EXPECT_EQ(shape.kind, InitialShapeKind::Anchored);
  expectValidShape(shape, anchor, fairlead, depth);

  const double w = (400.0 * 1100.0 + 730.0 * 300.0) / 1130.0;
  const double ea = 1130.0 / (400.0 / 5.8e8 + 730.0 / 6.0e8);
  const CatenarySolution sol = solveAnchoredCatenary({950.0, 330.0, 1130.0, w, ea});
  EXPECT_NEAR(shape.horizontalTension, sol.horizontalTension, 1e-9 * sol.horizontalTension);
  const Vec3 toward = Vec3(-0.6, -0.8, 0.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const CatenaryPoint p = sol.position(s[i]);
    const Vec3 expected = anchor + toward * p.x + Vec3::UnitZ() * p.z;
    EXPECT_NEAR((shape.positions[i] - expected).norm(), 0.0, 1e-9) << "s = " << s[i];
  }

  // Same line listed from the fairlead: the mirror image (s -> L - s).
  const std::vector<CatenarySection> reversed(kChainWireChain.rbegin(), kChainWireChain.rend());
  const InitialShape back = initialLineShape(fairlead, anchor, reversed, depth, s);
  expectValidShape(back, fairlead, anchor, depth);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR((back.positions[i] - shape.positions[s.size() - 1 - i]).norm(), 0.0, 1e-9);
  }
}

// Taut: chord longer than the unstretched length. Straight line, each section stretched under the
// uniform tension T = (D - L) / sum(L_i/EA_i) (exact bar statics; tolerance round-off).
TEST(InitialLineShape, TautLineIsStraightAndUniformlyStretched) {
  const Vec3 a(0.0, 0.0, -100.0), b(120.0, 0.0, 60.0);  // chord 200 m > L = 195 m
  const double chord = (b - a).norm();
  const std::vector<CatenarySection> shortLine = {{95.0, 500.0, 1e8}, {100.0, 500.0, 4e8}};
  const InitialShape shape = initialLineShape(a, b, shortLine, 100.0, {0.0, 47.5, 95.0, 145.0, 195.0});
  EXPECT_EQ(shape.kind, InitialShapeKind::Taut);
  expectValidShape(shape, a, b, 100.0);
  const double tension = (chord - 195.0) / (95.0 / 1e8 + 100.0 / 4e8);
  EXPECT_NEAR(shape.horizontalTension, tension, 1e-9 * tension);
  const Vec3 e = (b - a) / chord;
  const std::array<double, 5> stretched = {0.0, 47.5 * (1 + tension / 1e8), 95.0 * (1 + tension / 1e8),
                                           95.0 * (1 + tension / 1e8) + 50.0 * (1 + tension / 4e8), chord};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR((shape.positions[i] - (a + e * stretched[i])).norm(), 0.0, 1e-9) << i;
  }
}

// Both ends above a deep seabed: the two-point suspended catenary; the lowest point stays above
// the seabed and no clipping happens (compared to solveSuspendedCatenary to 1e-9 m).
TEST(InitialLineShape, FullySuspendedLine) {
  const double depth = 1000.0;
  const Vec3 a(0.0, 0.0, -200.0), b(0.0, 300.0, -50.0);
  const std::vector<CatenarySection> sections = {{250.0, 800.0, 3e8}, {250.0, 800.0, 3e8}};
  const std::vector<double> s = uniformArcLengths(500.0, 50);
  const InitialShape shape = initialLineShape(a, b, sections, depth, s);
  EXPECT_EQ(shape.kind, InitialShapeKind::Suspended);
  expectValidShape(shape, a, b, depth);
  const CatenarySolution sol = solveSuspendedCatenary({300.0, 150.0, 500.0, 800.0, 3e8});
  for (std::size_t i = 0; i < s.size(); ++i) {
    const CatenaryPoint p = sol.position(s[i]);
    EXPECT_NEAR((shape.positions[i] - (a + Vec3::UnitY() * p.x + Vec3::UnitZ() * p.z)).norm(), 0.0, 1e-9);
    EXPECT_GT(shape.positions[i].z(), -depth);
  }
  // It sags: some point is below the lower end.
  double lowest = 0.0;
  for (const Vec3& p : shape.positions) lowest = std::min(lowest, p.z());
  EXPECT_LT(lowest, -200.0);
}

// Both ends above a shallow seabed, with a sag that would cross it: points are lifted onto the seabed.
TEST(InitialLineShape, SuspendedLineIsClippedToSeabed) {
  const double depth = 120.0;
  const Vec3 a(0.0, 0.0, -100.0), b(300.0, 0.0, -100.0);
  const InitialShape shape =
      initialLineShape(a, b, {{500.0, 800.0, 3e8}}, depth, uniformArcLengths(500.0, 100));
  expectValidShape(shape, a, b, depth);
  int onSeabed = 0;
  for (const Vec3& p : shape.positions) onSeabed += p.z() == -depth ? 1 : 0;
  EXPECT_GT(onSeabed, 0);
}

// Buoyant overall (mean w <= 0): documented straight chord, uniformly shortened; the points stay on
// the chord. A lazy-wave-like line (buoyant middle, positive mean) still gets a catenary.
TEST(InitialLineShape, BuoyantLineIsStraight) {
  const Vec3 a(0.0, 0.0, -300.0), b(200.0, 0.0, -20.0);
  const std::vector<double> s = uniformArcLengths(400.0, 40);
  const InitialShape shape = initialLineShape(a, b, {{400.0, -200.0, 1e8}}, 300.0, s);
  EXPECT_EQ(shape.kind, InitialShapeKind::Straight);
  expectValidShape(shape, a, b, 300.0);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR((shape.positions[i] - (a + (b - a) * (s[i] / 400.0))).norm(), 0.0, 1e-9);
  }
  const InitialShape lazyWave =
      initialLineShape(a, b, {{150.0, 1500.0, 1e9}, {100.0, -800.0, 1e9}, {150.0, 1500.0, 1e9}}, 300.0, s);
  EXPECT_EQ(lazyWave.kind, InitialShapeKind::Anchored);
  expectValidShape(lazyWave, a, b, 300.0);
}

// Degenerate layouts never give NaN: both ends on the seabed (slack), a vertical line with a fold,
// a vertical line from an anchor, coincident ends.
TEST(InitialLineShape, DegenerateLayoutsHaveNoNaN) {
  const double depth = 100.0;
  const std::vector<CatenarySection> line = {{300.0, 500.0, 1e8}};
  const std::vector<double> s = uniformArcLengths(300.0, 30);
  const std::vector<std::pair<Vec3, Vec3>> ends = {
      {Vec3(0, 0, -100), Vec3(200, 0, -100)},  // both grounded, slack
      {Vec3(0, 0, -100), Vec3(0, 0, -100)},    // coincident on the seabed
      {Vec3(5, 5, -10), Vec3(5, 5, -50)},      // vertical, both free: fold clipped on the seabed
      {Vec3(5, 5, -100), Vec3(5, 5, -20)},     // vertical above an anchor, slack
      {Vec3(5, 5, -20), Vec3(5, 5, -20)},      // coincident free ends
  };
  for (const auto& [a, b] : ends) {
    const InitialShape shape = initialLineShape(a, b, line, depth, s);
    expectValidShape(shape, a, b, depth);
  }
}

// Slack line with both ends on the seabed, and a slack line below a fairlead straight above its
// anchor: H = 0, so the grounded part is laid as a strain-free circular arc on the seabed.
// Consecutive points are one unstretched spacing ds = 5 m apart along the arc, so their straight
// distance is the arc's chord 2R sin(ds/2R) ~ ds (1 - ds^2 / 24R^2), between ds (1 - 1e-3) and ds
// for any radius R >= 300 / (2 pi) ~ 48 m (the full circle is the tightest arc).
TEST(InitialLineShape, SlackGroundedPartIsStrainFreeArc) {
  const double depth = 100.0;
  const std::vector<double> s = uniformArcLengths(300.0, 60);  // spacing 5 m
  const Vec3 a(0, 0, -depth), b(200, 0, -depth);
  const InitialShape flat = initialLineShape(a, b, {{300.0, 500.0, 1e8}}, depth, s);
  EXPECT_EQ(flat.kind, InitialShapeKind::Anchored);
  EXPECT_EQ(flat.horizontalTension, 0.0);
  expectValidShape(flat, a, b, depth);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_NEAR(flat.positions[i].z(), -depth, 1e-12);
    const double gap = (flat.positions[i] - flat.positions[i - 1]).norm();
    EXPECT_LE(gap, 5.0 + 1e-9);
    EXPECT_GE(gap, 5.0 * (1.0 - 1e-3));
  }
  const Vec3 top(0, 0, -20);
  const InitialShape vertical = initialLineShape(a, top, {{300.0, 500.0, 1e8}}, depth, s);
  expectValidShape(vertical, a, top, depth);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_GT((vertical.positions[i] - vertical.positions[i - 1]).norm(), 4.9) << i;
  }
}

// A deterministic sweep of random layouts: always valid (end points exact, finite, above seabed),
// and the catenary never needs the fallback.
TEST(InitialLineShape, RandomLayoutsAreAlwaysValid) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    const double depth = 20.0 + 2000.0 * unit(rng);
    std::vector<CatenarySection> sections;
    const int n = 1 + static_cast<int>(3 * unit(rng));
    double length = 0.0;
    for (int k = 0; k < n; ++k) {
      sections.push_back(
          {10.0 + 1000.0 * unit(rng), 2000.0 * unit(rng) - 300.0, std::pow(10.0, 6.0 + 3.0 * unit(rng))});
      length += sections.back().length;
    }
    const bool grounded = unit(rng) < 0.5;
    const Vec3 a(0.0, 0.0, grounded ? -depth : -depth * unit(rng));
    const double radius = 1.3 * length * unit(rng);
    const double angle = 6.283185307179586 * unit(rng);
    const Vec3 b(radius * std::cos(angle), radius * std::sin(angle), -depth * unit(rng));
    const InitialShape shape = initialLineShape(a, b, sections, depth, uniformArcLengths(length, 50));
    expectValidShape(shape, a, b, depth);
    EXPECT_NE(shape.kind, InitialShapeKind::Fallback) << "layout " << i;
  }
}

TEST(InitialLineShape, InvalidInputThrows) {
  const Vec3 a(0, 0, -100), b(100, 0, -10);
  EXPECT_THROW(initialLineShape(a, b, {}, 100.0, {0.0}), Error);
  EXPECT_THROW(initialLineShape(a, b, {{0.0, 100.0, 1e8}}, 100.0, {0.0}), Error);
  EXPECT_THROW(initialLineShape(a, b, {{200.0, 100.0, kInf}}, 100.0, {0.0}), Error);
  EXPECT_THROW(initialLineShape(a, b, {{200.0, 100.0, 1e8}}, 100.0, {201.0}), Error);
}

}  // namespace
}  // namespace tangle::catenary
