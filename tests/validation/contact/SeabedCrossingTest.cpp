// A mooring chain laid across a pipeline on the seabed (a new user's model, 2026-12-04): the program's start
// shapes of the two lines pass through each other (both rest on the seabed, the chain's axis 0.13 m below the
// pipeline's, their surfaces 0.14 m into each other), and statics used to push the chain *under* the
// pipeline, 7.6 cm into the soil, lifting the pipeline onto it (39 kN, a 117 kN m moment in the pipeline),
// without a word. Now a line listed later is laid over one listed earlier (contact/StartShapeCrossings.hpp,
// docs/theory.md 2.4), and the run log says so.
//
// Set-up: water 100 m deep, seabed 1e5 N/m/m without friction (so that the laid chain's tension is its
// anchor's, not the statics path's); a 16 in pipeline (0.4064 m, 250 kg/m, EI 1.2e8 N m2) anchored at both
// ends along y; a 76 mm studless chain (0.1368 m, 114.9 kg/m, EA 4.93e8 N) along x from an anchor at
// x = -250 m to a fairlead 10 m below the surface at x = 250 m, 560 m long, on 0.5 m bars over the 30 m
// around the crossing at x = 0 (5 m elsewhere).
//
// Checks:
// - the chain rests on the pipeline: at the crossing its axis lies the sum of the radii above the
//   pipeline's, less the contact's penetration (2.9 mm measured: the crossing's Hertz-like law at 16 kN;
//   k = 0.1 EA / (20 (r_a + r_b)) = 9.1e6 N/m gives 1.8 mm as a point spring), allowed 3 % of the radii;
// - the contact force against the closed form of a string of weight w per length and tension T lifted at a
//   point to a height h above its resting level on a Winkler foundation of stiffness k (derived below):
//   each side lifts off over x_l, the root of w x^2 / (2 T) + w x / sqrt(k T) + w / k - h = 0, and the
//   lifted length and the foundation's relief carry F = 2 w (x_l + sqrt(T / k)). T is the anchor's
//   tension (the laid chain has no friction), h the chain's height at the crossing over a laid node far
//   from it. Tolerance 2 %: the closed form is a shallow string (slopes below 0.1 here: the arc and the
//   horizontal length differ by 0.5 %), and the 0.5 m bars resolve the 5 m lift-off by 10 elements;
//   the pipeline's own deflection is in the measured h.
// - the other order: with the chain listed first, the pipeline is laid over the chain (the rule, not
//   physics, decides; statics must hold it there).
//
// Derivation of the closed form: with u the height above the resting level, the supported part obeys
// T u'' = k u (the foundation's reaction w - k u), so u = (w / k) e^(-(x - x_l) / lambda), lambda =
// sqrt(T / k), up to the lift-off point x_l where the reaction vanishes (u = w / k, u' = -w / (k lambda));
// the lifted part obeys T u'' = w, a parabola through u(0) = h with slope -F / (2 T) at the crossing.
// Matching u and u' at x_l gives the quadratic above and F = 2 T (w x_l / T + w / sqrt(k T)).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kPipeRadius = 0.5 * 0.4064;   // [m]
constexpr double kChainRadius = 0.5 * 0.1368;  // [m]
constexpr double kSeabedStiffness = 1.0e5;     // [N/m/m]

std::string crossingYaml(bool chainFirst) {
  const std::string pipeline = R"(
  - name: pipeline
    end_a: {type: anchored, position: [0, -150, -100]}
    end_b: {type: anchored, position: [0, 150, -100]}
    sections: [{type: pipe16, length: 300, elements: 60}])";
  const std::string chain = R"(
  - name: chain
    end_a: {type: anchored, position: [-250, 0, -100]}
    end_b: {type: pinned, position: [250, 0, -10]}
    sections:
      - {type: chain76, length: 235, elements: 47}
      - {type: chain76, length: 30, elements: 60}
      - {type: chain76, length: 295, elements: 59})";
  return R"(title: a mooring chain laid across a pipeline
environment:
  water_depth: 100
  seabed: {normal_stiffness: 1.0e5, friction_coefficient: 0}
line_types:
  - {name: chain76, outer_diameter: 0.1368, mass_per_length: 114.9, axial_stiffness: 4.93e8}
  - {name: pipe16, outer_diameter: 0.4064, mass_per_length: 250, axial_stiffness: 6.0e9, bending_stiffness: 1.2e8, torsional_stiffness: 9.0e7}
lines:)" +
         (chainFirst ? chain + pipeline : pipeline + chain) + "\ncontact: {}\n";
}

/// The node of a line nearest the plane x = 0 (the chain) or y = 0 (the pipeline).
int nodeAtCrossing(const solver::LineSnapshot& line, int axis) {
  int best = 0;
  for (int i = 0; i < static_cast<int>(line.position.size()); ++i)
    if (std::abs(line.position[i][axis]) < std::abs(line.position[best][axis])) best = i;
  return best;
}

TEST(SeabedCrossing, ChainLaidAcrossAPipelineRestsOnItWithTheStringForce) {
  analysis::Simulation sim(io::readModelString(crossingYaml(false), "crossing.yaml"));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_EQ(sim.startShapeLifts().size(), 1u);
  EXPECT_EQ(sim.startShapeLifts()[0].upperLine, 1);  // the chain, listed second
  EXPECT_GT(sim.startShapeLifts()[0].direction.z(), 0.99);
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto lines = sim.snapshot(false);
  const solver::LineSnapshot &pipe = lines[0], &chain = lines[1];
  const int c = nodeAtCrossing(chain, 0), p = nodeAtCrossing(pipe, 1);
  const double above = chain.position[c].z() - pipe.position[p].z();  // [m]
  EXPECT_GT(above, 0.97 * (kPipeRadius + kChainRadius));
  EXPECT_LT(above, kPipeRadius + kChainRadius);

  // The closed form (file comment).
  const double g = 9.80665;
  const double w = (114.9 - 1025.0 * 0.25 * M_PI * 0.1368 * 0.1368) * g;  // [N/m]
  const double tension = chain.endTensionA;                               // [N]
  const double rest = chain.position[20].z();  // a laid node 100 m from the anchor [m]
  const double h = chain.position[c].z() - rest;
  const double k = kSeabedStiffness;
  const double qa = w / (2.0 * tension), qb = w / std::sqrt(k * tension), qc = w / k - h;
  const double liftOff = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);  // [m]
  const double expected = 2.0 * w * (liftOff + std::sqrt(tension / k));            // [N]
  const double force = sim.contact()->pairForce(1, 0).z();                         // on the chain, upwards
  EXPECT_NEAR(force, expected, 0.02 * expected) << "h " << h << " m, T " << tension << " N, x_l " << liftOff;
  RecordProperty("contact_force_N", std::to_string(force));
  RecordProperty("closed_form_N", std::to_string(expected));
}

TEST(SeabedCrossing, WithTheChainListedFirstThePipelineIsLaidOverIt) {
  analysis::Simulation sim(io::readModelString(crossingYaml(true), "crossing.yaml"));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_EQ(sim.startShapeLifts().size(), 1u);
  EXPECT_EQ(sim.startShapeLifts()[0].upperLine, 1);  // the pipeline, listed second
  ASSERT_TRUE(statics.converged) << statics.message;
  const auto lines = sim.snapshot(false);
  const solver::LineSnapshot &chain = lines[0], &pipe = lines[1];
  const double above =
      pipe.position[nodeAtCrossing(pipe, 1)].z() - chain.position[nodeAtCrossing(chain, 0)].z();
  EXPECT_GT(above, 0.97 * (kPipeRadius + kChainRadius));
}

}  // namespace
}  // namespace tangle
