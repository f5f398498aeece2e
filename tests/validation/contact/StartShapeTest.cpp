// Start shapes (issue 29): a line's starting shape given by intermediate points, so that a line can be
// draped over another before the static solve (the analytic catenary between the ends hangs below the
// other line and never touches it). Read from YAML, end to end.
//
// Set-up (in air, gravity 9.80665 m/s2): a taut wire along x, 10 m between pinned ends at z = 20 m
// (d = 0.1 m, 50 kg/m, EA 1e9 N, 5e5 N pretension); a chain (d = 0.1 m, 100 kg/m, EA 5e8 N, 7.4 m,
// 40 bars) pinned at y = -3 and 3 m, 2 m below the wire, across it at right angles. Its start shape: one
// point 0.12 m above the wire's axis (the radii are 0.1 m), so it starts as an inverted V over the wire.
//
// Checks:
// - the initial state is the polyline end A -> point -> end B, each node at its arc length in
//   proportion to the chords (to round-off);
// - the static solve settles it on the wire: the chain's highest node above the wire's axis by at least
//   the radii less the contact's penetration allowance (half the radii: the step validator's bound), and
//   the contact force equals the weight the contact carries, from the vertical equilibrium of the chain
//   as a free body with its support reactions (1e-5 of its weight: every nodal equilibrium holds to 1e-6
//   of the reference force, as StaticContactTest);
// - without the start shape the catenary hangs below the wire and there is no contact;
// - a start shape through the wire is refused before the solve, naming the key and both lines.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/ContactChecks.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

/// The model with `formulation` ("point", "distributed" or "" for the default) as contact.formulation.
std::string model(const std::string& startShape, const std::string& formulation = "") {
  return R"(title: chain draped over a taut wire by its start shape
environment:
  water_depth: 100
line_types:
  - {name: wire, outer_diameter: 0.1, mass_per_length: 50, axial_stiffness: 1.0e9}
  - {name: chain, outer_diameter: 0.1, mass_per_length: 100, axial_stiffness: 5.0e8}
lines:
  - name: wire
    end_a: {type: pinned, position: [-5, 0, 20]}
    end_b: {type: pinned, position: [5, 0, 20]}
    sections: [{type: wire, length: 9.995, elements: 10}]
  - name: chain
    end_a: {type: pinned, position: [0, -3, 18]}
    end_b: {type: pinned, position: [0, 3, 18]}
    sections: [{type: chain, length: 7.4, elements: 40}]
)" + startShape +
         (formulation.empty() ? std::string("contact: {}\n")
                              : "contact: {formulation: " + formulation + "}\n");
}

/// Both contact formulations (issue 43: the distributed one is the default).
class StartShapeStatics : public ::testing::TestWithParam<std::string> {};

TEST_P(StartShapeStatics, ChainDrapedOverAWireSettlesOnItInStatics) {
  analysis::Simulation sim(
      io::readModelString(model("    start_shape: [[0, 0, 20.12]]\n", GetParam()), "drape.yaml"));
  const model::Line& chain = sim.model().lines()[1];
  // The polyline: both legs 3.6069 m long, the apex at arc 3.7 m (node 20).
  const double leg = std::hypot(3.0, 2.12);
  for (int i = 0; i < chain.nodeCount; ++i) {
    const double s = chain.arcLength[i] * 2.0 * leg / chain.length;
    const Vec3 expected = s <= leg ? Vec3(0, -3, 18) + s / leg * Vec3(0, 3, 2.12)
                                   : Vec3(0, 0, 20.12) + (s - leg) / leg * Vec3(0, 3, -2.12);
    EXPECT_NEAR((sim.state().position[chain.firstNode + i] - expected).norm(), 0.0, 1e-12) << "node " << i;
  }

  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  double top = -1e30;
  for (int n = chain.firstNode; n <= chain.lastNode(); ++n) top = std::max(top, sim.state().position[n].z());
  const double wireZ = sim.state().position[sim.model().lines()[0].firstNode + 5].z();
  EXPECT_GT(top - wireZ, 0.5 * 0.1);

  const auto lines = sim.snapshot(false);
  const double contactZ = sim.contact()->pairForce(1, 0).z();  // on the chain
  const double weight = 100.0 * chain.length * sim.model().environment().gravity;
  EXPECT_GT(contactZ, 0.5 * weight);
  EXPECT_NEAR(contactZ, weight + lines[1].endForceA.z() + lines[1].endForceB.z(), 1e-5 * weight);
}

TEST(StartShape, WithoutItTheCatenaryHangsBelowTheWire) {
  analysis::Simulation sim(io::readModelString(model(""), "hanging.yaml"));
  ASSERT_TRUE(sim.solveStatics().converged);
  EXPECT_EQ(test::pressedContact(*sim.contact(), 1, 0).points, 0);
}

TEST(StartShape, AShapeThroughAnotherLineIsRefused) {
  try {
    analysis::Simulation sim(
        io::readModelString(model("    start_shape: [[0, -0.5, 20.12], [0, 0.5, 19.9]]\n"), "crossed.yaml"));
    FAIL() << "no InputError for a start shape through the wire";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), "lines[chain].start_shape") << what;
    EXPECT_NE(what.find("passes through"), std::string::npos) << what;
    EXPECT_NE(what.find("'wire'"), std::string::npos) << what;
    EXPECT_NE(what.find("crossed.yaml"), std::string::npos) << what;
  }
}

// Friction at a crossing in statics (issue 29: point contacts had friction in dynamics only). The same
// chain draped over the wire, the wire now inclined at 10 deg along its axis (ends at z = 20 -+ 5 tan 10).
// Without friction the chain slides down the wire until its lean balances the slope component of the
// contact force (measured: 0.61 m down, x = -0.61 m); with mu = 0.5 > tan 10 deg = 0.18 the elastic
// stick of the point contacts holds it where it was laid (measured x = +0.02 m, the stick spring's
// give; both feet stick with 1249 N of friction each against 0.5 x 4806 N). The two feet of the fold lie
// on one element of the wire: their anchors are keyed by both elements (one anchor for both made the
// second foot pull from the first's material point: 1300 N out of balance along x). Checks: the
// contact's position along x; every point contact's friction force within mu times its normal force and
// not zero; the chain's equilibrium along x as a free body: the contact forces (normal and friction)
// against its support reactions, to 1e-5 of its weight (every nodal equilibrium holds to 1e-6 of the
// reference force).
std::string inclinedModel(double mu, const std::string& formulation) {
  std::string yaml = model("    start_shape: [[0, 0, 20.12]]\n", formulation);
  const std::string from = "position: [-5, 0, 20]}", to = "position: [5, 0, 20]}";
  yaml.replace(yaml.find(from), from.size(), "position: [-5, 0, 19.11838]}");
  yaml.replace(yaml.find(to), to.size(), "position: [5, 0, 20.88162]}");
  yaml.replace(yaml.find("length: 9.995"), 13, "length: 10.149");
  yaml.replace(yaml.find("contact: {"), 10, "contact: {friction_coefficient: " + std::to_string(mu) + ", ");
  return yaml;
}

/// Where along x the contact presses on the wire (normal-force-weighted) [m].
double contactX(analysis::Simulation& sim) { return test::pressedContact(*sim.contact(), 0, 1).centre.x(); }

TEST_P(StartShapeStatics, FrictionAtTheCrossingHoldsTheDrapeOnAnInclinedWire) {
  analysis::Simulation frictionless(io::readModelString(inclinedModel(0.0, GetParam()), "inclined.yaml"));
  ASSERT_TRUE(frictionless.solveStatics().converged);
  EXPECT_LT(contactX(frictionless), -0.3);

  constexpr double kMu = 0.5;
  analysis::Simulation sim(io::readModelString(inclinedModel(kMu, GetParam()), "inclined-friction.yaml"));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  EXPECT_NEAR(contactX(sim), 0.0, 0.05);
  const auto lines = sim.snapshot(false);
  const test::PressedContact pressed = test::pressedContact(*sim.contact(), 1, 0);
  ASSERT_GE(pressed.points, 1);
  if (GetParam() == "point") {  // the point formulation's feet of the fold, each holding
    int held = 0;
    for (const contact::FrictionPatch& p : sim.contact()->frictionPatches()) {
      if (!p.point) continue;
      ++held;
      EXPECT_LE(p.force.norm(), kMu * p.normalLoad * (1.0 + 1e-9));
      EXPECT_GT(p.force.norm(), 0.01 * p.normalLoad);
    }
    EXPECT_GE(held, 1);
  } else {  // every Gauss point within Coulomb's cone, and friction acting
    EXPECT_LE(pressed.frictionRatioMax, kMu * (1.0 + 1e-9));
    EXPECT_GT(pressed.frictionRatioMax, 0.01);
  }
  const Vec3 onChain = -sim.contact()->pairForce(0, 1);
  const double weight = 100.0 * sim.model().lines()[1].length * sim.model().environment().gravity;
  EXPECT_NEAR(onChain.x(), lines[1].endForceA.x() + lines[1].endForceB.x(), 1e-5 * weight);
}

INSTANTIATE_TEST_SUITE_P(Formulations, StartShapeStatics, ::testing::Values("point", "distributed"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

}  // namespace
}  // namespace tangle
