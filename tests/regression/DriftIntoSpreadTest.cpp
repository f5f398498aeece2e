// Regression: the seed paper's application with the production system as the paper has it
// (examples/drift-into-spread, issue 29): the production unit free on eight chain-wire-chain legs, the
// DP unit drifting with its riser hung, contact allowed between the riser and every leg. Run to 165 s
// (the collision is at 150.9 s; the example runs the paper's 200 s). Asserts: statics puts the unit on its
// legs (offset along the current, within the 16.4 m of the example's README, 0.5 m); the run completes;
// the riser hits the leg towards 180 deg and no other; the impact is measured consistently (Eq. 5 and the
// absorbed work within the factor 2 of the warning, mass above one element of each line) at the speed
// of the example (0.445 m/s, 2 %: this test runs the same model, only shorter); the production unit moves
// less than a metre (its legs hold it against a contact force of tens of kN).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "TestPaths.hpp"
#include "support/ContactChecks.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

TEST(DriftIntoSpread, RiserHitsTheOneLegInItsWayAndTheMooredUnitHolds) {
  model::ModelSpec spec =
      io::readModelFile(std::string(test::kExamplesDir) + "/drift-into-spread/model.yaml");
  spec.dynamics.duration = 165.0;
  spec.output.plots = false;
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  ASSERT_TRUE(statics.converged) << statics.message;
  const model::Model& m = sim.model();
  int production = -1;
  for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v)
    if (m.vessels()[v].name == "production_unit") production = v;
  ASSERT_GE(production, 0);
  const Vec3 start = sim.vessels()->vesselPoint(sim.state(), production, Vec3::Zero());
  EXPECT_NEAR(std::hypot(start.x(), start.y()), 16.4, 0.5);
  EXPECT_LT(start.x(), 0.0);  // pushed along the current, towards 225 deg
  EXPECT_LT(start.y(), 0.0);

  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;

  std::vector<contact::ContactEvent> events = sim.contact()->events();
  events.insert(events.end(), sim.contact()->openEvents().begin(), sim.contact()->openEvents().end());
  ASSERT_EQ(events.size(), 1u);
  const contact::ContactEvent& hit = events.front();
  const std::string leg =
      m.lines()[hit.lineA].name == "riser" ? m.lines()[hit.lineB].name : m.lines()[hit.lineA].name;
  EXPECT_EQ(leg, "leg5");  // towards 180 deg
  EXPECT_TRUE(hit.impact);
  EXPECT_NEAR(hit.impactVelocity, 0.445, 0.02 * 0.445);
  test::expectImpactEnergiesWithinBounds(sim.contact()->events());
  EXPECT_GT(hit.phaseWork, 0.0);
  EXPECT_LT((sim.vessels()->vesselPoint(sim.state(), production, Vec3::Zero()) - start).norm(), 1.0);
}

// Issue 43: the same example run on to 300 s stops with the point formulation at t = 255.5 s ("Newton did
// not converge even with the minimum time step 1e-05 s; largest out-of-balance force 3.4e4 N at line 'leg5'
// node 118": the wire kinked over the riser at a node). With `contact.formulation: distributed` it runs
// through (measured 2026-11-29 with the CLI, output included: 30 335 steps, 35.8 s CPU against 31.3 s for
// the point formulation's 255.5 s). Asserts: the run completes; one event, leg5 against the riser, the impact
// at the example's speed (2 %) with its energies within the bounds; the contact slides along the wire (more
// than 20 m: it went from 764 to 700 m along leg5 and is still on at 300 s), and its deepest penetration
// stays below the barrier's bound, half the sum of the radii (measured 21 mm).
TEST(DriftIntoSpread, DistributedContactRunsOnTo300sWhereThePointContactStopped) {
  model::ModelSpec spec =
      io::readModelFile(std::string(test::kExamplesDir) + "/drift-into-spread/model.yaml");
  spec.dynamics.duration = 300.0;
  spec.output.plots = false;
  spec.contact.formulation = model::ContactFormulation::Distributed;
  analysis::Simulation sim(std::move(spec));
  ASSERT_TRUE(sim.solveStatics().converged);
  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;

  const model::Model& m = sim.model();
  std::vector<contact::ContactEvent> events = sim.contact()->events();
  events.insert(events.end(), sim.contact()->openEvents().begin(), sim.contact()->openEvents().end());
  ASSERT_EQ(events.size(), 1u);
  const contact::ContactEvent& hit = events.front();
  const bool riserFirst = m.lines()[hit.lineA].name == "riser";
  EXPECT_EQ(m.lines()[riserFirst ? hit.lineB : hit.lineA].name, "leg5");
  EXPECT_TRUE(hit.impact);
  EXPECT_NEAR(hit.impactVelocity, 0.445, 0.02 * 0.445);
  test::expectImpactEnergiesWithinBounds(events);
  const double alongWire = riserFirst ? hit.arcBMax - hit.arcBMin : hit.arcAMax - hit.arcAMin;
  EXPECT_GT(alongWire, 20.0);
  const model::Line& riser = m.lines()[riserFirst ? hit.lineA : hit.lineB];
  const model::Line& wire = m.lines()[riserFirst ? hit.lineB : hit.lineA];
  double radii = 0.0;
  for (const model::Line* l : {&riser, &wire}) {
    double largest = 0.0;
    for (int e = l->firstElement; e < l->firstElement + l->elementCount; ++e)
      largest = std::max(largest, 0.5 * m.elements()[e].type->contactDiameter);
    radii += largest;
  }
  EXPECT_LT(hit.maxPenetration, 0.5 * radii);
}

}  // namespace
}  // namespace tangle
