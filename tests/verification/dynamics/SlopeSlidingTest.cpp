// A chain laid along the fall line of a sloping seabed, released from rest (issue 46: friction along the
// local surface). Closed form (a block on an incline with Coulomb friction): the seabed's normal reaction is
// w cos(alpha) per metre and friction mu w cos(alpha) opposes the sliding, so the whole chain slides down
// with a = (w / m) (sin(alpha) - mu cos(alpha)) when mu < tan(alpha) and stays when mu > tan(alpha) (w the
// submerged weight and m the mass per metre; no axial drag or added mass: the motion is along the chain).
// Tolerance 1 % of the closed form's distance. Measured: without friction 13.87827 m against 13.87826 m
// (7e-7: generalized-alpha integrates a constant acceleration exactly); with mu = 0.2 6.2774 m against 6.2522
// m with either friction law (+0.40 %): friction takes hold during the first step (the elastic law's anchors
// are set where the nodes touch, the viscous law's force grows with the speed), after the initial
// acceleration was taken without it, and generalized-alpha carries that start-up difference (about mu g'
// cos(alpha) dt / 2 in velocity, 0.008 m/s) through the run. Held (mu = 0.5): 0.04 mm.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kSlopeDeg = 20.0, kLength = 20.0, kMass = 100.0, kDiameter = 0.1, kDuration = 3.0;

/// A 20 m chain on a seabed rising 20 degrees towards azimuth `rise`, laid along the fall line.
std::string chainOnSlope(double mu, const char* frictionModel, double rise) {
  const double slope = degToRad(kSlopeDeg), az = degToRad(rise);
  // The chain rests one radius above the seabed along its normal: its centreline is the plane lifted by
  // r / cos(alpha) (penetration 1e-5 m at this seabed stiffness, neglected).
  const double lift = 0.5 * kDiameter / std::cos(slope);
  const double run = kLength * std::cos(slope), climb = kLength * std::sin(slope);
  const double ax = 10.0 * std::cos(az), ay = 10.0 * std::sin(az);
  const double az0 = -100.0 + 10.0 * std::tan(slope) + lift;
  return fmt::format(R"(title: a chain sliding down a slope
environment:
  water_depth: 100
  seabed: {{slope: {slope}, upslope_azimuth: {rise}, normal_stiffness: 1.0e8, friction_coefficient: {mu},
           friction_model: {model}}}
line_types:
  - {{name: chain, outer_diameter: {d}, mass_per_length: {m}, axial_stiffness: 1.0e9, drag_normal: 0, drag_axial: 0,
     added_mass_axial: 0, axial_damping: 1.0e6}}
lines:
  - name: chain
    end_a: {{type: free, position: [{ax}, {ay}, {az0}]}}
    end_b: {{type: free, position: [{bx}, {by}, {bz}]}}
    sections: [{{type: chain, length: {L}, elements: 20}}]
    start_shape: [[{ax}, {ay}, {az0}], [{bx}, {by}, {bz}]]
dynamics: {{duration: {T}, time_step: 0.01, output_interval: 0.1, ramp_time: 0}}
)",
                     fmt::arg("slope", kSlopeDeg), fmt::arg("rise", rise), fmt::arg("mu", mu),
                     fmt::arg("model", frictionModel), fmt::arg("d", kDiameter), fmt::arg("m", kMass),
                     fmt::arg("ax", ax), fmt::arg("ay", ay), fmt::arg("az0", az0),
                     fmt::arg("bx", ax + run * std::cos(az)), fmt::arg("by", ay + run * std::sin(az)),
                     fmt::arg("bz", az0 + climb), fmt::arg("L", kLength), fmt::arg("T", kDuration));
}

/// Mean displacement [m] of the chain's nodes down the slope after kDuration of dynamics from rest.
double slideDistance(double mu, const char* frictionModel, double rise) {
  analysis::Simulation sim(io::readModelString(chainOnSlope(mu, frictionModel, rise), "slope.yaml"));
  const model::Model& m = sim.model();
  const model::Line& line = m.lines().front();
  const model::State start = sim.state();
  const time::DynamicResult run = sim.runDynamics([](const model::State&, const VecX&) {});
  EXPECT_TRUE(run.completed) << run.message;
  const double slope = degToRad(kSlopeDeg), az = degToRad(rise);
  const Vec3 down(-std::cos(slope) * std::cos(az), -std::cos(slope) * std::sin(az), -std::sin(slope));
  double sum = 0.0;
  for (int n = line.firstNode; n <= line.lastNode(); ++n) {
    const Vec3 d =
        sim.state().position[static_cast<std::size_t>(n)] - start.position[static_cast<std::size_t>(n)];
    sum += d.dot(down);
    // The chain stays on the seabed: no motion along the normal beyond a millimetre.
    EXPECT_LT((d - d.dot(down) * down).norm(), 1e-3) << "node " << n;
  }
  return sum / line.nodeCount;
}

double closedForm(double mu) {
  const double slope = degToRad(kSlopeDeg);
  const double area = 0.25 * kPi * kDiameter * kDiameter;
  const double w = (kMass - 1025.0 * area) * 9.80665;
  const double a = w / kMass * (std::sin(slope) - mu * std::cos(slope));
  return 0.5 * a * kDuration * kDuration;
}

TEST(SlopeSliding, ChainSlidesWithTheInclinesAccelerationElasticFriction) {
  const double expected = closedForm(0.2);  // 6.24 m
  EXPECT_NEAR(slideDistance(0.2, "elastic", 0.0), expected, 0.01 * expected);
}

TEST(SlopeSliding, ChainSlidesWithTheInclinesAccelerationViscousFrictionAnyAzimuth) {
  const double expected = closedForm(0.2);
  EXPECT_NEAR(slideDistance(0.2, "viscous", 135.0), expected, 0.01 * expected);
}

TEST(SlopeSliding, FrictionAboveTheSlopesTangentHoldsTheChain) {
  // mu = 0.5 > tan(20 deg) = 0.364: the elastic friction holds the chain (it settles by the stick springs'
  // stretch, mu w cos(alpha) / k_t < 1 mm); without friction it would slide 13.8 m.
  EXPECT_LT(std::abs(slideDistance(0.5, "elastic", 250.0)), 1e-3);
  EXPECT_NEAR(slideDistance(0.0, "elastic", 250.0), closedForm(0.0), 0.01 * closedForm(0.0));
}

}  // namespace
}  // namespace tangle
