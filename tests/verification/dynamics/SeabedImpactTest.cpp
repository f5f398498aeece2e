// A line's impact on a sloping seabed (issue 46: "a riser's lower end dropped onto a slope: impact energy
// against 1/2 m v^2 with the Eq. 5 mass"). A 10 m stiff pipe piece lying along the contour of a seabed
// that rises 10 degrees, dropped from rest 0.5 m above it. Closed forms:
//  - it falls under its submerged weight against its own and its added mass (no drag):
//    g' = w / (m + Ca rho A), v = sqrt(2 g' h), and meets the seabed with the normal speed v0 = v cos(alpha);
//  - it lands along its whole length at once (a rigid body: the line lies along the contour), so the Eq. 5
//    mass (impulse of the impact phase / change of normal velocity) is its mass with the added mass of its
//    normal direction, M = (m + Ca rho A) L, and the impact energy 1/2 M v0^2.
// Tolerances: v0 0.5 % (the approach speed is the accepted state's before contact, g' dt = 4e-4 m/s early);
// M and the energy 2 %: the impulse also carries the weight's normal component over the impact phase,
// w cos(alpha) L t_phase, which is 0.5 % of M v0 with the phase of a quarter of pi sqrt(m / k) = 2 ms at this
// seabed stiffness (k = 1e8 N/m/m). Measured: v0 -0.011 %, M +0.60 %, the energy +0.57 %, the work +0.78 %.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tangle/analysis/SeabedImpacts.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kSlopeDeg = 10.0, kLength = 10.0, kDiameter = 0.5, kMass = 300.0, kCa = 1.0, kDrop = 0.5;

std::string pieceAboveSlope() {
  const double slope = degToRad(kSlopeDeg);
  // Along the contour x = 20 (the seabed there at -100 + 20 tan(alpha)), its surface kDrop above the seabed's
  // contact surface (vertically).
  const double z = -100.0 + 20.0 * std::tan(slope) + 0.5 * kDiameter / std::cos(slope) + kDrop;
  return fmt::format(R"(title: a pipe piece dropped onto a slope
environment:
  water_depth: 100
  seabed: {{slope: {slope}, upslope_azimuth: 0, normal_stiffness: 1.0e8}}
line_types:
  - {{name: pipe, outer_diameter: {d}, mass_per_length: {m}, axial_stiffness: 1.0e10, bending_stiffness: 1.0e9,
     drag_normal: 0, drag_axial: 0, added_mass_normal: {ca}, added_mass_axial: 0}}
lines:
  - name: piece
    end_a: {{type: free, position: [20, {y0}, {z}]}}
    end_b: {{type: free, position: [20, {y1}, {z}]}}
    sections: [{{type: pipe, length: {L}, elements: 10}}]
    start_shape: [[20, {y0}, {z}], [20, {y1}, {z}]]
dynamics: {{duration: 0.9, time_step: 0.0002, output_interval: 0.1, ramp_time: 0}}
)",
                     fmt::arg("slope", kSlopeDeg), fmt::arg("d", kDiameter), fmt::arg("m", kMass),
                     fmt::arg("ca", kCa), fmt::arg("y0", -0.5 * kLength), fmt::arg("y1", 0.5 * kLength),
                     fmt::arg("z", z), fmt::arg("L", kLength));
}

TEST(SeabedImpact, PieceDroppedOnASlopeHasItsMassAndTheFallsEnergy) {
  analysis::Simulation sim(io::readModelString(pieceAboveSlope(), "drop.yaml"));
  const model::Model& m = sim.model();
  analysis::SeabedImpacts impacts(m, 0.05);
  impacts.start(sim.state());
  ASSERT_TRUE(impacts.events().empty()) << "the piece starts clear of the seabed";
  const time::DynamicResult run =
      sim.runDynamics([](const model::State&, const VecX&) {}, false,
                      [&](const model::State& s, double dt) { impacts.commit(s, dt); });
  ASSERT_TRUE(run.completed) << run.message;
  impacts.finish();
  ASSERT_GE(impacts.impactCount(), 1);
  const analysis::SeabedImpact& first = impacts.events().front();
  ASSERT_TRUE(first.impact);

  const double rho = 1025.0, g = 9.80665, area = 0.25 * kPi * kDiameter * kDiameter;
  const double massPerLength = kMass + kCa * rho * area;
  const double w = (kMass - rho * area) * g;
  const double v = std::sqrt(2.0 * w / massPerLength * kDrop);
  const double v0 = v * std::cos(degToRad(kSlopeDeg));
  const double mass = massPerLength * kLength;
  EXPECT_NEAR(first.impactVelocity, v0, 0.005 * v0);
  EXPECT_NEAR(first.eq5Mass, mass, 0.02 * mass);
  const double energy = 0.5 * mass * v0 * v0;
  EXPECT_NEAR(first.impactEnergy, energy, 0.02 * energy);
  // The seabed took the approach's kinetic energy over the phase (the work of its reaction against it).
  EXPECT_NEAR(first.phaseWork, energy, 0.05 * energy);
  // Every node touched in the same event (the piece lands flat).
  EXPECT_EQ(first.lastNode - first.firstNode, m.lines().front().nodeCount - 1);
  // Where: at the contour x = 20, from the piece's middle.
  EXPECT_NEAR(first.position.x(), 20.0, 0.2);
}

// An impact whose approach was not stopped within what was recorded (here the tracker is given only the
// state in which the piece first touches, as when a run ends there): its Eq. 5 mass cannot be measured, and
// neither can its energy. Until 2026-12-06 the energy stayed at 0 J, written as a zero-energy impact in
// seabed_impacts.csv beside an empty mass; now both are empty (NaN), and the log says none was measured.
TEST(SeabedImpact, AnImpactWhoseApproachWasNotStoppedHasNoEnergy) {
  analysis::Simulation sim(io::readModelString(pieceAboveSlope(), "drop.yaml"));
  analysis::SeabedImpacts impacts(sim.model(), 0.05);
  impacts.start(sim.state());
  const time::DynamicResult run = sim.runDynamics([](const model::State&, const VecX&) {}, false,
                                                  [&](const model::State& s, double dt) {
                                                    if (impacts.events().empty()) impacts.commit(s, dt);
                                                  });
  ASSERT_TRUE(run.completed) << run.message;
  impacts.finish();
  ASSERT_EQ(impacts.events().size(), 1u);
  const analysis::SeabedImpact& first = impacts.events().front();
  ASSERT_TRUE(first.impact);
  EXPECT_TRUE(first.open);
  EXPECT_TRUE(std::isnan(first.eq5Mass));
  EXPECT_TRUE(std::isnan(first.impactEnergy));
  EXPECT_NE(impacts.terminalSummary().find("no impact energy measured"), std::string::npos)
      << impacts.terminalSummary();
}

}  // namespace
}  // namespace tangle
