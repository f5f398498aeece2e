// Issue 47: a submerged body (a free vessel with `displaced_volume`, the form MoorDyn's bodies take): its
// weight M g acts at its reference point (its centre of gravity) and its buoyancy rho g V at its centre of
// buoyancy, h = 2 m above; it is held by one vertical tether from an anchor to its reference point.
// - Statics (hand equilibrium of a two-force member): the tether, neutrally buoyant, carries the net lift
//   T = (rho V - M) g along its length, so the body floats at z = z_anchor + L (1 + T / EA). Tolerance 2e-5
//   m: the link between the tether's end and the vessel (100 EA / l, l the element length) stretches T l /
//   (100 EA) = 1.05e-5 m (measured: 1.05e-5 m); the tension to 1e-6 relative.
// - Dynamics: the tether's pull acts at the reference point and the buoyancy stays vertical, so a roll is a
//   pendulum of its own: (I_xx + A_44) theta'' = -rho g V h sin(theta), T = 2 pi sqrt(I_xx / (rho g V h)) for
//   a small amplitude (Newman 1977, "Marine hydrodynamics", 6.16: the metacentric restoring of a submerged
//   body is rho g V times the height of its centre of buoyancy over its centre of gravity). Started upright
//   with a roll rate of 0.01 rad/s (0.0029 rad amplitude: sin(theta) = theta to 1.4e-6) and no damping or
//   added inertia, the period over 6 upward zero crossings within 0.2 %: generalized-alpha at spectral radius
//   1 has a period error of (omega dt)^2 / 12 = 1e-4 at dt = 0.01 s (Chung & Hulbert 1993).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "support/UpwardCrossings.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kRho = 1025.0, kG = 9.81, kMass = 8000.0, kVolume = 12.0, kRollInertia = 2.0e4, kArm = 2.0;
constexpr double kTetherLength = 50.0, kTetherEA = 2.0e8, kAnchorZ = -99.0;

std::string bodyModel() {
  const double neutral = kRho * std::numbers::pi / 4.0 * 0.1 * 0.1;
  return fmt::format(R"(
environment: {{water_depth: 100, water_density: {rho}, gravity: {g}}}
line_types:
  - {{name: tether, outer_diameter: 0.1, mass_per_length: {m:.15g}, axial_stiffness: {ea}, drag_normal: 0, drag_axial: 0, added_mass_normal: 0}}
vessels:
  - name: buoy
    mode: free
    position: [0, 0, -50]
    mass: {mass}
    inertia: [{ixx}, {ixx}, 1.0e4]
    displaced_volume: {volume}
    centre_of_buoyancy: [0, 0, {arm}]
lines:
  - {{name: tether, end_a: {{type: pinned, position: [0, 0, {za}]}}, end_b: {{type: vessel, vessel: buoy, position: [0, 0, 0]}},
     sections: [{{type: tether, length: {L}, elements: 10}}]}}
dynamics: {{duration: 12, time_step: 0.01, output_interval: 0.01, ramp_time: 0, spectral_radius: 1}}
)",
                     fmt::arg("rho", kRho), fmt::arg("g", kG), fmt::arg("m", neutral),
                     fmt::arg("ea", kTetherEA), fmt::arg("mass", kMass), fmt::arg("ixx", kRollInertia),
                     fmt::arg("volume", kVolume), fmt::arg("arm", kArm), fmt::arg("za", kAnchorZ),
                     fmt::arg("L", kTetherLength));
}

TEST(SubmergedBody, FloatsOnItsTetherAtTheHandEquilibrium) {
  analysis::Simulation sim(io::readModelString(bodyModel(), "buoy (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  const double lift = (kRho * kVolume - kMass) * kG;
  const double height = kAnchorZ + kTetherLength * (1.0 + lift / kTetherEA);
  const int node = sim.model().vesselNode(0);
  EXPECT_NEAR(sim.state().position[static_cast<std::size_t>(node)].z(), height, 2e-5);
  for (const solver::LineSnapshot& s : sim.snapshot())
    if (s.name == "tether") {
      EXPECT_NEAR(s.endTensionB, lift, 1e-6 * lift);
    }
}

TEST(SubmergedBody, RollsAtItsMetacentricPeriod) {
  analysis::Simulation sim(io::readModelString(bodyModel(), "buoy (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::Model& m = sim.model();
  const int node = m.vesselNode(0);
  sim.state().velocity[m.dofs().firstDof(node) + 3] = 0.01;  // roll rate [rad/s]
  const double expected = 2.0 * std::numbers::pi * std::sqrt(kRollInertia / (kRho * kG * kVolume * kArm));
  test::UpwardCrossings crossings;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    crossings.add(s.time, geometry::logMap(s.triad[static_cast<std::size_t>(node)]).x());
  });
  ASSERT_TRUE(run.completed) << run.message;
  ASSERT_GE(crossings.count(), 5u) << "period " << expected << " s";
  EXPECT_NEAR(crossings.meanPeriod(), expected, 2e-3 * expected) << crossings.count() << " crossings";
}

}  // namespace
}  // namespace tangle
