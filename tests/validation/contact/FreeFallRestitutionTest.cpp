// Validation against the seed paper, section 6.2 (Silva, Pereira & Jacob 2007): free fall with
// restitution. A small body (L2 = 10 mm, d2 = 10 mm, 2 beam elements) falls from h = 4.85 m onto a very
// rigid large body (L1 = 10 m, d1 = 10 m, 10 beam elements), both E = 70 GPa, rho = 2680 kg/m3; the
// paper reports rebound heights h* = e^2 h: 4.85, 3.9285, 2.7281, 1.2125 m for e = 1, 0.9, 0.75, 0.5
// (its Eq. 10-11), independent of mesh, time step and densities.
//
// Set-up (the paper gives no orientation): in air (no hydrodynamics), gravity 9.80665 m/s2. The large
// body lies along x with its axis at z = 10 m, both ends fixed (position and rotation); it weighs 2.1e6 kg
// against the small body's 2.1 g and its midspan stiffness is ~1e13 N/m, so it does not move measurably.
// The small body lies along y, crossing the large body's axis at right angles above its midspan, its
// middle node above the large body's middle node; it is released at rest with its lower surface
// h = 4.85 m above the large body's top.
//
// Rebound height: the largest height of the small body's centre of mass after the impact, minus its
// height at first touch (large body top + r2). Measured from the touch, the body's own radius drops
// out: h is the height fallen to the touch and h* the height risen from it. The centre is sampled
// every 1 ms (apex error <= g (0.5 ms)^2 / 2 = 1.2 um).
//
// Tolerance 1 % (the bound). What remains below it: the time discretisation of the impact
// (40 steps per impact: ~0.1 %), the separation at a small residual penetration (2 zeta e v0 sqrt(m/k)
// = 0.3 mm at e = 0.5, 0.03 %), gravity acting during the 0.25 ms contact (~0.1 % at e = 0.5), and the
// growth of the small body's participating mass during the first microseconds of the impact (below).
//
// Contact stiffness. The automatic stiffness (0.1 EA / L_element of the 5 mm elements: 1.1e8 N/m) makes
// the impact last 14 us, about three periods of the small body's own first modes (bending of the two
// elements and axial, ~5 us): the small body is then not the rigid body the paper's impact model
// assumes (section 4: effective mass constant during the impact, shape unchanged). The mass taking
// part at the contact node grows during the impact from the node's lumped half of the body to the
// whole body, and the penalty model's rebound heights come out 0.4 % (e = 1) to 13 % (e = 0.5) high.
// With k = 3e5 N/m the impact lasts 0.25 ms, 50 such periods, the body responds as a whole, and the
// penetration v0 sqrt(m/k) = 0.8 mm stays a sixth of the small body's radius: the paper's idealisation
// holds. (With one element the middle of the element is hit, both nodes move together from the start,
// and the automatic stiffness works: second suite.)
//
// Impact models. The penalty model calibrates its dashpot with the pair's effective mass, measured
// during the impact with Eq. 5 (impulse / velocity change). The impulse model gives the velocity jump
// at the first touch with the lumped mass of the nodes at the contact point: exact when that is the
// body's participating mass (one element hit at its middle), but half of it for the two-element body
// hit at its middle node, whose ends keep falling after the jump; that case is the disabled suite
// (a known limitation, see tests/validation/contact/README.md).

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

constexpr double kE = 70.0e9, kRho = 2680.0;
constexpr double kLargeLength = 10.0, kLargeDiameter = 10.0;
constexpr double kSmallLength = 0.01, kSmallDiameter = 0.01;
constexpr double kDrop = 4.85;      // h [m]
constexpr double kAxisZ = 10.0;     // large body axis height, in air [m]
constexpr double kTimeStep = 1e-3;  // nominal step [s]

struct Case {
  double restitution;
  model::ImpactModel model;
  int smallElements;
  double stiffness;          // [N/m], 0 = automatic
  bool distributed = false;  // contact.formulation: distributed (DistributedContact.hpp)
};

std::string caseName(const ::testing::TestParamInfo<Case>& p) {
  return std::string(p.param.model == model::ImpactModel::Penalty ? "Penalty" : "Impulse") + "_e" +
         std::to_string(static_cast<int>(std::round(100.0 * p.param.restitution)));
}

class FreeFall : public ::testing::TestWithParam<Case> {};

TEST_P(FreeFall, ReboundHeightIsRestitutionSquaredTimesDropHeight) {
  const Case c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "free fall with restitution (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["large"] = test::solidRodType("large", kLargeDiameter, kE, kRho);
  spec.lineTypes["small"] = test::solidRodType("small", kSmallDiameter, kE, kRho);
  const double touchZ = kAxisZ + 0.5 * kLargeDiameter + 0.5 * kSmallDiameter;  // centre at first touch
  const double z0 = touchZ + kDrop;
  spec.lines = {test::simpleLine("large", "large", kLargeLength, 10, model::EndKind::Fixed,
                                 Vec3(-0.5 * kLargeLength, 0, kAxisZ), model::EndKind::Fixed,
                                 Vec3(0.5 * kLargeLength, 0, kAxisZ)),
                test::simpleLine("small", "small", kSmallLength, c.smallElements, model::EndKind::Free,
                                 Vec3(0, -0.5 * kSmallLength, z0), model::EndKind::Free,
                                 Vec3(0, 0.5 * kSmallLength, z0))};
  spec.contact.enabled = true;
  spec.contact.restitution = c.restitution;
  spec.contact.model = c.model;
  spec.contact.stiffness = c.stiffness;
  spec.contact.formulation =
      c.distributed ? model::ContactFormulation::Distributed : model::ContactFormulation::Point;
  spec.dynamics.enabled = true;
  const double fallTime = std::sqrt(2.0 * kDrop / kStandardGravity);
  spec.dynamics.duration = fallTime * (1.0 + c.restitution) + 0.05;  // just past the rebound apex
  spec.dynamics.timeStep = kTimeStep;
  spec.dynamics.minTimeStep = 1e-9;  // impact steps are ~6 us here (14 us / 40 with one element)
  spec.dynamics.outputInterval = 1e-3;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));  // no static solve: the small body is free
  const model::Line& small = sim.model().lines()[1];
  const auto& nodeMass = sim.model().nodeMass();
  double smallMass = 0.0;
  for (int n = small.firstNode; n <= small.lastNode(); ++n) smallMass += nodeMass[n];
  double zMax = -1e30;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    if (s.time < fallTime) return;  // before the impact
    double z = 0.0;
    for (int n = small.firstNode; n <= small.lastNode(); ++n) z += nodeMass[n] * s.position[n].z();
    zMax = std::max(zMax, z / smallMass);
  });
  ASSERT_TRUE(run.completed) << run.message;

  const double expected = c.restitution * c.restitution * kDrop;
  EXPECT_NEAR(zMax - touchZ, expected, 0.01 * expected);
  RecordProperty("rebound_relative_error", fmt::format("{:.3e}", (zMax - touchZ) / expected - 1.0));
  RecordProperty("steps", std::to_string(run.steps));

  // One impact event, at the free-fall impact speed sqrt(2 g h) (to the resolution of the first contact
  // step, 0.1 %), whose Eq. 5 effective mass of the small body is its whole mass (rigid-body response;
  // 1 %: the mass measured over the whole impact includes the first microseconds, see above).
  const auto& events = sim.contact()->events();
  ASSERT_GE(events.size(), 1u);
  const contact::ContactEvent& impact = events.front();
  EXPECT_NEAR(impact.impactVelocity, std::sqrt(2.0 * kStandardGravity * kDrop),
              1e-3 * std::sqrt(2.0 * kStandardGravity * kDrop));
  EXPECT_NEAR(impact.effectiveMassB, smallMass, 0.01 * smallMass);
  // The clash report's impact energy (issue 29, docs/theory.md 9.10): the large body does not move, so the
  // pair's participating mass is the small body's, and the energy of approach 1/2 m v0^2 is what the
  // contact takes up. Eq. 5 over the impact phase and the absorbed work, within 1 % (the phase ends at
  // the first committed state past maximum compression; gravity acts during the impact, 0.1 % at e = 1).
  const double energy = 0.5 * smallMass * impact.impactVelocity * impact.impactVelocity;
  EXPECT_NEAR(impact.energyMass, smallMass, 0.01 * smallMass);
  EXPECT_NEAR(impact.impactEnergy, energy, 0.01 * energy);
  EXPECT_NEAR(impact.phaseWork, energy, 0.01 * energy);
  test::expectImpactEnergiesWithinBounds(events);
  for (std::size_t i = 1; i < events.size(); ++i)
    EXPECT_LT(events[i].impulse, 1e-3 * impact.impulse)
        << "a second impact at t = " << events[i].startTime << " s";

  // The step limiter shrinks the step for the impact only: the run needs the nominal steps plus a few
  // hundred (approach halving, ~50 impact steps, twofold regrowth), not impact-sized steps throughout.
  EXPECT_LT(run.steps, static_cast<int>(std::ceil(fallTime * (1.0 + c.restitution) / kTimeStep)) + 300);
}

// The paper's mesh (two elements), penalty model, contact stiffness 3e5 N/m (see the file comment). The error
// grows with the dashpot (the dashpot calibrated with the Eq. 5 mass measured while it grows, see the file
// comment): +0.13, +0.26, +0.41, +0.85 % for e = 1, 0.9, 0.75, 0.5 (measured 2026-11-30). e = 0.5 was
// +1.02 % and disabled until output times were landed on in equal steps (DynamicAnalysis): a step cut to a
// sliver before an output time, and the 2 g body's impact steps grown back from it, cost it 0.17 %.
INSTANTIATE_TEST_SUITE_P(Paper62, FreeFall,
                         ::testing::Values(Case{1.0, model::ImpactModel::Penalty, 2, 3e5},
                                           Case{0.9, model::ImpactModel::Penalty, 2, 3e5},
                                           Case{0.75, model::ImpactModel::Penalty, 2, 3e5},
                                           Case{0.5, model::ImpactModel::Penalty, 2, 3e5}),
                         caseName);

// One element hit at its middle (both nodes share the impact from the start), automatic stiffness, both
// impact models; also e = 0.1 (beyond the paper's values: an overdamped dashpot, zeta = 1.6).
INSTANTIATE_TEST_SUITE_P(Paper62OneElement, FreeFall,
                         ::testing::Values(Case{1.0, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.9, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.75, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.5, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{0.1, model::ImpactModel::Penalty, 1, 0.0},
                                           Case{1.0, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{0.9, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{0.75, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{0.5, model::ImpactModel::Impulse, 1, 0.0},
                                           Case{0.1, model::ImpactModel::Impulse, 1, 0.0}),
                         caseName);

// The distributed formulation (issue 43), the paper's mesh and stiffness. Rebound against e^2 h, measured
// 2026-11-30: +0.056, +0.038, -0.023, -0.083 % for e = 1, 0.9, 0.75, 0.5; 1709-2141 steps. Until
// 2026-11-29 these were known failures: -2.1 to -5.3 % with a dashpot calibrated for a linear law on the
// crossing's Hertz-like p^(3/2) law (restitution by hysteresis gives e^2 of the energy back whatever the law,
// theory 9.11), and 4000-6200 steps, the step regrowing 1.25-fold from every sliver cut to land on an output
// time (now landed on in equal steps, and 1.25 only while the lines are in or near contact).
INSTANTIATE_TEST_SUITE_P(Distributed, FreeFall,
                         ::testing::Values(Case{1.0, model::ImpactModel::Penalty, 2, 3e5, true},
                                           Case{0.9, model::ImpactModel::Penalty, 2, 3e5, true},
                                           Case{0.75, model::ImpactModel::Penalty, 2, 3e5, true},
                                           Case{0.5, model::ImpactModel::Penalty, 2, 3e5, true}),
                         caseName);

// Known limitation (README): the impulse model with the paper's two-element body hit at its middle node
// uses the node's lumped mass (half the body) for the velocity jump. Run by ctest as expected to fail
// (validation.impulse_two_elements_expected_fail). Measured 2026-11-30: rebound -99.4 % (e = 1) and
// -75.1 % (e = 0.5) of e^2 h, 3256 and 1959 steps.
INSTANTIATE_TEST_SUITE_P(ImpulseTwoElementsKnownFailures, FreeFall,
                         ::testing::Values(Case{1.0, model::ImpactModel::Impulse, 2, 3e5},
                                           Case{0.5, model::ImpactModel::Impulse, 2, 3e5}),
                         caseName);

}  // namespace
}  // namespace tangle
