// Two lines hitting head-on: conservation of momentum and the coefficient of restitution (seed paper,
// Silva, Pereira & Jacob 2007, section 4, Eq. 6-7 and the definition of e as the ratio of the relative
// normal velocities after and before the impact).
//
// Two identical steel bars in air (no hydrodynamics, gravity 0) cross at right angles, one above the
// other, 5 mm apart, and move towards each other at 1 m/s each, with a common drift (0.2, 0.1, 0) m/s on
// top (so the total momentum is not zero). For equal masses and a central impact the kinetic energy in
// the centre-of-mass frame after the impact is e^2 times the one before (Eq. 6-7 with e).
//
// Checks and tolerances:
// - Total momentum (sum of nodal mass times velocity) conserved to 1e-6 of one bar's momentum m v: the
//   contact forces act on the four nodes with weights summing to zero and the lumped-mass integrator
//   conserves the momentum of internal forces exactly; the impulse model's jump is distributed the same
//   way. What is left is round-off of the Newton solution (~1e-10 relative).
// - Kinetic energy ratio after / before (centre-of-mass frame, translations and rotations of every
//   node) = e^2 within 2 % (the bound). Known deviations below it: the discretisation of the
//   impact (40 steps per impact; ~0.1 % in the free-fall test), and, for the multi-element bars, the
//   growth of the mass taking part in the impact during its first instants (below).
//
// Cases: one-element bars hit at their middles (the lumped mass at the contact point is the bar's mass:
// the rigid-body case, automatic stiffness 4e9 N/m, both impact models) and three-element bars hit at
// the middle of their middle elements (penalty model). For the latter the mass taking part grows during
// the impact from the lumped 2/3 of a bar (the two nodes of the hit element) to the whole bar, which the
// Eq. 5 measurement follows; the dashpot is calibrated with the smaller mass for the first instants and
// the restitution comes out high by an amount that grows with the ratio of the bars' first bending
// period (free-free, 0.27 ms) to the impact duration: KE ratio +4 % at 1e8 N/m (impact 1 ms), +2.2 % at
// 2e7 N/m, +0.7 % at 1e6 N/m (impact 22 ms, 80 bending periods; penetration 16 mm, a sixth of the radius),
// which is used (the rigid-body idealisation of the paper's impact model, section 4).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/ContactChecks.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kE = 2.1e11, kRho = 7850.0, kD = 0.2, kL = 0.5;
constexpr double kGap = 0.005;    // initial clearance [m]
constexpr double kSpeed = 1.0;    // approach speed of each bar [m/s]
constexpr double kHeight = 10.0;  // in air [m]

struct Case {
  double restitution;
  model::ImpactModel model;
  int elements;
  double stiffness;          // [N/m], 0 = automatic
  bool distributed = false;  // contact.formulation: distributed (DistributedContact.hpp)
};

class HeadOn : public ::testing::TestWithParam<Case> {};

TEST_P(HeadOn, ConservesMomentumAndRestoresESquaredOfTheKineticEnergy) {
  const Case c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "head-on impact (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 0.0;
  spec.lineTypes["bar"] = test::solidRodType("bar", kD, kE, kRho);
  const double zA = kHeight + 0.5 * kD + 0.5 * kGap, zB = kHeight - 0.5 * kD - 0.5 * kGap;
  spec.lines = {test::simpleLine("barA", "bar", kL, c.elements, model::EndKind::Free, Vec3(-0.5 * kL, 0, zA),
                                 model::EndKind::Free, Vec3(0.5 * kL, 0, zA)),
                test::simpleLine("barB", "bar", kL, c.elements, model::EndKind::Free, Vec3(0, -0.5 * kL, zB),
                                 model::EndKind::Free, Vec3(0, 0.5 * kL, zB))};
  spec.contact.enabled = true;
  spec.contact.restitution = c.restitution;
  spec.contact.model = c.model;
  spec.contact.formulation =
      c.distributed ? model::ContactFormulation::Distributed : model::ContactFormulation::Point;
  spec.contact.stiffness = c.stiffness;
  spec.dynamics.enabled = true;
  // Touch at 2.5 ms; the rigid bars' impact < 3 ms; the slowest case, three-element bars on the distributed
  // formulation's soft crossing at e = 0.5, is in contact until 45.1 ms (unloading along (1 - a) = 0.4 of
  // the law, 42.6 ms against 34.2 ms at e = 1) and its event closes, 5 % of the radii apart, at 55.8 ms
  // (a run of 50 ms ended it open: a known failure until 2026-12-02).
  spec.dynamics.duration = 0.08;
  spec.dynamics.timeStep = 1e-3;
  spec.dynamics.minTimeStep = 1e-9;
  spec.dynamics.outputInterval = spec.dynamics.duration;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::DofMap& dofs = m.dofs();
  const Vec3 drift(0.2, 0.1, 0.0);
  for (int line = 0; line < 2; ++line) {
    const Vec3 v = drift + Vec3(0, 0, line == 0 ? -kSpeed : kSpeed);
    for (int n = m.lines()[line].firstNode; n <= m.lines()[line].lastNode(); ++n)
      sim.state().velocity.segment<3>(dofs.firstDof(n)) = v;
  }

  double lineMass = 0.0;
  for (int n = m.lines()[0].firstNode; n <= m.lines()[0].lastNode(); ++n) lineMass += m.nodeMass()[n];
  auto momentum = [&](const model::State& s) {
    Vec3 p = Vec3::Zero();
    for (int n = 0; n < m.nodeCount(); ++n) p += m.nodeMass()[n] * s.velocity.segment<3>(dofs.firstDof(n));
    return p;
  };
  auto kineticEnergyRelative = [&](const model::State& s, const Vec3& vcm) {
    double ke = 0.0;
    for (int n = 0; n < m.nodeCount(); ++n) {
      const int d = dofs.firstDof(n);
      ke += 0.5 * m.nodeMass()[n] * (s.velocity.segment<3>(d) - vcm).squaredNorm();
      if (dofs.hasRotations(n))
        ke += 0.5 * m.nodeRotationalInertia()[n] * s.velocity.segment<3>(d + 3).squaredNorm();
    }
    return ke;
  };
  const Vec3 p0 = momentum(sim.state());
  const Vec3 vcm = p0 / (2.0 * lineMass);
  const double ke0 = kineticEnergyRelative(sim.state(), vcm);

  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;

  const Vec3 p1 = momentum(sim.state());
  EXPECT_LT((p1 - p0).norm(), 1e-6 * lineMass * kSpeed)
      << "momentum before " << p0.transpose() << ", after " << p1.transpose();
  const double ratio = kineticEnergyRelative(sim.state(), vcm) / ke0;
  const double expected = c.restitution * c.restitution;
  EXPECT_NEAR(ratio, expected, 0.02 * expected);
  RecordProperty("kinetic_energy_ratio_relative_error", fmt::format("{:.3e}", ratio / expected - 1.0));
  RecordProperty("momentum_relative_error", fmt::format("{:.3e}", (p1 - p0).norm() / (lineMass * kSpeed)));

  // The bars separated: one event, closed.
  const auto& events = sim.contact()->events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_FALSE(events[0].open);
  EXPECT_NEAR(events[0].impactVelocity, 2.0 * kSpeed, 1e-3 * 2.0 * kSpeed);

  // Impact energy (issue 29, docs/theory.md 9.10): two free rigid bars of mass m meeting at 2 v have the
  // reduced mass m / 2 and the energy of approach 1/2 (m / 2) (2 v)^2 = m v^2, taken up by the contact
  // until the approach stops. Eq. 5 over the impact phase and the absorbed work both measure it:
  // one-element bars within 1 % (the phase ends at the first committed state past maximum compression,
  // 1/40 of the impact duration); three-element bars within 5 % (the mass taking part grows from 2/3 of
  // a bar to the whole bar during the impact, see the file comment).
  const contact::ContactEvent& impact = events[0];
  const double reduced = 0.5 * lineMass, energy = lineMass * kSpeed * kSpeed;
  const double tolerance = c.elements == 1 ? 0.01 : 0.05;
  EXPECT_EQ(impact.energyMassBasis, "eq5");
  EXPECT_NEAR(impact.energyMass, reduced, tolerance * reduced);
  EXPECT_NEAR(impact.impactEnergy, energy, tolerance * energy);
  EXPECT_NEAR(impact.phaseWork, energy, tolerance * energy);
  EXPECT_EQ(impact.phaseEnd, "reversed");
  test::expectImpactEnergiesWithinBounds(events);
  RecordProperty("eq5_mass_relative_error", fmt::format("{:.3e}", impact.energyMass / reduced - 1.0));
  RecordProperty("absorbed_energy_relative_error", fmt::format("{:.3e}", impact.phaseWork / energy - 1.0));
}

std::string caseName(const ::testing::TestParamInfo<Case>& p) {
  return std::string(p.param.model == model::ImpactModel::Penalty ? "Penalty" : "Impulse") + "_e" +
         std::to_string(static_cast<int>(std::round(100.0 * p.param.restitution))) + "_" +
         std::to_string(p.param.elements) + "elements";
}

INSTANTIATE_TEST_SUITE_P(RigidBars, HeadOn,
                         ::testing::Values(Case{0.5, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.8, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{1.0, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.5, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{0.8, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{1.0, model::ImpactModel::Impulse, 1, 0.0}),
                         caseName);

INSTANTIATE_TEST_SUITE_P(FlexibleBars, HeadOn,
                         ::testing::Values(Case{0.5, model::ImpactModel::Penalty, 3, 1e6},
                                           Case{0.8, model::ImpactModel::Penalty, 3, 1e6},
                                           Case{1.0, model::ImpactModel::Penalty, 3, 1e6}),
                         caseName);

// The distributed formulation (issue 43; restitution by hysteresis, docs/theory.md 9.11): three-element
// bars at 1e6 N/m, e = 1: KE ratio +1.2e-4; e = 0.5: +1e-5 (a known failure while the run ended before its
// event closed). One-element (rigid) bars at the automatic stiffness, e = 1: +0.53 % (a known failure at
// +9.8 % until the impact step limit judged a crossing by its own law: DistributedContact::impactStepLimit).
INSTANTIATE_TEST_SUITE_P(Distributed, HeadOn,
                         ::testing::Values(Case{1.0, model::ImpactModel::Penalty, 3, 1e6, true},
                                           Case{0.5, model::ImpactModel::Penalty, 3, 1e6, true},
                                           Case{1.0, model::ImpactModel::Penalty, 1, 0.0, true}),
                         caseName);

// Known failure (run by ctest as expected to fail, validation.distributed_head_on_expected_fail):
// one-element (rigid) bars at the automatic stiffness, e = 0.5: KE ratio 0.2615 for 0.25 (+4.6 %; it was
// +18.9 % while the step limit judged a just-touching crossing with the point stiffness). The impact is
// resolved in steps of the crossing's own law while the bars approach and judged afresh once they turn to
// separate; the unloading along (1 - a) f then takes growing steps. Held through the rebound as well it
// came to +1.8 %, but wires chattering on each other were held through every rebound and the random
// sweeps took 1.34 times their CPU (DistributedContact::commitSamples). Measured 2026-12-04, held through the
// rebound with the struck steps 2x and 4x finer: e = 1 converges to +5e-5 and +1e-5, e = 0.5 to +1.41 % and
// +1.34 %: about 1.3 % is the law's (the switch of the hysteresis smoothed over |v| < v_s = 0.13 m/s against
// the 2 m/s impact, docs/theory.md 9.11), the other 3.3 % the rebound's growing steps.
INSTANTIATE_TEST_SUITE_P(DistributedKnownFailures, HeadOn,
                         ::testing::Values(Case{0.5, model::ImpactModel::Penalty, 1, 0.0, true}), caseName);

// End-on impact: a bar falling end first onto the side of a heavy line (a free line end hitting another
// line, e.g. a riser's lower end). The contact normal there is the closest-point direction, not the
// crossing normal tA x tB (which would be horizontal for a vertical bar on a horizontal line). A
// one-element steel bar (1 m, d = 0.05 m), vertical, moves down at 1 m/s onto a fixed steel beam
// (d = 1 m, 4 m, fixed ends: 2.1e6 times heavier than the bar's end node, midspan stiffness ~1e10 N/m),
// gravity 0. Expected: the bar's centre-of-mass velocity reverses to e times its impact velocity (a
// rigid, immovable wall), within 2 % (as above). Stiffness 3e5 N/m (impact ~25 ms, penetration 7 mm, a
// quarter of the bar's radius): the mass taking part grows from the bar's end node (half the bar) to
// the whole bar while the axial wave crosses it (0.2 ms); with the automatic stiffness (4e7 N/m, impact
// 1.4 ms) the rebound ratio is 7 % high at e = 0.5 (the effect of the flexible cases above), 1.6 % at
// 1e6 N/m, 1.0 % at 3e5 and 1e5 N/m (what is left: the bar's axial vibration excited by the dashpot
// force jump at the touch, which the dashpot sees in the end node's velocity).
TEST(EndOnImpact, BarHittingALineEndFirstReboundsWithTheRestitution) {
  for (double e : {1.0, 0.5}) {
    model::ModelSpec spec;
    spec.sourceFile = "end-on impact (test)";
    spec.environment.waterDepth = 100.0;
    spec.environment.gravity = 0.0;
    spec.lineTypes["beam"] = test::solidRodType("beam", 1.0, kE, kRho);
    spec.lineTypes["bar"] = test::solidRodType("bar", 0.05, kE, kRho);
    spec.lines = {test::simpleLine("beam", "beam", 4.0, 4, model::EndKind::Fixed, Vec3(-2.0, 0, kHeight),
                                   model::EndKind::Fixed, Vec3(2.0, 0, kHeight)),
                  test::simpleLine("bar", "bar", 1.0, 1, model::EndKind::Free, Vec3(0.3, 0, kHeight + 0.55),
                                   model::EndKind::Free, Vec3(0.3, 0, kHeight + 1.55))};
    spec.contact.enabled = true;
    spec.contact.restitution = e;
    spec.contact.stiffness = 3e5;
    spec.dynamics.enabled = true;
    spec.dynamics.duration = 0.1;  // touch at 25 ms, impact ~25 ms
    spec.dynamics.timeStep = 1e-3;
    spec.dynamics.minTimeStep = 1e-9;
    spec.dynamics.outputInterval = spec.dynamics.duration;
    spec.dynamics.rampTime = 0.0;
    analysis::Simulation sim(std::move(spec));
    const model::Line& bar = sim.model().lines()[1];
    const model::DofMap& dofs = sim.model().dofs();
    for (int n = bar.firstNode; n <= bar.lastNode(); ++n) sim.state().velocity[dofs.firstDof(n) + 2] = -1.0;
    const time::DynamicResult run = sim.runDynamics(nullptr);
    ASSERT_TRUE(run.completed) << run.message;
    double p = 0.0, m = 0.0;
    for (int n = bar.firstNode; n <= bar.lastNode(); ++n) {
      p += sim.model().nodeMass()[n] * sim.state().velocity[dofs.firstDof(n) + 2];
      m += sim.model().nodeMass()[n];
    }
    EXPECT_NEAR(p / m, e, 0.02 * e) << "e = " << e;
    EXPECT_NEAR(sim.contact()->events().front().impactVelocity, 1.0, 1e-3) << "e = " << e;
    test::expectImpactEnergiesWithinBounds(sim.contact()->events());
    RecordProperty(fmt::format("rebound_ratio_relative_error_e{}", static_cast<int>(100 * e)),
                   fmt::format("{:.3e}", p / m / e - 1.0));
  }
}

}  // namespace
}  // namespace tangle
