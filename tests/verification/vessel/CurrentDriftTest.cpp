// Vessel verification, issue 5 item 2: a free vessel drifting under a steady uniform current.
//
// Model: a free vessel (no lines, no hydrostatics needed) with linear surge damping B1 only, an
// OCIMF-style current coefficient table (VesselLoads: F_x = 1/2 rho V^2 Cx(beta) A_x with the relative
// velocity V = U - v, OCIMF 1994 "Prediction of wind and current loads on VLCCs"), and a uniform current
// U along +x (heading 0, so beta = 0 and the flow load stays along x). It starts on station (a DP hold
// in statics, `heldInStatics`) and is released at t = 0. The surge equation is
//
//     m dv/dt = c (U - v)^2 - B1 v,    m = M + A11,    c = 1/2 rho Cx(0) A_x.
//
// Steady state: c (U - v)^2 = B1 v; the root below U is
//     v1 = (2 c U + B1 - sqrt(D)) / (2 c),  D = (2 c U + B1)^2 - 4 c^2 U^2 = B1 (4 c U + B1).
// The right-hand side is c (v - v1)(v - v2) with v2 the other root (> U), so the equation is a Riccati
// equation with constant coefficients and separates: with v(0) = 0,
//     w(t) = (v - v1) / (v - v2) = (v1 / v2) exp(-t / tau),   tau = m / (c (v2 - v1)) = m / sqrt(D),
// which is also the time constant of the equation linearised about v1, m / (B1 + 2 c (U - v1)).
// Hence v(t) = (v1 - v2 w(t)) / (1 - w(t)) in closed form.
//
// Checks and tolerances:
// - final velocity after 8 tau: within 1 % of v1 (issue 5). At 8 tau the transient itself still leaves
//   v - v1 = -v1 (1 - v1 / v2) e^-8 / (1 - w) = -2.5e-4 v1 (with the data below); the integrator
//   (Newmark, dt = tau / 100) adds ~(dt / tau)^2 / 12 ~ 1e-5 in the decay rate. Expected error -2.5e-4.
// - the whole history against the closed form v(t): within 1 % of v1 (same reasoning; 1 % is the
//   issue's bound for this test).
// - the time constant, estimated from the record as the least-squares slope of ln w(t) over
//   0.5 tau .. 4 tau: within 2 %. It is checked loosely because it is a derived quantity: w divides the
//   small difference v - v1 (which falls to 1.4 % of v1 at 4 tau), so a velocity error e becomes an error
//   ~ e / (v - v1) in w and the fitted slope amplifies the velocity error by up to ~e^4 / 4 ~ 14 times
//   near the end of the window. With the expected velocity error the estimate is good to ~1e-4.
// The run also checks that the statics hold keeps the vessel on station (offset < 1e-3 m) and that
// sway, heave and the rotations stay zero.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle {
namespace {

constexpr double kPiValue = 3.141592653589793;

TEST(VesselCurrentDrift, SteadyDriftVelocityAndTimeConstant) {
  const auto wall0 = std::chrono::steady_clock::now();
  constexpr double kMass = 1.0e7;      // M [kg]
  constexpr double kAdded = 2.0e6;     // A11 [kg]
  constexpr double kB1 = 1.0e5;        // linear surge damping [N s/m]
  constexpr double kCx = 0.8;          // Cx(0) [-]
  constexpr double kAreaX = 500.0;     // A_x [m^2]
  constexpr double kU = 1.0;           // current speed [m/s]
  constexpr double kRho = 1025.0;      // [kg/m^3]

  const double m = kMass + kAdded;
  const double c = 0.5 * kRho * kCx * kAreaX;
  const double disc = kB1 * (4.0 * c * kU + kB1);
  const double v1 = (2.0 * c * kU + kB1 - std::sqrt(disc)) / (2.0 * c);
  const double v2 = (2.0 * c * kU + kB1 + std::sqrt(disc)) / (2.0 * c);
  const double tau = m / std::sqrt(disc);
  ASSERT_NEAR(c * (kU - v1) * (kU - v1), kB1 * v1, 1e-9 * kB1 * v1);  // the quadratic is solved
  ASSERT_NEAR(tau, m / (kB1 + 2.0 * c * (kU - v1)), 1e-9 * tau);       // = linearised time constant
  const auto exact = [&](double t) {
    const double w = v1 / v2 * std::exp(-t / tau);
    return (v1 - v2 * w) / (1.0 - w);
  };

  model::ModelSpec spec;
  spec.sourceFile = "vessel drift in current (test)";
  spec.environment.waterDepth = 345.0;
  spec.environment.waterDensity = kRho;
  spec.environment.current = {{0.0, kU, 0.0}, {-345.0, kU, 0.0}};  // uniform, towards +x
  model::VesselSpec v;
  v.name = "drifter";
  v.mode = model::VesselMode::Free;
  v.heldInStatics = true;
  v.mass = kMass;
  v.inertia = Vec3(1e10, 1e10, 1e10);
  v.addedMass = {kAdded, kAdded, kAdded, 1e9, 1e9, 1e9};
  v.linearDamping = {kB1, 0.0, 0.0, 0.0, 0.0, 0.0};
  v.currentAreas = Vec3(kAreaX, kAreaX, 100.0);
  // OCIMF-style table, Cx = 0.8 cos(beta), Cy = 0.8 sin(beta), no yaw moment (only beta = 0 is used).
  v.currentCoefficients.heading = {0.0, 0.5 * kPiValue, kPiValue, 1.5 * kPiValue};
  v.currentCoefficients.values = {Vec3(kCx, 0, 0), Vec3(0, kCx, 0), Vec3(-kCx, 0, 0), Vec3(0, -kCx, 0)};
  spec.vessels.push_back(v);
  spec.dynamics.enabled = true;
  spec.dynamics.integrator = model::IntegratorKind::Newmark;
  spec.dynamics.spectralRadius = 1.0;
  spec.dynamics.timeStep = tau / 100.0;
  spec.dynamics.outputInterval = spec.dynamics.timeStep;
  spec.dynamics.duration = 8.0 * tau;
  spec.dynamics.rampTime = 0.0;  // the vessel's environmental loads are not ramped anyway (see report)

  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult st = sim.solveStatics();
  ASSERT_TRUE(st.converged) << st.message;
  const int node = sim.model().vesselNode(0);
  const int d = sim.model().dofs().firstDof(node);
  EXPECT_LT(sim.state().position[node].norm(), 1e-3) << "the statics hold must keep the vessel on station";
  // Released at t = 0 from rest: consistent initial acceleration c U^2 / m (DynamicAnalysis assumes a0 = 0).
  sim.state().acceleration.setZero();
  sim.state().acceleration[d] = c * kU * kU / m;

  std::vector<double> t, vx;
  double largestError = 0.0, other = 0.0;
  const auto observer = [&](const model::State& s, const VecX&) {
    t.push_back(s.time);
    vx.push_back(s.velocity[d]);
    largestError = std::max(largestError, std::abs(s.velocity[d] - exact(s.time)));
    other = std::max({other, std::abs(s.velocity[d + 1]), std::abs(s.velocity[d + 2]),
                      s.velocity.segment<3>(d + 3).cwiseAbs().maxCoeff(), std::abs(s.position[node].y()),
                      std::abs(s.position[node].z()), geometry::logMap(s.triad[node]).norm()});
  };
  const time::DynamicResult r = sim.runDynamics(observer);
  ASSERT_TRUE(r.completed) << r.message;

  // Time constant from the slope of ln w over 0.5 tau .. 4 tau (least squares).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < 0.5 * tau || t[i] > 4.0 * tau) continue;
    const double w = (vx[i] - v1) / (vx[i] - v2);
    if (!(w > 0.0)) continue;
    const double y = std::log(w);
    sx += t[i];
    sy += y;
    sxx += t[i] * t[i];
    sxy += t[i] * y;
    ++n;
  }
  ASSERT_GT(n, 100);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double tauMeasured = -1.0 / slope;

  const double vFinal = vx.back();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("[ vessel   ] drift: v1 %.6f m/s, final %.6f m/s (error %+.3e); history max error %.3e of v1; "
              "tau %.4f s, measured %.4f s (error %+.3e); other DOFs max %.2e; %d steps, %.2f s wall\n",
              v1, vFinal, (vFinal - v1) / v1, largestError / v1, tau, tauMeasured, (tauMeasured - tau) / tau, other,
              r.steps, wall);
  EXPECT_NEAR(vFinal, v1, 0.01 * v1);           // issue 5: 1 %
  EXPECT_LT(largestError, 0.01 * v1);           // closed-form history, 1 %
  EXPECT_NEAR(tauMeasured, tau, 0.02 * tau);    // loose: see the file comment
  EXPECT_LT(other, 1e-8);
}

}  // namespace
}  // namespace tangle
