// Vessel verification, issue 5 item 1: free-floating vessel, natural periods of heave, pitch and roll.
//
// A free vessel with no lines, no current, wind or waves and no damping is a set of uncoupled linear
// oscillators about its hydrostatic equilibrium (VesselLoads: F_z = -K33 (z - z0); the tilt moment
// -K55 theta for a pure pitch rotation theta, which the tilt-vector model gives exactly; mass and
// inertia about the reference point, no centre-of-gravity offset, so no coupling). Displaced and
// released from rest, each oscillates with the undamped natural period of a single-degree-of-freedom
// system (e.g. Faltinsen 1990, "Sea loads on ships and offshore structures", ch. 3, natural periods in heave, roll and pitch;
// Rao 2011, "Mechanical Vibrations", 5th ed., sec. 2.2):
//
//     T = 2 pi sqrt((M + A) / K)
//
// with M the mass (or moment of inertia), A the added mass (moment) and K the hydrostatic stiffness.
// The vessel data are those of the drilling unit of examples/drilling-riser-drift/model.yaml (a
// 45 000 t semisubmersible): T_heave = 15.4 s, T_pitch = 42.4 s, T_roll = 36.6 s (roll is given a
// different inertia so that the three cases differ).
//
// Run: Simulation::solveStatics (trivial: the vessel starts in equilibrium), displace the vessel node
// (heave +0.5 m, or a rotation of 0.05 rad about the vessel y or x axis, spatial increment
// R <- exp(theta) R; vessel headings 0 and 30 / 120 deg, the latter checking the vessel-axes form of
// the mass matrix and of the hydrostatic moment), set the consistent initial acceleration a0 = -K x0 / (M + A) (DynamicAnalysis
// assumes a start at rest in equilibrium, a0 = 0, its documented use; see docs/verification-dynamics.md),
// then runDynamics with Newmark's average-acceleration rule (rho_inf = 1: no numerical damping),
// dt = T / 200, an output every step, for 6 periods. The period is the mean spacing of the upward zero
// crossings (linear interpolation between steps) of the recorded motion.
//
// Tolerance: 1 % (issue 5). Expected error: Newmark's period elongation (omega dt)^2 / 12 = 8.2e-5
// (Hughes 1987, "The finite element method", sec. 9.3), plus the zero-crossing interpolation error,
// which is O(dt^2) times the curvature at the crossing (zero for a sine): the errors should be ~1e-4.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle {
namespace {

constexpr double kPiValue = 3.141592653589793;

// Drilling unit of examples/drilling-riser-drift/model.yaml (README.md there for the sources).
constexpr double kMass = 4.5e7;         // [kg]
constexpr double kHeaveAdded = 4.5e7;   // A33 [kg]
constexpr double kHeaveK = 1.5e7;       // K33 [N/m]
constexpr double kPitchInertia = 4.05e10;  // I55 [kg m^2]
constexpr double kPitchAdded = 2.0e10;     // A55 [kg m^2]
constexpr double kPitchK = 1.33e9;         // K55 [N m/rad]
constexpr double kRollInertia = 3.0e10;    // I44 [kg m^2] (different from I55 on purpose)
constexpr double kRollAdded = 1.5e10;      // A44 [kg m^2]
constexpr double kRollK = 1.33e9;          // K44 [N m/rad]

/// DOF of the vessel node that is displaced: 2 = heave (z), 3 = roll (about x), 4 = pitch (about y).
struct FreeCase {
  const char* name;
  int dof;
  double inertia;  // M or I [kg] / [kg m^2]
  double added;    // A [kg] / [kg m^2]
  double stiffness;  // K [N/m] / [N m/rad]
  double amplitude;  // initial displacement [m] / [rad]
  double heading = 0.0;  // vessel heading [rad]: the DOF is in vessel axes
};

model::ModelSpec freeVesselSpec(double period, double heading) {
  model::ModelSpec spec;
  spec.sourceFile = "free-floating vessel (test)";
  spec.environment.waterDepth = 345.0;
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Free;
  v.position = Vec3(0.0, 0.0, 0.0);
  v.heading = heading;
  v.mass = kMass;
  v.inertia = Vec3(kRollInertia, kPitchInertia, 5.5e10);
  v.addedMass = {2.2e7, 2.2e7, kHeaveAdded, kRollAdded, kPitchAdded, 2.5e10};
  v.hydrostaticStiffness = {0.0, 0.0, kHeaveK, kRollK, kPitchK, 0.0};
  // No damping, no current/wind/drift tables, no RAOs.
  spec.vessels.push_back(v);
  // No lines: the model does not need any.
  spec.dynamics.enabled = true;
  spec.dynamics.integrator = model::IntegratorKind::Newmark;
  spec.dynamics.spectralRadius = 1.0;
  spec.dynamics.timeStep = period / 200.0;
  spec.dynamics.outputInterval = spec.dynamics.timeStep;
  spec.dynamics.duration = 6.0 * period;
  spec.dynamics.rampTime = 0.0;
  return spec;
}

/// Mean spacing of the upward zero crossings of x(t) (linear interpolation); -1 with fewer than two.
double periodFromUpCrossings(const std::vector<double>& t, const std::vector<double>& x, int* crossings) {
  std::vector<double> up;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x[i - 1] < 0.0 && x[i] >= 0.0) up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-x[i - 1]) / (x[i] - x[i - 1]));
  }
  *crossings = static_cast<int>(up.size());
  if (up.size() < 2) return -1.0;
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

class FreeFloatingVessel : public ::testing::TestWithParam<FreeCase> {};

TEST_P(FreeFloatingVessel, NaturalPeriodMatchesSingleDofTheory) {
  const FreeCase c = GetParam();
  const double expected = 2.0 * kPiValue * std::sqrt((c.inertia + c.added) / c.stiffness);
  const auto wall0 = std::chrono::steady_clock::now();

  analysis::Simulation sim(freeVesselSpec(expected, c.heading));
  const solver::StaticResult st = sim.solveStatics();
  ASSERT_TRUE(st.converged) << st.message;
  const int node = sim.model().vesselNode(0);
  const int d = sim.model().dofs().firstDof(node);
  // Statics is trivial: the vessel stays where it was put.
  EXPECT_LT((sim.state().position[node] - Vec3::Zero()).norm(), 1e-9);
  const Mat3 r0 = sim.model().vesselRotation(0);
  EXPECT_LT((sim.state().triad[node] - r0).norm(), 1e-12);

  // Displacement along / rotation about the vessel axis of the DOF (global vector r0 e_k).
  model::State& s = sim.state();
  Vec3 unit = Vec3::Zero();
  unit[c.dof % 3] = c.amplitude;
  if (c.dof < 3) {
    s.position[node] += r0 * unit;
  } else {
    s.triad[node] = geometry::expMap(r0 * unit) * s.triad[node];
  }
  s.velocity.setZero();
  s.acceleration.setZero();
  const Vec3 a0 = r0 * (-c.stiffness / (c.inertia + c.added) * unit);
  s.acceleration.segment<3>(d + (c.dof < 3 ? 0 : 3)) = a0;

  std::vector<double> t, x;
  Vec6 largestOther = Vec6::Zero();  // largest motion in the other DOFs (they must stay at rest)
  const auto observer = [&](const model::State& state, const VecX&) {
    Vec6 q;  // motion in vessel axes (initial orientation)
    q.head<3>() = r0.transpose() * state.position[node];
    q.tail<3>() = r0.transpose() * geometry::logMap(state.triad[node] * r0.transpose());
    t.push_back(state.time);
    x.push_back(q[c.dof]);
    for (int k = 0; k < 6; ++k)
      if (k != c.dof) largestOther[k] = std::max(largestOther[k], std::abs(q[k]));
  };
  const time::DynamicResult r = sim.runDynamics(observer);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_EQ(r.cutbacks, 0);

  int crossings = 0;
  const double measured = periodFromUpCrossings(t, x, &crossings);
  ASSERT_GE(crossings, 5);
  const double error = (measured - expected) / expected;
  // Amplitude kept (no damping in the model, none in Newmark with rho_inf = 1).
  double peak = 0.0;
  for (std::size_t i = x.size() / 2; i < x.size(); ++i) peak = std::max(peak, std::abs(x[i]));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("[ vessel   ] %s: T expected %.5f s, measured %.5f s (%d up-crossings), error %+.3e; "
              "amplitude %.6g -> %.6g; other DOFs max %.2e; %d steps, %.2f s wall\n",
              c.name, expected, measured, crossings, error, c.amplitude, peak, largestOther.maxCoeff(), r.steps, wall);
  EXPECT_NEAR(error, 0.0, 0.01);  // issue 5: 1 %
  EXPECT_NEAR(peak, c.amplitude, 0.01 * c.amplitude);
  // Uncoupled: nothing else moves (round-off only).
  EXPECT_LT(largestOther.maxCoeff(), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(
    Modes, FreeFloatingVessel,
    ::testing::Values(FreeCase{"heave", 2, kMass, kHeaveAdded, kHeaveK, 0.5},
                      FreeCase{"pitch", 4, kPitchInertia, kPitchAdded, kPitchK, 0.05},
                      FreeCase{"roll", 3, kRollInertia, kRollAdded, kRollK, 0.05},
                      // Heading 30 / 120 deg: pitch and roll about the turned vessel axes (checks the
                      // vessel-axes transformation of the mass matrix and of the hydrostatic moment).
                      FreeCase{"pitch_heading30", 4, kPitchInertia, kPitchAdded, kPitchK, 0.05, kPiValue / 6.0},
                      FreeCase{"roll_heading120", 3, kRollInertia, kRollAdded, kRollK, 0.05, 2.0 * kPiValue / 3.0}),
    [](const ::testing::TestParamInfo<FreeCase>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace tangle
