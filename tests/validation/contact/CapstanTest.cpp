// Issue 29: belt friction (the capstan). A rope wrapped half way round a fixed bollard, a weight on one
// end, the other end pulled down slowly: during steady slip the tension on the pulled side is
// exp(mu theta) times the tension on the weight's side, theta = pi (Euler-Eytelwein; e.g. Meriam &
// Kraige, Statics, sec. 6/8).
//
// Set-up (in air, gravity 9.80665 m/s2): the bollard is a fixed steel beam along y, contact diameter
// 0.5 m. The rope (cable, 20 mm, 1 kg/m, EA 2e6 N) is laid over it by `start_shape`: up from the weight
// 1 m below the bollard's axis on the -x side, half round the top (16 elements on the arc, a kink of 11
// deg per node) and down 1 m on the +x side to end B. End A is free and carries a 50 kg weight; end B is
// pinned and pulled down (prescribed motion, amplitude 1 m, period 200 s: 0.031 m/s, three times the
// point formulation's friction regularisation velocity, within 2 % of constant over the measurement). Contact
// friction mu = 0.3. A mass-proportional damping of 2 1/s stands for the air and settles the start.
//
// Measured over t = 4-8 s of steady slip: T_pulled / T_weight, with T_pulled = end B's tension plus the
// weight of the 1 m leg above it (the tension where the rope leaves the bollard) and T_weight = the
// weight 50 g plus its leg's 1 m of rope (the weight rises at 0.031 m/s: its inertia is nil, the
// damping's force alpha M v = 3 N, 0.6 %, is added to it). Tolerance 3 % (the bound): the
// polyline wraps the bollard in 16 straight pieces, contact points at the nodes, so the wrap angle is
// pi within the first and last half kink (~3 %/2 at the ends), and the regularised friction is full at
// the slip speed.
//
// The point formulation's run (CapstanKnownFailures, run by ctest as expected to fail,
// validation.point_capstan_expected_fail) stops at t = 0.015 s, as the rope settles onto the bollard, with
// and without friction ("Newton did not converge even with the minimum time step"). What was found (theory
// 11): the contact of a cable wrapped round a line has every node of the wrap at the same distance from the
// line's axis, a continuum of minima. The contact keeps one point per local minimum of the distance, so
// only two or three nodes of the 16 carry force and the nodes between sink into the bollard; Newton then
// cycles between sets of minima. Keeping every node of the wrap (each element held at its own node is a
// distinct contact) removes the cycling but exposes a second inconsistency: the step look-ahead measures
// the rope's chords, which cut inside the circle by R (1 - cos 5.6 deg) = 1.2 mm, and sees a contact
// already made where the contact (on the nodes) sees a 1 mm gap, so the landing of the rope is not
// resolved (impact duration 0.35 ms) and the active set pulls with 1e5 N. Wrap contact wants a
// distributed (Gauss point to line) contact along the rope at any crossing angle, which the
// point-to-point branch of the all-angle blending (9.0) does not give.

// With the distributed formulation (issue 43: Gauss points along the rope against the bollard's C1
// centreline, theory 9.11) the run goes through, and the test passes. Measured 2026-11-29 with the friction
// on the committed slip (exactly mu f_n in slip, no regularisation velocity) and the law scaled with the
// rope's diameter: mean ratio 2.5658 (-0.02 %), min 2.5480, max 2.5789, against exp(0.3 pi) = 2.5663;
// 34 s CPU. (With a velocity-regularised friction and the law scaled with the sum of the radii it was 2.5518,
// a cancellation of -4.8 % from the regularisation and +4.4 % from the rope sinking 3 cm into the bollard.)
// The point formulation's test stays a known failure with the reason above.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kPi = 3.141592653589793;

/// The capstan run with either contact formulation; expects the tension ratio within 3 %.
void runCapstan(bool distributed) {
  constexpr double kBollardDiameter = 0.5, kRopeDiameter = 0.02, kRopeMass = 1.0, kRopeEA = 2.0e6;
  constexpr double kLeg = 1.0, kWeight = 50.0, kMu = 0.3, kDamping = 2.0;
  constexpr int kArcElements = 16, kLegElements = 10;
  model::ModelSpec spec;
  spec.sourceFile = "capstan (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["bollard"] = test::solidRodType("bollard", kBollardDiameter, 2.1e11, 7850.0);
  spec.lineTypes["rope"] = test::cableType("rope", kRopeDiameter, kRopeMass, kRopeEA);
  const double z = 10.0;           // bollard axis, in air
  constexpr double kRopeY = 0.25;  // over the middle of a bollard element
  const double radius = 0.5 * (kBollardDiameter + kRopeDiameter) + 0.001;
  const double arc = kPi * radius;
  model::LineSpec bollard = test::simpleLine("bollard", "bollard", 2.0, 4, model::EndKind::Fixed,
                                             Vec3(0, -1, z), model::EndKind::Fixed, Vec3(0, 1, z));
  model::LineSpec rope;
  rope.name = "rope";
  rope.endA.kind = model::EndKind::Free;
  rope.endA.position = Vec3(-radius, kRopeY, z - kLeg);
  rope.endB.kind = model::EndKind::Pinned;
  rope.endB.position = Vec3(radius, kRopeY, z - kLeg);
  rope.endB.motion.enabled = true;
  rope.endB.motion.amplitude = Vec3(0, 0, -1.0);
  rope.endB.motion.period = 200.0;
  rope.sections = {{"rope", kLeg, kLegElements}, {"rope", arc, kArcElements}, {"rope", kLeg, kLegElements}};
  for (int i = 0; i <= kArcElements; ++i) {
    const double phi = kPi * i / kArcElements;  // from the -x side over the top
    model::StartPoint p;
    p.position = Vec3(-radius * std::cos(phi), kRopeY, z + radius * std::sin(phi));
    p.arcLength = kLeg + arc * i / kArcElements;
    rope.startShape.push_back(p);
  }
  model::AttachmentSpec weight;
  weight.arcLength = 0.0;
  weight.mass = kWeight;
  rope.attachments.push_back(weight);
  spec.lines = {bollard, rope};
  spec.contact.enabled = true;
  spec.contact.restitution = 0.5;
  spec.contact.frictionCoefficient = kMu;
  spec.contact.pairs = {{"bollard", "rope"}};
  spec.contact.formulation =
      distributed ? model::ContactFormulation::Distributed : model::ContactFormulation::Point;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 8.0;
  spec.dynamics.timeStep = 0.005;
  spec.dynamics.outputInterval = 0.1;
  spec.dynamics.rampTime = 1.0;
  spec.dynamics.rayleighAlpha = kDamping;

  analysis::Simulation sim(std::move(spec));
  double sumRatio = 0.0;
  int samples = 0;
  double minRatio = 1e9, maxRatio = 0.0;
  const double g = kStandardGravity;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    if (s.time < 4.0 - 1e-9) return;
    const auto lines = sim.snapshot(true);
    const double pulled = lines[1].endTensionB + kRopeMass * g * kLeg;
    const double slip = 2.0 * kPi / 200.0 * std::cos(2.0 * kPi * s.time / 200.0);  // end B's speed
    const double held = kWeight * g + kDamping * kWeight * slip + kRopeMass * g * kLeg;
    const double ratio = pulled / held;
    sumRatio += ratio;
    minRatio = std::min(minRatio, ratio);
    maxRatio = std::max(maxRatio, ratio);
    ++samples;
  });
  ASSERT_TRUE(run.completed) << run.message;
  ASSERT_GT(samples, 10);
  const double expected = std::exp(kMu * kPi);
  const double mean = sumRatio / samples;
  EXPECT_NEAR(mean, expected, 0.03 * expected);
  EXPECT_NEAR(minRatio, expected, 0.03 * expected);
  EXPECT_NEAR(maxRatio, expected, 0.03 * expected);
  ::testing::Test::RecordProperty("tension_ratio_mean", fmt::format("{:.4f}", mean));
  ::testing::Test::RecordProperty("tension_ratio_min", fmt::format("{:.4f}", minRatio));
  ::testing::Test::RecordProperty("tension_ratio_max", fmt::format("{:.4f}", maxRatio));
  ::testing::Test::RecordProperty("exp_mu_theta", fmt::format("{:.4f}", expected));
}

TEST(CapstanKnownFailures, PointTensionRatioDuringSlipIsExpMuTheta) { runCapstan(false); }

// The distributed formulation (issue 43): Gauss points along the rope against the bollard's C1 centreline.
TEST(Capstan, DistributedTensionRatioDuringSlipIsExpMuTheta) { runCapstan(true); }

}  // namespace
}  // namespace tangle
