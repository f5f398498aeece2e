// No tunnelling: a fast line hits another with a nominal time step in which it would travel ten times the
// sum of the two diameters (issue 4: the contact search must not let lines pass through each other
// between steps; the seed paper, Silva, Pereira & Jacob 2007, section 5, finds the contact point at every
// step, which alone does not prevent it).
//
// Set-up (in air, gravity 0): line A is a taut wire along x, 10 m between pinned ends, 10 elements,
// d = 0.05 m, 10 kg/m, EA = 1e8 N, pretension 100 kN. Line B is a free steel bar, d = 0.05 m, 2 m long, one
// element, along y, crossing above A at x = 0.3 m (inside an element of A), 0.4 m above it, moving down at
// 20 m/s. Nominal step 0.05 s: B would move 1 m per step, ten times the sum of the diameters (0.1 m); the
// impact (automatic stiffness 1e7 N/m) lasts ~3 ms, a sixteenth of a step. The wire is a trampoline: it
// throws B back and catches up with it a few times (4 contact events, all within 0.11 s).
//
// Checks:
// - Control: the same model run with the contact forces but without the step limiter and the step
//   validator (a plain fixed-step scheme with a penalty contact) ended with B below A before issue 29;
//   since the contact pushes an iterate that passed through back to the side of the step's start, B
//   stays above A, with an unresolved impact.
// - With them (Simulation::runDynamics): B stays above A at every output (every nominal step; the sign
//   of the vertical separation of the crossing points, the initial normal, is kept) and leaves upwards;
//   the first contact event is the impact at the relative normal speed of 20 m/s (to 0.1 %: B's speed
//   changes by less over the approach); no event penetrates deeper than half the sum of the radii (the
//   step validator's bound; measured 30 % in the 20 m/s impact), all events are closed at the end.
// - The step grows back after the impacts: from one nominal step after the end of the last event, no step
//   shorter than 1/20 of the nominal (impact steps are 1/1000 of it), not impact-sized steps throughout.
//   Under the point formulation, also at most 100 steps per contact event (approach halving, 40 impact steps,
//   twofold regrowth) on top of the 40 nominal steps (measured: 387 steps for 4 events); the distributed
//   one (the default, issue 43) has one 90 ms event instead, resolved at its stiffness's steps.
//
// Spectral radius 0.5 instead of the default 0.8: with 0.8 the wire's axial modes (omega dt ~ 300 at the
// nominal step) keep spurious node velocities of 100 to 5000 m/s at intermediate steps after the impact
// (10 m/s at the output times), which the contact look-ahead takes for real approach speeds: the steps
// then stay at 1e-4 to 1e-3 s (2187 steps, 241 cut-backs). This is the integrator's high-frequency
// velocity overshoot, reported; 0.5 damps those modes within a few steps.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/ContactChecks.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"

namespace tangle {
namespace {

constexpr double kHeight = 10.0, kD = 0.05, kSpeed = 20.0, kClearance = 0.4, kCrossX = 0.3;
constexpr double kTimeStep = 0.05, kDuration = 2.0;

model::ModelSpec tunnellingModel(
    model::ContactFormulation formulation = model::ContactFormulation::Distributed) {
  model::ModelSpec spec;
  spec.sourceFile = "tunnelling (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 0.0;
  spec.lineTypes["wire"] = test::cableType("wire", kD, 10.0, 1e8);
  spec.lineTypes["beam"] = test::solidRodType("beam", kD, 2.1e11, 7850.0);
  const double zB = kHeight + kD + kClearance;
  spec.lines = {test::simpleLine("wire", "wire", 10.0 / (1.0 + 1e5 / 1e8), 10, model::EndKind::Pinned,
                                 Vec3(-5.0, 0, kHeight), model::EndKind::Pinned, Vec3(5.0, 0, kHeight)),
                test::simpleLine("fast", "beam", 2.0, 1, model::EndKind::Free, Vec3(kCrossX, -1.0, zB),
                                 model::EndKind::Free, Vec3(kCrossX, 1.0, zB))};
  spec.contact.enabled = true;
  spec.contact.formulation = formulation;
  spec.contact.restitution = 0.5;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = kDuration;
  spec.dynamics.timeStep = kTimeStep;
  spec.dynamics.minTimeStep = 1e-7;
  spec.dynamics.outputInterval = kTimeStep;
  spec.dynamics.rampTime = 0.0;
  spec.dynamics.spectralRadius = 0.5;  // see the file comment
  return spec;
}

/// Vertical separation of B's middle from A at the crossing (A's height interpolated at x = kCrossX) [m].
double separation(const model::Model& m, const model::State& s) {
  const model::Line& a = m.lines()[0];
  const model::Line& b = m.lines()[1];
  const Vec3 mid = 0.5 * (s.position[b.firstNode] + s.position[b.lastNode()]);
  for (int n = a.firstNode; n < a.lastNode(); ++n) {
    const Vec3& p = s.position[n];
    const Vec3& q = s.position[n + 1];
    if (p.x() <= mid.x() && mid.x() <= q.x())
      return mid.z() - (p.z() + (mid.x() - p.x()) / (q.x() - p.x()) * (q.z() - p.z()));
  }
  return mid.z() - kHeight;  // outside A's span (not expected)
}

void launch(analysis::Simulation& sim) {
  const model::Line& b = sim.model().lines()[1];
  for (int n = b.firstNode; n <= b.lastNode(); ++n)
    sim.state().velocity[sim.model().dofs().firstDof(n) + 2] = -kSpeed;
}

TEST(Tunnelling, PlainFixedStepsNoLongerPassThrough) {
  analysis::Simulation sim(tunnellingModel(model::ContactFormulation::Point));
  ASSERT_TRUE(sim.solveStatics().converged);
  launch(sim);
  // The integrator with the contact forces, without the step limiter and the validator.
  time::DynamicAnalysis plain(sim.assembler(), sim.model().spec().dynamics);
  plain.setStepControl(false);
  const time::DynamicResult run = plain.run(sim.state());
  ASSERT_TRUE(run.completed) << run.message;
  // Before issue 29 B passed through A here (the control proved the set-up tunnels). The contact now tells
  // the side of each element pair from its chords at the step's start, so the iterate that overshoots by
  // 0.6 m is pushed back: B ends above A even without the step control, but the impact is not resolved
  // (one 0.05 s step against a 3 ms impact): it leaves at 6.0 m/s (measured) instead of the resolved run's
  // speed, and the step control remains what makes the impact physical (next test).
  const model::Line& b = sim.model().lines()[1];
  double upwards = 0.0;
  for (int n = b.firstNode; n <= b.lastNode(); ++n)
    upwards += sim.state().velocity[sim.model().dofs().firstDof(n) + 2] / b.nodeCount;
  RecordProperty("final_upward_speed", fmt::format("{:.3g}", upwards));
  EXPECT_GT(separation(sim.model(), sim.state()), 0.0) << "B passed through A";
}

// The distributed formulation (issue 43) holds no side per pair: its barrier filters each step's predictor
// and Newton corrections instead, so that no iterate passes it (before the predictor was filtered, B
// ended 12.2 m below A here).
TEST(Tunnelling, DistributedPlainFixedStepsDoNotPassThrough) {
  analysis::Simulation sim(tunnellingModel(model::ContactFormulation::Distributed));
  ASSERT_TRUE(sim.solveStatics().converged);
  launch(sim);
  time::DynamicAnalysis plain(sim.assembler(), sim.model().spec().dynamics);
  plain.setStepControl(false);
  double smallest = 1e30;
  plain.setObserver(
      [&](const model::State& s, const VecX&) { smallest = std::min(smallest, separation(sim.model(), s)); });
  const time::DynamicResult run = plain.run(sim.state());
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_GT(smallest, 0.0) << "B passed through A";
  EXPECT_GT(separation(sim.model(), sim.state()), 0.0) << "B passed through A";
}

class TunnellingRun : public ::testing::TestWithParam<model::ContactFormulation> {};

TEST_P(TunnellingRun, FastLineDoesNotPassThroughAndTheStepGrowsBack) {
  analysis::Simulation sim(tunnellingModel(GetParam()));
  ASSERT_TRUE(sim.solveStatics().converged);
  launch(sim);
  double smallest = 1e30;
  std::vector<double> stepEnds;  // time at the end of every accepted step [s]
  const time::DynamicResult run = sim.runDynamics(
      [&](const model::State& s, const VecX&) { smallest = std::min(smallest, separation(sim.model(), s)); },
      false, [&](const model::State& s, double) { stepEnds.push_back(s.time); });
  ASSERT_TRUE(run.completed) << run.message;
  // Output every nominal step: B stays above A (its centreline never below A's), and ends well above.
  EXPECT_GT(smallest, 0.0);
  EXPECT_GT(separation(sim.model(), sim.state()), kD + kClearance);
  const model::Line& b = sim.model().lines()[1];
  EXPECT_GT(sim.state().velocity[sim.model().dofs().firstDof(b.firstNode) + 2], 5.0);

  const auto& events = sim.contact()->events();
  ASSERT_GE(events.size(), 1u);
  EXPECT_NEAR(events[0].impactVelocity, kSpeed, 1e-3 * kSpeed);
  double deepest = 0.0;
  for (const contact::ContactEvent& e : events) {
    EXPECT_FALSE(e.open);
    deepest = std::max(deepest, e.maxPenetration);
  }
  EXPECT_LT(deepest, 0.5 * kD);  // half the sum of the radii (rejectStep's bound)
  RecordProperty("events", static_cast<int>(events.size()));
  test::expectImpactEnergiesWithinBounds(events);
  RecordProperty("deepest_penetration_over_radii_sum", fmt::format("{:.3f}", deepest / kD));

  // Grown back: from one nominal step after the end of the last event, no step shorter than 1/20 of the
  // nominal one (the impact's steps are 1/1000 of it; what still shortens some there is the wire's axial
  // ringing, the cable snap limit, not the contact).
  double lastEnd = 0.0;
  for (const contact::ContactEvent& e : events) lastEnd = std::max(lastEnd, e.endTime);
  double shortestAfter = kTimeStep;
  for (std::size_t i = 1; i < stepEnds.size(); ++i)
    if (stepEnds[i - 1] > lastEnd + kTimeStep)
      shortestAfter = std::min(shortestAfter, stepEnds[i] - stepEnds[i - 1]);
  EXPECT_GT(shortestAfter, kTimeStep / 20.0) << "last event ended at " << lastEnd << " s";
  // The point formulation's four short bounces: at most 100 steps each. (The distributed contact is one
  // event of 90 ms, the bar riding the wire's trampoline on its softer Hertz-like crossing, resolved with
  // steps of 5e-5 s, 40 per period of its stiffness against the pair mass: 535 steps in all.)
  if (GetParam() == model::ContactFormulation::Point) {
    EXPECT_LT(run.steps, static_cast<int>(kDuration / kTimeStep) + 100 * static_cast<int>(events.size()));
  }
  RecordProperty("steps", run.steps);
  RecordProperty("shortest_step_after_the_last_event", fmt::format("{:.3e}", shortestAfter));
  RecordProperty("last_event_end", fmt::format("{:.4f}", lastEnd));
  RecordProperty("cutbacks", run.cutbacks);
}

INSTANTIATE_TEST_SUITE_P(Formulations, TunnellingRun, test::bothFormulations(), test::formulationTestName);

}  // namespace
}  // namespace tangle
