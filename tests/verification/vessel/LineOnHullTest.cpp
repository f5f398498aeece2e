// A line hitting a hull (issue 46: "a riser swinging into a pontoon"): a 10 m stiff pipe piece, level,
// dropped from rest 0.5 m above the top face of a fixed pontoon (a box hull). Closed forms, as the seabed's
// drop test (SeabedImpactTest):
//  - it falls under its submerged weight against its own and its added mass (no drag):
//    g' = w / (m + Ca rho A), v0 = sqrt(2 g' h);
//  - it lands along its whole length at once (a rigid body), so the Eq. 5 mass (the impulse over the contact
//    / the change of normal velocity) is its mass with its normal added mass, M = (m + Ca rho A) L, and the
//    impact energy 1/2 M v0^2; it rebounds at e v0 (the hysteretic restitution law, ContactLaw.hpp).
// Tolerances: v0 0.5 % (the approach speed is the accepted state's before contact); the rebound ratio 2 %;
// M and the energy 2 %: the impulse also carries the weight over the contact, w L t_c with t_c = pi
// sqrt(m'/k) = 7 ms at the line stiffness 1e8 N/m/m, about 0.6 % of M (v0 + e v0).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/vessel/HullContact.hpp"

namespace tangle {
namespace {

constexpr double kLength = 10.0, kDiameter = 0.5, kMass = 300.0, kCa = 1.0, kDrop = 0.5, kTop = -15.0;
constexpr double kRho = 1025.0, kG = 9.80665;

std::string pieceAbovePontoon(double restitution) {
  const double z = kTop + 0.5 * kDiameter + kDrop;
  return fmt::format(R"(title: a pipe piece dropped onto a pontoon
environment: {{water_depth: 100, water_density: {rho}, gravity: {g}}}
line_types:
  - {{name: pipe, outer_diameter: {d}, mass_per_length: {m}, axial_stiffness: 1.0e10, bending_stiffness: 1.0e9,
     drag_normal: 0, drag_axial: 0, added_mass_normal: {ca}, added_mass_axial: 0}}
vessels:
  - name: pontoon
    mode: fixed
    position: [0, 0, 0]
    hull: [{{shape: box, centre: [0, 0, -20], size: [20, 20, 10]}}]
hull_contact: {{line_stiffness: 1.0e8, restitution: {e}, point_spacing: 0.5}}
lines:
  - name: piece
    end_a: {{type: free, position: [0, {y0}, {z}]}}
    end_b: {{type: free, position: [0, {y1}, {z}]}}
    sections: [{{type: pipe, length: {L}, elements: 10}}]
    start_shape: [[0, {y0}, {z}], [0, {y1}, {z}]]
statics: {{method: none}}
dynamics: {{duration: 0.9, time_step: 0.0005, output_interval: 0.1, ramp_time: 0}}
)",
                     fmt::arg("rho", kRho), fmt::arg("g", kG), fmt::arg("d", kDiameter), fmt::arg("m", kMass),
                     fmt::arg("ca", kCa), fmt::arg("e", restitution), fmt::arg("y0", -0.5 * kLength),
                     fmt::arg("y1", 0.5 * kLength), fmt::arg("z", z), fmt::arg("L", kLength));
}

TEST(LineOnHull, PieceDroppedOnAPontoonHasItsMassTheFallsEnergyAndTheRestitution) {
  constexpr double e = 0.5;
  analysis::Simulation sim(io::readModelString(pieceAbovePontoon(e), "pontoon.yaml"));
  const time::DynamicResult r = sim.runDynamics([](const model::State&, const VecX&) {});
  ASSERT_TRUE(r.completed) << r.message;
  const auto& events = sim.hullContact()->impacts().events();
  ASSERT_FALSE(events.empty());
  const vessel::HullImpact& hit = events.front();
  const double area = 0.25 * std::numbers::pi * kDiameter * kDiameter;
  const double massPerLength = kMass + kCa * kRho * area;
  const double g = (kMass - kRho * area) * kG / massPerLength;
  const double v0 = std::sqrt(2.0 * g * kDrop);
  const double mass = massPerLength * kLength;
  EXPECT_TRUE(hit.lineOnHull);
  EXPECT_EQ(hit.bodyA, "piece");
  EXPECT_EQ(hit.bodyB, "pontoon");
  EXPECT_NEAR(hit.impactVelocity / v0, 1.0, 0.005) << hit.impactVelocity << " m/s";
  EXPECT_NEAR(hit.reboundVelocity / (e * hit.impactVelocity), 1.0, 0.02) << hit.reboundVelocity << " m/s";
  EXPECT_NEAR(hit.eq5Mass / mass, 1.0, 0.02) << hit.eq5Mass << " kg";
  EXPECT_NEAR(hit.impactEnergy / (0.5 * mass * v0 * v0), 1.0, 0.02) << hit.impactEnergy << " J";
  EXPECT_NEAR(hit.position.z(), kTop + 0.5 * kDiameter, 0.01) << "on the top face";
}

TEST(LineOnHull, ALineThatStartsInsideAHullIsRefusedByName) {
  std::string yaml = pieceAbovePontoon(0.5);
  // The piece 2 m into the pontoon's top.
  const std::string z = fmt::format("{}", kTop + 0.5 * kDiameter + kDrop);
  const std::string inside = fmt::format("{}", kTop - 2.0);
  for (std::size_t at = yaml.find(z); at != std::string::npos; at = yaml.find(z))
    yaml.replace(at, z.size(), inside);
  try {
    analysis::Simulation sim(io::readModelString(yaml, "pontoon.yaml"));
    FAIL() << "a line inside a hull at the start must be refused";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("piece"), std::string::npos) << what;
    EXPECT_NE(what.find("pontoon"), std::string::npos) << what;
    EXPECT_NE(what.find("hull_contact.exclude"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tangle
