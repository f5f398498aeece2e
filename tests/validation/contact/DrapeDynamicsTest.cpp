// Issue 29: a short wire dropped across a taut wire at 90 deg must run until the two come to rest draped,
// through the first impact, the fold of the short wire over the taut one at its middle node, and the
// rattling that follows. Before the fixes of issue 29 this model stopped at t = 0.54 s with "lines pass
// through each other" (e = 1 and e = 0.5; the issue reported 0.57 s and 0.65 s on its own variant).
//
// Set-up (in air, above the still water level: no hydrodynamics): a taut wire of 20 m between fixed ends at
// z = 10 m (unstretched 19.99 m: 10 kN of tension), in its static equilibrium (sag 8 cm); a short wire of
// 4 m and 4 bars across it at right angles, its middle node above the taut wire's middle node, released at
// rest with its lower surface 0.5 m above the taut wire's top. Both wires: D = 20 mm, 1.6 kg/m, EA = 2e7 N
// (a 20 mm steel strand). Contact friction 0 or 0.3 (the point formulation's cases with friction are known
// failures, at the end). A mass-proportional damping of 0.5 1/s stands for the air (the swinging legs would
// otherwise swing for ever); its work is accounted for below.
//
// Checks (sources and tolerances):
// - the run completes (the issue's failure);
// - the first impact: approach speed of the damped free fall (1 %: the first contact step's resolution);
//   the energy balance of its impact phase: the mechanical energy (kinetic, gravity, bar strain) lost from
//   just before the contact to the phase end equals the work the contact absorbed (the report's
//   absorbed_energy) plus the damping's work, within 2 % of the impact energy (the integrator's energy
//   error over ~40 impact steps is ~0.2 %, the contact spring's energy at the phase end is in the absorbed
//   work by definition);
// - the Eq. 5 energy and the absorbed work agree within 5 % (two rigid point masses give equality; the
//   struck node of a slack cable is such a mass over the 2 ms of the impact: no transverse stiffness
//   couples it to its neighbours that fast) and its mass lies between one element of each line and the
//   two whole lines (issue 29's bound for every impact);
// - first event, e = 1: the mechanical energy after it equals the one before, less the damping's work,
//   within 2 % of the impact energy; e = 0.5: the loss is (1 - e^2) of the impact energy within 5 %
//   (the clipped-dashpot restitution law e(zeta) is exact for a constant mass, theory 9.6);
// - at the end (12 s) the short wire hangs over the taut wire, both ends below the fold, the fold within
//   one element of the taut wire's middle; at rest for e = 0.5 (kinetic energy below 1 % of the energy
//   dissipated since the release; e = 1 keeps chattering, see the code).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kDiameter = 0.02, kMassPerLength = 1.6, kEA = 2.0e7;
constexpr double kSpan = 20.0, kTautLength = 19.99, kShortLength = 4.0, kAxisZ = 10.0, kDropGap = 0.5;
constexpr double kDamping = 0.5;  // mass-proportional (Rayleigh alpha) [1/s]

struct DrapeCase {
  double restitution;
  double friction;           // contact friction coefficient [-]
  bool distributed = false;  // contact.formulation: distributed (DistributedContact.hpp)
  int shortElements = 4;     // bars of the short wire
};

/// Kinetic, gravity and bar strain energy [J] of the model (lumped masses; bars carry no compression, the
/// 1e-6 EA of a slack bar is left out).
double mechanicalEnergy(const model::Model& m, const model::State& s) {
  const double g = m.environment().gravity;
  double energy = 0.0;
  for (int n = 0; n < m.nodeCount(); ++n) {
    const double mass = m.nodeMass()[n];
    energy +=
        mass * (g * s.position[n].z() + 0.5 * s.velocity.segment<3>(m.dofs().firstDof(n)).squaredNorm());
  }
  for (const model::LineElement& e : m.elements()) {
    const double stretch = (s.position[e.node2] - s.position[e.node1]).norm() - e.restLength;
    if (stretch > 0.0) energy += 0.5 * e.type->axialStiffness / e.restLength * stretch * stretch;
  }
  return energy;
}

/// sum m v^2 [J]: the Rayleigh damping force alpha m v does work alpha sum m v^2 per unit time.
double twiceKineticEnergy(const model::Model& m, const model::State& s) {
  double energy = 0.0;
  for (int n = 0; n < m.nodeCount(); ++n)
    energy += m.nodeMass()[n] * s.velocity.segment<3>(m.dofs().firstDof(n)).squaredNorm();
  return energy;
}

model::LineSpec tautWire() {
  return test::simpleLine("taut", "wire", kTautLength, 20, model::EndKind::Fixed,
                          Vec3(-0.5 * kSpan, 0, kAxisZ), model::EndKind::Fixed, Vec3(0.5 * kSpan, 0, kAxisZ));
}

model::ModelSpec baseSpec() {
  model::ModelSpec spec;
  spec.sourceFile = "short wire dropped across a taut wire (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["wire"] = test::cableType("wire", kDiameter, kMassPerLength, kEA);
  return spec;
}

class DrapeDynamics : public ::testing::TestWithParam<DrapeCase> {};

TEST_P(DrapeDynamics, ShortWireDroppedAcrossTautWireComesToRestDraped) {
  const double e = GetParam().restitution;
  // The taut wire's static equilibrium, alone (the free short wire has none).
  model::ModelSpec tautSpec = baseSpec();
  tautSpec.lines = {tautWire()};
  analysis::Simulation taut(std::move(tautSpec));
  ASSERT_TRUE(taut.solveStatics().converged);

  model::ModelSpec spec = baseSpec();
  const double tautTop = taut.state().position[10].z() + kDiameter;  // middle node, plus both radii
  const double z0 = tautTop + kDropGap;
  spec.lines = {tautWire(), test::simpleLine("short", "wire", kShortLength, GetParam().shortElements,
                                             model::EndKind::Free, Vec3(0, -0.5 * kShortLength, z0),
                                             model::EndKind::Free, Vec3(0, 0.5 * kShortLength, z0))};
  spec.contact.enabled = true;
  spec.contact.restitution = e;
  spec.contact.frictionCoefficient = GetParam().friction;
  spec.contact.formulation =
      GetParam().distributed ? model::ContactFormulation::Distributed : model::ContactFormulation::Point;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 12.0;
  spec.dynamics.timeStep = 0.01;
  spec.dynamics.outputInterval = 0.1;
  spec.dynamics.rampTime = 0.0;
  spec.dynamics.rayleighAlpha = kDamping;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::Line& tautLine = m.lines()[0];
  for (int n = 0; n < tautLine.nodeCount; ++n)
    sim.state().position[tautLine.firstNode + n] = taut.state().position[n];
  const double initialEnergy = mechanicalEnergy(m, sim.state());

  // Energy bookkeeping per accepted step: the work of the damping and of the contact friction (trapezoidal;
  // counted with the damping below), and the mechanical energy just before the first contact, at the end of
  // the first impact phase and after the first event. Friction's power is -sum w f_t . (v_A - v_B) over the
  // distributed formulation's Gauss points (the point formulation's friction cases are known failures).
  const auto frictionPower = [&]() {
    double power = 0.0;
    if (const contact::DistributedContact* d = sim.contact()->distributed())
      for (const contact::ContactSample& smp : d->samples())
        power -= smp.length * smp.friction.dot(smp.slipRate);
    return power;
  };
  double lastFrictionPower = 0.0;
  double dampingWork = 0.0, lastTwiceKinetic = twiceKineticEnergy(m, sim.state());
  double before = 0.0, dampingBefore = 0.0, atPhaseEnd = 0.0, dampingAtPhaseEnd = 0.0, afterFirst = 0.0,
         dampingAfterFirst = 0.0;
  bool touched = false, phaseEnded = false, firstClosed = false;
  const time::DynamicResult run =
      sim.runDynamics([](const model::State&, const VecX&) {}, false,
                      [&](const model::State& s, double h) {
                        const double twiceKinetic = twiceKineticEnergy(m, s);
                        dampingWork += 0.5 * kDamping * (lastTwiceKinetic + twiceKinetic) * h;
                        lastTwiceKinetic = twiceKinetic;
                        const double power = frictionPower();
                        dampingWork += 0.5 * (lastFrictionPower + power) * h;
                        lastFrictionPower = power;
                        const contact::LineContact& lc = *sim.contact();
                        if (!touched && lc.openEvents().empty() && lc.events().empty()) {
                          before = mechanicalEnergy(m, s);
                          dampingBefore = dampingWork;
                          return;
                        }
                        touched = true;
                        const bool closed = !lc.events().empty();
                        if (!phaseEnded && (closed || !lc.openEvents().front().phaseOpen)) {
                          phaseEnded = true;
                          atPhaseEnd = mechanicalEnergy(m, s);
                          dampingAtPhaseEnd = dampingWork;
                        }
                        if (!firstClosed && closed) {
                          firstClosed = true;
                          afterFirst = mechanicalEnergy(m, s);
                          dampingAfterFirst = dampingWork;
                        }
                      });
  ASSERT_TRUE(run.completed) << run.message;
  RecordProperty("steps", std::to_string(run.steps));

  const auto& events = sim.contact()->events();
  ASSERT_GE(events.size(), 1u);
  ASSERT_TRUE(phaseEnded && firstClosed);
  const contact::ContactEvent& first = events.front();
  // Free fall through kDropGap against the damping force alpha m v: x(t) = g t / alpha - g (1 - e^(-alpha
  // t)) / alpha^2, v = g (1 - e^(-alpha t)) / alpha (2.97 m/s against 3.13 m/s undamped).
  double tFall = std::sqrt(2.0 * kDropGap / kStandardGravity);
  for (int i = 0; i < 50; ++i) {
    const double decay = std::exp(-kDamping * tFall);
    const double x =
        kStandardGravity * tFall / kDamping - kStandardGravity * (1.0 - decay) / (kDamping * kDamping);
    tFall -= (x - kDropGap) / (kStandardGravity * (1.0 - decay) / kDamping);  // Newton on x(t) = h
  }
  const double v0 = kStandardGravity * (1.0 - std::exp(-kDamping * tFall)) / kDamping;
  EXPECT_TRUE(first.impact);
  EXPECT_NEAR(first.impactVelocity, v0, 0.01 * v0);
  const double impactEnergy = first.impactEnergy;
  RecordProperty("impact_energy_J", fmt::format("{:.4g}", impactEnergy));
  RecordProperty("absorbed_J", fmt::format("{:.4g}", first.phaseWork));
  RecordProperty("energy_mass_kg", fmt::format("{:.4g}", first.energyMass));
  EXPECT_EQ(first.energyMassBasis, "eq5");
  EXPECT_NEAR(first.phaseWork, impactEnergy, 0.05 * impactEnergy);
  EXPECT_TRUE(first.energyWarning.empty()) << first.energyWarning;
  EXPECT_GE(first.energyMass, first.massLowerBound * (1.0 - 1e-9));
  EXPECT_LE(first.energyMass, first.massUpperBound * (1.0 + 1e-9));

  // Impact phase: energy lost = absorbed work + damping.
  EXPECT_NEAR(before - atPhaseEnd, first.phaseWork + (dampingAtPhaseEnd - dampingBefore),
              0.02 * impactEnergy);
  // The whole first event.
  const double lost = before - afterFirst - (dampingAfterFirst - dampingBefore);
  RecordProperty("first_event_loss_J", fmt::format("{:.4g}", lost));
  EXPECT_NEAR(lost, (1.0 - e * e) * impactEnergy, (e == 1.0 ? 0.02 : 0.05) * impactEnergy)
      << "first event " << first.startTime << " - " << first.endTime << " s";

  // At rest, draped: the fold on the taut wire near its middle, both ends of the short wire below it.
  const model::State& s = sim.state();
  const model::Line& shortLine = m.lines()[1];
  int fold = shortLine.firstNode;
  for (int n = shortLine.firstNode; n <= shortLine.lastNode(); ++n)
    if (s.position[n].z() > s.position[fold].z()) fold = n;
  const double dissipated = initialEnergy - mechanicalEnergy(m, s);
  RecordProperty("final_kinetic_energy_J", fmt::format("{:.3g}", 0.5 * twiceKineticEnergy(m, s)));
  // At e = 1 the resting contact has no dashpot and keeps chattering: the kinetic energy stalls near 0.9 J
  // (1 % of the 88 J dissipated) from t = 10 s on instead of decaying with the damping (measured, left
  // open in issue 29's note); the rest check is for e < 1.
  if (e < 1.0) {
    EXPECT_LT(0.5 * twiceKineticEnergy(m, s), 0.01 * dissipated);
  }
  EXPECT_NEAR(s.position[fold].x(), 0.0, 1.0);
  EXPECT_NEAR(s.position[fold].z(), tautTop, 0.1);
  EXPECT_LT(s.position[shortLine.firstNode].z(), s.position[fold].z() - 0.5);
  EXPECT_LT(s.position[shortLine.lastNode()].z(), s.position[fold].z() - 0.5);
}

std::string caseName(const ::testing::TestParamInfo<DrapeCase>& p) {
  return "e" + std::to_string(static_cast<int>(std::round(100.0 * p.param.restitution))) + "_mu" +
         std::to_string(static_cast<int>(std::round(100.0 * p.param.friction))) +
         (p.param.shortElements != 4 ? "_n" + std::to_string(p.param.shortElements) : std::string());
}

// Frictionless: the drape is then an unstable equilibrium that the damping and the symmetric start keep.
INSTANTIATE_TEST_SUITE_P(Issue29, DrapeDynamics, ::testing::Values(DrapeCase{1.0, 0.0}, DrapeCase{0.5, 0.0}),
                         caseName);

// Known limitation (issue 29, left open): with friction at the crossing (mu = 0.3, the regularised point
// friction of theory 9.8) the fold of the short wire over the taut one sharpens to about 110 deg, and the
// fold's contact at its node (theory 9.3: the feet of a fold within the radii are moved onto the node)
// does not see the legs, which pass 43 % of the radii inside the taut wire: the step validator refuses
// the state at t = 0.58-0.60 s (e = 0.5) or Newton cycles between the two legs at t = 0.51 s (e = 1).
// A contact per leg for sharp folds, blended with the node contact by fold angle, was tried and not kept:
// it held the drape but changed the static chain-over-wire solution (StaticContactTest) by 3-7 % and
// made its Newton solve fail. Run by ctest as expected to fail
// (validation.point_drape_friction_expected_fail). Measured 2026-11-30: Newton stops at the minimum step at t
// = 1.076 s (e = 1) and 0.518 s (e = 0.5).
INSTANTIATE_TEST_SUITE_P(PointFrictionKnownFailures, DrapeDynamics,
                         ::testing::Values(DrapeCase{1.0, 0.3}, DrapeCase{0.5, 0.3}), caseName);

// The distributed formulation (issue 43): the same drop, every line on its C1 centreline; e = 1 and 0.5 on 4
// bars, with and without friction (mu = 0.3), and e = 0.5 on 40 bars, pass every check. The 40-bar case
// (about 110 s CPU, 235 000 steps) measured on 2026-11-29: first impact 0.646 J, its event loses 0.4855 J
// against (1 - e^2) E = 0.4844 J (+0.2 %), final kinetic energy 0.13 J. With the step free to double every
// step it gained energy until the wire was thrown off (3.8 kJ of mechanical energy grew to 0.8 MJ within
// 1.3 s, the contact forces doing no net work): the distributed contact's steps grow at most 1.25-fold
// (LineContact::maxStepGrowth).
// With friction (measured 2026-12-02): Eq. 5 mass 0.8145 kg (e = 1) and 0.8128 kg (e = 0.5) against 0.8152
// and 0.8130 kg without, impact energy 3.586 and 3.578 J; the contact's normal law absorbs 3.411 and 3.432 J
// (-4.9 % and -4.1 %: the rest of the approach is stopped by friction, whose work goes into sliding and is
// counted with the damping's above), and the first event at e = 0.5 loses 2.574 J, (1 - e^2) of what the
// normal law absorbed. Known failures from 2026-11-29 to 12-02: the impulse of Eq. 5 was the normal forces'
// alone, and the friction's part along the patch's mean normal, which helps stop the approach where the
// normals of a crossing over a bent wire spread, was missing: Eq. 5 mass 0.787 / 0.792 kg, below one
// element's reduced mass (0.800 kg).
// On 40 bars (measured 2026-12-02, each 72-79 s CPU; e = 0.5 with friction is run here, the others were run
// once): e = 0.5, mu = 0.3: first impact 0.6473 J, Eq. 5 mass 0.147 kg, absorbed 0.6308 J, the first event
// loses 0.4716 J against (1 - e^2) of the absorbed 0.4731 J, final kinetic energy 0.074 J, 216 759 steps;
// e = 1, mu = 0.3: 0.6470 J, 246 827 steps; e = 1 without friction: 0.6471 J, 280 734 steps (friction costs
// nothing here: 71.9 s against 73.4 s). Where those steps come from (counted 2026-12-04, e = 0.5 without
// friction, 226 335 steps): the cable snap limit (docs/theory.md 8.3) shortens 104 562 of them, the hanging
// legs' 0.1 m bars chattering axially at their kinks, and the others grow back from those 1.25-fold; the
// contact's limits set fewer than 4 %.
INSTANTIATE_TEST_SUITE_P(Distributed, DrapeDynamics,
                         ::testing::Values(DrapeCase{1.0, 0.0, true, 4}, DrapeCase{0.5, 0.0, true, 4},
                                           DrapeCase{0.5, 0.0, true, 40}, DrapeCase{1.0, 0.3, true, 4},
                                           DrapeCase{0.5, 0.3, true, 4}, DrapeCase{0.5, 0.3, true, 40}),
                         caseName);

}  // namespace
}  // namespace tangle
