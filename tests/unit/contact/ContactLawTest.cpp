/// Tests of the restitution calibration of the clipped spring-dashpot contact law (ContactLaw.hpp).
///
/// Sources: Schwager & Poeschel 2007 ("Coefficient of restitution and linear-dashpot model revisited",
/// Granular Matter 9:465-469, eq. 16-20) for the clipped law; the unclipped linear dashpot gives
/// e = exp(-pi zeta / sqrt(1 - zeta^2)) (e.g. Tsuji et al. 1992). The decisive check is independent of
/// both: the 1-DOF impact m x'' + c x' + k x = 0 integrated numerically with RK4 until the clipped
/// force k x + c x' reaches zero.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tangle/contact/ContactLaw.hpp"
#include "tangle/core/Units.hpp"

namespace tangle::contact {
namespace {

/// Outcome of a numerically integrated 1-DOF clipped impact.
struct ImpactOutcome {
  double restitution;  ///< rebound speed / impact speed [-]
  double duration;     ///< time from first touch to separation [s]
};

/// m x'' + c x' + k x = 0 with x = penetration, x(0) = 0, x'(0) = v0 > 0 (approaching). The clipped
/// force F = k x + c x' acts while it is positive; separation is its first zero after t = 0 (for
/// zeta = 0 that is x = 0). The ODE is smooth up to separation, so it is integrated with classical
/// RK4 at a fine step and the event located by bisection on the length of the last RK4 step, which
/// keeps RK4's accuracy up to the event (error ~ (omega h)^4 ~ 1e-15 with 20000 steps per period).
ImpactOutcome integrateImpact(double m, double c, double k, double v0) {
  auto accel = [&](double x, double v) { return -(c * v + k * x) / m; };
  auto rk4 = [&](double x, double v, double h, double& xOut, double& vOut) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    xOut = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    vOut = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
  };
  auto force = [&](double x, double v) { return k * x + c * v; };
  const double period = 2.0 * kPi * std::sqrt(m / k);
  const double h = period / 20000.0;
  double t = 0.0, x = 0.0, v = v0;
  for (int i = 0; i < 1000000; ++i) {
    double x1 = 0.0, v1 = 0.0;
    rk4(x, v, h, x1, v1);
    if (force(x1, v1) <= 0.0) {
      // Separation within this step: bisect on the sub-step (force > 0 at lo, <= 0 at hi).
      double lo = 0.0, hi = h;
      for (int b = 0; b < 200 && hi - lo > 1e-18 * period; ++b) {
        const double mid = 0.5 * (lo + hi);
        rk4(x, v, mid, x1, v1);
        (force(x1, v1) > 0.0 ? lo : hi) = mid;
      }
      rk4(x, v, hi, x1, v1);
      return {-v1 / v0, t + hi};
    }
    t += h;
    x = x1;
    v = v1;
  }
  ADD_FAILURE() << "no separation";
  return {0.0, 0.0};
}

// No damping, no loss: e(0) = 1 exactly (tau* = pi, a = 0), and the duration is half a period.
TEST(ContactLaw, UndampedImpactIsElastic) {
  EXPECT_DOUBLE_EQ(restitutionOfDampingRatio(0.0), 1.0);
  EXPECT_DOUBLE_EQ(dampingRatioForRestitution(1.0), 0.0);
  const double k = 2.0e6, m = 3.0;
  EXPECT_NEAR(contactDuration(k, m, 0.0), kPi * std::sqrt(m / k), 1e-15);
}

// Small zeta: the clipped and unclipped laws agree at first order (both 1 - pi zeta); the clipped
// contact separates earlier (when k x + c x' = 0, while x > 0) and so escapes the pulling part of the
// dashpot: it is the more elastic one. Series of the closed forms (sympy):
//   e_clipped - e_unclipped = 2 zeta^2 - 2 pi zeta^3 + (10/3 + pi^2) zeta^4 - 23.95 zeta^5 + ...
// The test checks the three leading terms; the tolerance is the next term, 30 zeta^5 (> 23.95 zeta^5),
// plus round-off of the difference of two numbers near 1 (1e-15).
TEST(ContactLaw, SmallDampingDiffersFromUnclippedLawAtSecondOrder) {
  for (double zeta : {1e-4, 1e-3, 1e-2, 3e-2}) {
    const double clipped = restitutionOfDampingRatio(zeta);
    const double unclipped = std::exp(-kPi * zeta / std::sqrt(1.0 - zeta * zeta));
    EXPECT_GT(clipped, unclipped) << "zeta " << zeta;
    EXPECT_NEAR(clipped, 1.0 - kPi * zeta, 7.0 * zeta * zeta) << "first order, zeta " << zeta;  // 2 + pi^2/2 < 7
    const double series = 2.0 * zeta * zeta - 2.0 * kPi * std::pow(zeta, 3) + (10.0 / 3.0 + kPi * kPi) * std::pow(zeta, 4);
    EXPECT_NEAR(clipped - unclipped, series, 30.0 * std::pow(zeta, 5) + 1e-15) << "zeta " << zeta;
  }
}

// The inverse recovers zeta, below and above critical damping. It is a bisection down to 1e-15 relative
// in zeta; |de/dzeta| >= 1e-6 up to zeta = 50 (e ~ 1e-4 there) and e is computed to ~1e-16, so the
// round trip is exact to ~1e-10 at worst; within 1e-9 of zeta = 1 the law uses the critical values
// (e constant there), so the tolerance is 2e-9 (relative above zeta = 1).
TEST(ContactLaw, InverseRoundTrip) {
  for (double zeta : {0.0, 1e-6, 0.01, 0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.9, 0.99, 1.0, 1.01, 1.5, 3.0, 10.0, 50.0}) {
    EXPECT_NEAR(dampingRatioForRestitution(restitutionOfDampingRatio(zeta)), zeta, 2e-9 * std::max(1.0, zeta))
        << "zeta " << zeta;
  }
  // Monotone decreasing over the whole range, continuous through critical damping (e = exp(-2)).
  double previous = 2.0;
  for (double zeta = 0.0; zeta <= 100.0; zeta += (zeta < 2.0 ? 0.001 : 0.1)) {
    const double e = restitutionOfDampingRatio(zeta);
    EXPECT_LT(e, previous) << "zeta " << zeta;
    previous = e;
  }
  for (double d : {1e-3, 1e-6, 1e-8})
    for (double zeta : {1.0 - d, 1.0 + d})
      EXPECT_NEAR(restitutionOfDampingRatio(zeta), std::exp(-2.0), 4.0 * d) << "zeta " << zeta;  // de/dzeta ~ -0.5
  // The reachable range goes down to nearly plastic; below it the inverse clamps.
  EXPECT_GT(minimumRestitution(), 0.0);
  EXPECT_LT(minimumRestitution(), 1e-4);
  EXPECT_NEAR(restitutionOfDampingRatio(dampingRatioForRestitution(0.0)), minimumRestitution(), 1e-15);
}

struct LawCase {
  double restitution;
  double mass, stiffness;  // [kg], [N/m]
};

class ClippedImpact : public ::testing::TestWithParam<LawCase> {};

// Independent check: the RK4 rebound-to-impact speed ratio and the time to separation of the clipped
// 1-DOF impact, with c = 2 zeta sqrt(k m) for the zeta the law gives for e (underdamped, critical
// e = exp(-2), and overdamped for e < 0.135). The integration error is ~1e-12 (see integrateImpact);
// tolerance 1e-6 (the bound), relative for the duration.
TEST_P(ClippedImpact, RestitutionAndDurationMatchNumericalIntegration) {
  const LawCase p = GetParam();
  const double zeta = dampingRatioForRestitution(p.restitution);
  const double c = 2.0 * zeta * std::sqrt(p.stiffness * p.mass);
  const ImpactOutcome o = integrateImpact(p.mass, c, p.stiffness, 3.7);
  EXPECT_NEAR(o.restitution, restitutionOfDampingRatio(zeta), 1e-6);
  EXPECT_NEAR(o.restitution, p.restitution, 1e-6);
  const double duration = contactDuration(p.stiffness, p.mass, zeta);
  EXPECT_NEAR(o.duration, duration, 1e-6 * duration);
}

INSTANTIATE_TEST_SUITE_P(Law, ClippedImpact,
                         ::testing::Values(LawCase{1.0, 1.0, 1.0e4}, LawCase{0.9, 2.1e-3, 1.1e8},
                                           LawCase{0.8, 50.0, 3.0e7}, LawCase{0.75, 1.0, 1.0},
                                           LawCase{0.5, 1.0e3, 1.0e6}, LawCase{0.2, 7.0, 2.0e5},
                                           LawCase{0.15, 1.0, 1.0e4}, LawCase{std::exp(-2.0), 3.0, 1.0e5},
                                           LawCase{0.1, 1.0, 1.0e4}, LawCase{0.05, 20.0, 4.0e6},
                                           LawCase{0.01, 1.0, 1.0e4}),
                         [](const ::testing::TestParamInfo<LawCase>& p) {
                           return "e" + std::to_string(static_cast<int>(std::round(1000.0 * p.param.restitution))) +
                                  "permille";
                         });

}  // namespace
}  // namespace tangle::contact
