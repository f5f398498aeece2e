// Issue 47: a free point in the dynamics. A 20 t buoy of 40 m^3 held down by three taut, light, neutrally
// buoyant legs, started from its static equilibrium with an upward velocity of 0.01 m/s at the point, heaves
// at the natural period of a mass on the legs' vertical stiffness:
//   T = 2 pi sqrt(M / k_zz),   K = sum_i [EA / L0 u_i u_i^T + T_i / l_i (I - u_i u_i^T)]
// (a taut two-force member's axial and geometric stiffness; u_i the unit chord, l_i its length, T_i its
// tension; e.g. Irvine 1981, "Cable structures", ch. 1, for the taut-string stiffness), with the static
// geometry of the hand equilibrium (bisection on the height, as JunctionTest). The point's mass M is the
// buoy's; the legs' (24 kg each, with as much added mass) move with it over a third of their length: 0.1 % of
// M, and the ties' compliance is 1 % of one element's (0.1 % of the leg's): tolerance 0.5 % on the period,
// measured over the upward zero crossings of 7 periods (1.8672 s against 1.8650 s: +0.12 %, the legs' mass).
// The amplitude (3 mm) keeps the response linear; no drag, no waves; spectral radius 1 (no numerical
// damping).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/UpwardCrossings.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kRho = 1025.0, kG = 9.81, kEA = 1.0e7, kLegLength = 75.0, kSpread = 50.0;
constexpr double kMass = 20000.0, kVolume = 40.0;
constexpr double kAnchorZ = -99.0;

std::string buoyModel() {
  const double neutral = kRho * 0.25 * 3.141592653589793 * 0.02 * 0.02;
  const double c = std::cos(2.0 * 3.141592653589793 / 3.0), s = std::sin(2.0 * 3.141592653589793 / 3.0);
  return fmt::format(R"(
environment: {{water_depth: 100, water_density: {rho}, gravity: {g}}}
line_types:
  - {{name: rope, outer_diameter: 0.02, mass_per_length: {m:.12g}, axial_stiffness: {ea}, drag_normal: 0, drag_axial: 0}}
points:
  - {{name: buoy, position: [0, 0, -40], mass: {mass}, volume: {volume}}}
lines:
  - {{name: leg1, end_a: {{type: anchored, position: [{r}, 0, {za}]}}, end_b: {{type: point, point: buoy}},
     sections: [{{type: rope, length: {L}, elements: 10}}]}}
  - {{name: leg2, end_a: {{type: anchored, position: [{x2}, {y2}, {za}]}}, end_b: {{type: point, point: buoy}},
     sections: [{{type: rope, length: {L}, elements: 10}}]}}
  - {{name: leg3, end_a: {{type: point, point: buoy}}, end_b: {{type: anchored, position: [{x2}, {y3}, {za}]}},
     sections: [{{type: rope, length: {L}, elements: 10}}]}}
dynamics: {{duration: 14, time_step: 0.002, output_interval: 0.01, ramp_time: 0, spectral_radius: 1}}
)",
                     fmt::arg("rho", kRho), fmt::arg("g", kG), fmt::arg("m", neutral), fmt::arg("ea", kEA),
                     fmt::arg("mass", kMass), fmt::arg("volume", kVolume), fmt::arg("r", kSpread),
                     fmt::arg("za", kAnchorZ), fmt::arg("L", kLegLength), fmt::arg("x2", kSpread * c),
                     fmt::arg("y2", kSpread * s), fmt::arg("y3", -kSpread * s));
}

TEST(JunctionDynamics, BuoyOnThreeLegsHeavesAtTheirNaturalPeriod) {
  // The hand equilibrium: height h of the buoy over the anchors with 3 T(h) h / l = (rho V - M) g.
  const double lift = (kRho * kVolume - kMass) * kG;
  double lo = 0.0, hi = 100.0;
  for (int k = 0; k < 200; ++k) {
    const double h = 0.5 * (lo + hi), l = std::hypot(kSpread, h);
    (3.0 * kEA * (l - kLegLength) / kLegLength * h / l > lift ? hi : lo) = h;
  }
  const double h = 0.5 * (lo + hi), l = std::hypot(kSpread, h);
  const double tension = kEA * (l - kLegLength) / kLegLength;
  const double sin2 = h * h / (l * l);
  const double kzz = 3.0 * (kEA / kLegLength * sin2 + tension / l * (1.0 - sin2));
  const double expected = 2.0 * 3.141592653589793 * std::sqrt(kMass / kzz);

  analysis::Simulation sim(io::readModelString(buoyModel(), "buoy (test)"));
  ASSERT_TRUE(sim.solveStatics().converged);
  const model::Model& m = sim.model();
  const model::JunctionPoint& point = m.points().front();
  const double zStatic = sim.state().position[static_cast<std::size_t>(point.node)].z();
  ASSERT_NEAR(zStatic, kAnchorZ + h, 1e-3);
  for (const int node : point.endNodes) sim.state().velocity[m.dofs().firstDof(node) + 2] = 0.01;

  test::UpwardCrossings crossings;
  const time::DynamicResult run = sim.runDynamics(nullptr, false, [&](const model::State& s, double) {
    crossings.add(s.time, s.position[static_cast<std::size_t>(point.node)].z() - zStatic);
  });
  ASSERT_TRUE(run.completed) << run.message;
  ASSERT_GE(crossings.count(), 6u) << "period " << expected << " s";
  EXPECT_NEAR(crossings.meanPeriod(), expected, 5e-3 * expected) << crossings.count() << " crossings";
}

}  // namespace
}  // namespace tangle
