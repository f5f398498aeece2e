// Issue 47: MoorDyn's bodies, read from MoorDyn v2.7.1's own decks (tests/data/moordyn, unchanged) and
// checked against what MoorDyn's tests check (tests/bodies.cpp), with MoorDyn's tolerances.
// - body_tests/orbitalBody.txt ("Excentric body"): two free bodies whose reference point (the deck's X0, Y0,
//   Z0 = (0, 10, 20)) is 10 m from their centre of gravity (0, 0, 20), no gravity: body 1 of two 20 kg
//   points, body 2 massless with a 40 kg rod fixed to it. MoorDyn's test sets each body's velocity to v6 =
//   (0, 0, 10 omega, omega, 0, 0) at its reference point (the centre of gravity at rest, a spin omega = 0.2
//   rad/s about x) and checks every 0.25 s for 10 s that the reference point stays on the circle of radius 10
//   m about (0, 0, 20) to 1e-6 of the radius and turns at omega (its angle over the time) to 1e-6 of omega.
//   tangle's converted model has no initial velocities: the test gives the vessels' nodes and the rod's
//   nodes the rigid spin before the run (as MoorDyn's test gives its bodies), and reads the reference point
//   as MoorDyn_GetBodyState does, p + Q (origin0 - reference0) from the vessel's node.
//   Body 1 (a rigid vessel): exact to round-off (measured: angle 9e-14 rad after 10 s, radius 2e-15 m).
//   Body 2 is a known failure (MoorDynBodiesKnownFailures, run as expected to fail): its rod is tangle's
//   stiff beam (EA = 3.3e10 N for a 40 kg rod) tied to a 1 g vessel, and its spin drifts by about 1.5e-5 of
//   omega (measured 2.9e-6 rad/s at dt = 0.01 s; 0.9e-6 to 3.7e-6 rad/s, either sign, at dt = 0.001 to 0.05
//   s, not converging with dt, the same with a Newton tolerance of 1e-6 or 1e-10: consistent with the
//   round-off of the rod's stiffness, 16 eps k |x| = 6e-3 N per node 20 m from the origin, not proven), 15
//   times MoorDyn's 1e-6 (its radius holds to 2e-11 m).
// - BodiesAndRods.dat (MoorDyn's RM3 wave-energy deck; MoorDyn's tests only run it): a free 1000 t body with
//   no volume at the surface, two 10 m diameter, 13 m cans (1 t/m) fixed and pinned on it standing above the
//   water, four slack lines. It must sink until the cans float: the statics converges (through dynamic
//   relaxation), the body floats with its cans through the surface, and the whole floating body balances
//   vertically: rho g V - (M + m_cans) g + the lines' vertical pulls = 0, V the cans' volume below z = 0 from
//   their nodes (straight elements, pi/4 d^2 times the length below the surface). Tolerance 1e-5 of the
//   weight (the statics tolerance is 1e-6 of it).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

std::string deck(const std::string& name) { return std::string(test::kTestDataDir) + "/moordyn/" + name; }

/// Runs orbitalBody.txt as MoorDyn's "Excentric body" test and checks body `body` (1 or 2) at every 0.25 s.
void checkExcentricBody(int body) {
  model::ModelSpec spec = io::readModelFile(deck("orbitalBody.txt"));
  spec.dynamics.duration = 10.0;
  spec.dynamics.outputInterval = 0.25;  // MoorDyn's test's step
  analysis::Simulation sim(spec);
  ASSERT_TRUE(sim.solveStatics().converged);  // statics.method none: the deck's positions
  const double radius = 10.0, omega = 0.2;
  const Vec3 centre(0.0, 0.0, 20.0), reference0(0.0, 10.0, 20.0);
  const model::Model& m = sim.model();
  ASSERT_EQ(m.spec().vessels.size(), 2u);
  model::State& state = sim.state();
  const Vec3 spin(omega, 0.0, 0.0);
  // The rigid spin about the centre of gravity: the vessels' nodes (at the centre) turn, the rod's nodes move
  // at spin x (r - centre) and turn (spatial angular velocities).
  for (int node = 0; node < m.dofs().nodeCount(); ++node) {
    const int d = m.dofs().firstDof(node);
    state.velocity.segment<3>(d) = spin.cross(state.position[static_cast<std::size_t>(node)] - centre);
    if (m.dofs().hasRotations(node)) state.velocity.segment<3>(d + 3) = spin;
  }
  const auto node = static_cast<std::size_t>(m.vesselNode(body - 1));
  int checked = 0;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    if (s.time < 0.1) return;
    const Vec3 reference = s.position[node] + s.triad[node] * (reference0 - centre);
    const Vec3 q = (reference - centre) / radius;
    // MoorDyn's angle test holds while the angle stays in (-pi, pi]: omega t <= 2 rad over the 10 s.
    EXPECT_LE(std::abs((reference - centre).norm() - radius), 1e-6 * radius) << "t = " << s.time;
    EXPECT_LE(std::abs(std::atan2(q.z(), q.y()) / s.time - omega), 1e-6 * omega) << "t = " << s.time;
    ++checked;
  });
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_GE(checked, 39);
}

TEST(MoorDynBodies, ExcentricBodyOfPointsOrbitsItsCentreOfGravityAtItsSpin) { checkExcentricBody(1); }

TEST(MoorDynBodies, BodyOnTwoCansSinksUntilTheyFloat) {
  analysis::Simulation sim(io::readModelFile(deck("BodiesAndRods.dat")));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const model::Model& m = sim.model();
  const double rho = 1025.0, g = 9.80665, area = std::numbers::pi / 4.0 * 10.0 * 10.0;
  const double body = sim.state().position[static_cast<std::size_t>(m.vesselNode(0))].z();
  EXPECT_LT(body, -2.0);   // the cans (from 2 m above the body) reach into the water
  EXPECT_GT(body, -15.0);  // and stand out of it
  double volume = 0.0, canMass = 0.0, pull = 0.0;
  for (const solver::LineSnapshot& s : sim.snapshot()) {
    if (s.name == "rod1" || s.name == "rod2") {
      for (std::size_t i = 0; i + 1 < s.position.size(); ++i) {
        const double za = s.position[i].z(), zb = s.position[i + 1].z();
        const double length = (s.position[i + 1] - s.position[i]).norm();
        const double below = za < 0.0 && zb < 0.0     ? 1.0
                             : za >= 0.0 && zb >= 0.0 ? 0.0
                                                      : std::max(-za, -zb) / std::abs(zb - za);
        volume += area * length * below;
        canMass += 1000.0 * length;
      }
    } else {
      pull += s.endForceB.z();  // every line's end B is on the body
    }
  }
  const double weight = (1.0e6 + canMass) * g;
  EXPECT_GT(volume, 0.0);
  EXPECT_NEAR(rho * g * volume - weight + pull, 0.0, 1e-5 * weight)
      << "buoyancy " << rho * g * volume << " N, weight " << weight << " N, lines " << pull << " N";
}

TEST(MoorDynBodiesKnownFailures, ExcentricBodyWithARodOrbitsItsCentreOfGravityAtItsSpin) {
  checkExcentricBody(2);
}

}  // namespace
}  // namespace tangle
