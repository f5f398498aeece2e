// Issue 29: the impact energy of the clash report (docs/theory.md 9.10) against independent references.
//
// 1. A rigid mass on a spring-supported line (1-DOF). A short bar (one element, 0.5 m, 30.8 kg, free, hit
//    at its middle: a rigid mass m) hits a light taut wire (10 m between pinned ends, 10 kN, 0.01 kg/m)
//    carrying a 30 kg lump at its middle node, at right angles, at v0 = 0.2 m/s; in air, no gravity,
//    restitution 1 (no dashpot). The wire is a massless spring K = 4 T / L on the lump (the string under a
//    point load; its mass is 0.3 % of the lump's, its own modes 30 times faster than the lump's), so the
//    struck line is one degree of freedom, M on K, and the reference is the linear two-mass system m -
//    k_c - M - K integrated to round-off (RK4 at 1e-5 of the contact duration) from first touch to
//    maximum compression: Eq. 5 mass = impulse / v0 there, absorbed work = contact spring energy there.
//    Its limits: a short contact (k_c >> K) engages the reduced mass m M / (m + M), as two free bodies; a
//    soft one (k_c << K) the bar's mass against a fixed wall, and a little more when the wire throws the
//    lump back before the approach stops. Part of the bar's energy can be in the support spring at
//    maximum compression rather than in the contact (the split of DNV-RP-C204 section 3 between local and
//    global strain energy): the absorbed work is then smaller than the Eq. 5 energy (here by 0-5 %),
//    and the report must warn when the two differ by more than 2. Tolerances: 1 % on the Eq. 5 mass and
//    energy (the phase ends at the first committed state past maximum compression, 1/40 of the contact),
//    2 % on the peak force and the absorbed work (they go as the square of the force, sampled at the
//    committed states).
// 2. A simply supported beam struck at mid-span. A short bar (one element, 0.5 m, D = 0.2 m, 123 kg) hits
//    a solid steel beam (10 m, D = 0.2 m, 2466 kg, pinned ends, 20 elements) at its middle at 1 m/s; in
//    air, no gravity, contact stiffness 1e7 N/m, restitution 1. The reference is the Euler-Bernoulli
//    beam's modal solution (Timoshenko & Young; Goldsmith, "Impact", ch. 4: the striker, the linear contact
//    spring and the symmetric modes sin(n pi x / L), n = 1, 3, ... 99, each of generalised mass M / 2 and
//    stiffness (n pi / L)^4 EI L / 2, integrated with RK4 at 0.2 us): the impulse up to maximum compression
//    over v0 (the Eq. 5 mass of the impact phase) and the contact spring's energy then (the absorbed work).
//    The contact lasts ~10 ms, 1/25 of the beam's first period (0.25 s): modes 1 to ~7 respond, so the
//    mass is neither the first mode's participating mass M / 2 (the long-contact limit: 112 kg reduced
//    with the bar's) nor one element's (61 kg reduced): the modal solution is the truth, the first mode's
//    mass a bound it must lie below. Tolerance 3 %: the 20-element lumped-mass mesh has modes 5 and 7 about
//    1 % and 3 % low in frequency, and the phase end is resolved to 1/40 of the contact.
//
// Both contact formulations (issue 43: the distributed one is the default). The references take each
// formulation's own contact law: the point formulation's linear spring k_c; the distributed one's law per
// unit length (docs/theory.md 9.11, restated below from the theory) integrated along a right-angle crossing
// of two straight lines (Hertz-like, softer than k_c at first touch, so its contacts last longer: its runs
// get 40 steps per twice the reference's time to maximum compression). The absorbed work is then the law's
// work, integrated along the reference. Measured, distributed: the struck beam's Eq. 5 mass and peak force
// within 3 % (see the RecordProperty output); the stiff contact on the spring-supported mass within 1 %;
// the soft and as-stiff cases are known failures (see their instantiation).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "support/ContactChecks.hpp"
#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"

namespace tangle {
namespace {

constexpr double kPi = 3.141592653589793;

struct LinearImpact {
  double eq5Mass = 0.0;       // impulse to maximum compression / v0 [kg]
  double absorbedWork = 0.0;  // contact spring energy at maximum compression [J]
  double peakForce = 0.0;     // largest contact force up to maximum compression [N]
  double time = 0.0;          // from first touch to maximum compression [s]
};

/// Contact force [N] as a function of the compression [m] (the approach of the two centrelines since first
/// touch).
using ContactForceLaw = std::function<double(double)>;

/// A striker (mass m [kg], speed v0 [m/s] towards the struck line) on a contact spring `law` against a
/// struck line given by its modes at the contact point: generalised masses [kg], stiffnesses [N/m] and
/// mode shape values at the point [-], all at rest at first touch. Integrated with RK4 at dt [s] from
/// first touch to maximum compression (the first instant the relative velocity is no longer closing): the
/// impact phase of docs/theory.md 9.10. The absorbed work is the law's work up to there (trapezoidal
/// along the steps).
LinearImpact contactImpact(double m, double v0, const ContactForceLaw& law,
                           const std::vector<double>& modalMass, const std::vector<double>& modalStiffness,
                           const std::vector<double>& shape, double dt) {
  const int modes = static_cast<int>(modalMass.size());
  // State: striker displacement and velocity (towards the line), then q_i and dq_i/dt per mode.
  std::vector<double> y(2 + 2 * modes, 0.0), k1, k2, k3, k4, tmp;
  y[1] = v0;
  auto atPoint = [&](const std::vector<double>& s, int offset) {
    double w = 0.0;
    for (int i = 0; i < modes; ++i) w += shape[i] * s[offset + 2 * i];
    return w;
  };
  auto rate = [&](const std::vector<double>& s, std::vector<double>& d) {
    d.assign(s.size(), 0.0);
    const double force = law(s[0] - atPoint(s, 2));
    d[0] = s[1];
    d[1] = -force / m;
    for (int i = 0; i < modes; ++i) {
      d[2 + 2 * i] = s[3 + 2 * i];
      d[3 + 2 * i] = (shape[i] * force - modalStiffness[i] * s[2 + 2 * i]) / modalMass[i];
    }
  };
  auto plus = [&](const std::vector<double>& d, double h) {
    tmp = y;
    for (std::size_t i = 0; i < y.size(); ++i) tmp[i] += h * d[i];
    return tmp;
  };
  LinearImpact result;
  double impulse = 0.0, work = 0.0;
  for (long step = 0; step < 100000000; ++step) {
    const double compressionBefore = y[0] - atPoint(y, 2);
    const double forceBefore = law(compressionBefore);
    rate(y, k1);
    rate(plus(k1, 0.5 * dt), k2);
    rate(plus(k2, 0.5 * dt), k3);
    rate(plus(k3, dt), k4);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    const double compression = y[0] - atPoint(y, 2);
    const double force = law(compression);
    impulse += 0.5 * (forceBefore + force) * dt;
    work += 0.5 * (forceBefore + force) * (compression - compressionBefore);
    result.peakForce = std::max(result.peakForce, force);
    const double closing = y[1] - atPoint(y, 3);
    if (step > 10 && closing <= 0.0) {
      result.eq5Mass = impulse / (v0 - closing);  // the relative velocity has just reversed
      result.absorbedWork = work;
      result.time = (step + 1) * dt;
      return result;
    }
  }
  return result;
}

/// The point formulation's contact spring: linear, k [N/m] (docs/theory.md 9.4).
ContactForceLaw linearLaw(double k) {
  return [k](double c) { return c > 0.0 ? k * c : 0.0; };
}

/// The distributed formulation's law per unit length (docs/theory.md 9.11, restated here from the theory,
/// not taken from the code): with D the smaller contact diameter, p0 = D/100, p1 = D/4, pmax = D/2 and
/// k_line = k / D,  f = k_line p^2 / (2 p0) up to p0, k_line (p - p0/2) beyond, plus from p1 the barrier
/// k_line (pmax - p1) (p - p1)^2 / (pmax - p)^2.
double distributedLineForce(double p, double k, double diameter) {
  const double p0 = 0.01 * diameter, p1 = 0.25 * diameter, pmax = 0.5 * diameter, kLine = k / diameter;
  if (p <= 0.0) return 0.0;
  double f = p < p0 ? 0.5 * kLine * p * p / p0 : kLine * (p - 0.5 * p0);
  if (p > p1) f += kLine * (pmax - p1) * (p - p1) * (p - p1) / ((pmax - p) * (pmax - p));
  return f;
}

/// Its force [N] at a right-angle crossing of two straight lines whose centrelines have approached by c
/// from first touch (distance R - c, R the sum of the radii): the law integrated along either line, where
/// the penetration is R - sqrt((R - c)^2 + u^2) (the two passes of 9.11 integrate the same pressure), by
/// composite Simpson on [0, u_max] with 400 intervals (the integrand and its slope vanish at u_max),
/// tabulated at 20 000 compressions up to the law's limit D / 2 and interpolated linearly (relative error of
/// order 1e-7 where the force matters).
ContactForceLaw crossingLaw(double k, double diameter, double radii) {
  auto integral = [=](double c) {
    const double d = radii - c, uMax = std::sqrt(radii * radii - d * d);
    constexpr int kIntervals = 400;
    const double h = uMax / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double u = i * h, weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += weight * distributedLineForce(radii - std::sqrt(d * d + u * u), k, diameter);
    }
    return 2.0 * sum * h / 3.0;  // both sides of the crossing point
  };
  constexpr int kPoints = 20000;
  const double limit = 0.5 * diameter * (1.0 - 1e-6), dc = limit / kPoints;
  auto table = std::make_shared<std::vector<double>>(kPoints + 1);
  for (int i = 0; i <= kPoints; ++i) (*table)[i] = integral(i * dc);
  return [table, dc](double c) {
    if (c <= 0.0) return 0.0;
    const double x = c / dc;
    const auto i = static_cast<std::size_t>(x);
    if (i + 1 >= table->size()) return std::numeric_limits<double>::infinity();  // through the barrier
    return (*table)[i] + (x - i) * ((*table)[i + 1] - (*table)[i]);
  };
}

// ---- 1. Rigid mass on a spring-supported line -------------------------------------------------------

constexpr double kWireSpan = 10.0, kWireTension = 1.0e4, kWireEA = 1.0e7, kWireMassPerLength = 0.01;
constexpr double kLumpedMass = 30.0;  // attachment at the wire's middle [kg]
constexpr double kBarDiameter = 0.1;      // steel section of the bar [m]
constexpr double kContactDiameter = 0.4;  // both lines: room for the soft contact's penetration [m]
constexpr double kBarLength = 0.5, kBarDensity = 7850.0, kApproach = 0.2;

/// k_c / K and the contact formulation.
class SpringSupportedMass : public ::testing::TestWithParam<std::tuple<double, model::ContactFormulation>> {};

TEST_P(SpringSupportedMass, ImpactEnergyMatchesTheTwoMassSolution) {
  const double supportStiffness = 4.0 * kWireTension / kWireSpan;  // K [N/m]
  const double contactStiffness = std::get<0>(GetParam()) * supportStiffness;
  const model::ContactFormulation formulation = std::get<1>(GetParam());
  const bool distributed = formulation == model::ContactFormulation::Distributed;

  model::ModelSpec spec;
  spec.sourceFile = "rigid mass on a spring-supported line (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 0.0;
  spec.lineTypes["wire"] = test::cableType("wire", kBarDiameter, kWireMassPerLength, kWireEA);
  spec.lineTypes["wire"].contactDiameter = kContactDiameter;
  spec.lineTypes["wire"].addedMassNormal = 0.0;
  section::LineType bar = test::solidRodType("bar", kBarDiameter, 2.1e11, kBarDensity);
  bar.contactDiameter = kContactDiameter;
  bar.bendingStiffness = 0.0;  // a cable: a rigid mass when hit at its middle
  bar.torsionalStiffness = 0.0;
  bar.addedMassNormal = 0.0;
  spec.lineTypes["bar"] = bar;
  const double z = 10.0, gap = 0.002;
  const double unstretched = kWireSpan / (1.0 + kWireTension / kWireEA);
  model::LineSpec wire = test::simpleLine("wire", "wire", unstretched, 10, model::EndKind::Pinned,
                                          Vec3(-0.5 * kWireSpan, 0, z), model::EndKind::Pinned,
                                          Vec3(0.5 * kWireSpan, 0, z));
  model::AttachmentSpec lump;
  lump.arcLength = 0.5 * unstretched;
  lump.mass = kLumpedMass;
  wire.attachments.push_back(lump);
  spec.lines = {wire, test::simpleLine("bar", "bar", kBarLength, 1, model::EndKind::Free,
                                       Vec3(0, -0.5 * kBarLength, z + kContactDiameter + gap),
                                       model::EndKind::Free, Vec3(0, 0.5 * kBarLength, z + kContactDiameter + gap))};
  spec.contact.enabled = true;
  spec.contact.restitution = 1.0;
  spec.contact.stiffness = contactStiffness;
  spec.contact.formulation = formulation;
  spec.dynamics.enabled = true;
  const double barMass = bar.massPerLength * kBarLength;
  const double reduced = barMass * kLumpedMass / (barMass + kLumpedMass);
  // The two-mass system: the lump (with the wire's middle node, 0.01 kg) on the wire's spring K, struck
  // through the formulation's contact law (the distributed one's Hertz-like crossing of the two 0.4 m
  // contact diameters).
  const double lumpMass = kLumpedMass + kWireMassPerLength * unstretched / 10.0;
  const double linearDuration = kPi * std::sqrt(reduced / contactStiffness);
  const LinearImpact ref =
      contactImpact(barMass, kApproach,
                    distributed ? crossingLaw(contactStiffness, kContactDiameter, kContactDiameter)
                                : linearLaw(contactStiffness),
                    {lumpMass}, {supportStiffness}, {1.0}, linearDuration * 1e-5);
  // The run resolves the contact in 40 steps (the distributed law's is longer than the linear spring's:
  // twice the reference's time to maximum compression).
  const double contactDuration = distributed ? 2.0 * ref.time : linearDuration;
  spec.dynamics.duration = gap / kApproach + 3.0 * contactDuration;
  spec.dynamics.timeStep = contactDuration / 40.0;
  spec.dynamics.outputInterval = spec.dynamics.duration;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::Line& barLine = m.lines()[1];
  for (int n = barLine.firstNode; n <= barLine.lastNode(); ++n)
    sim.state().velocity.segment<3>(m.dofs().firstDof(n)) = Vec3(0, 0, -kApproach);
  // No gravity: the wire's equilibrium is the straight line between its ends, where it starts.
  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;

  const auto& events = sim.contact()->events();
  ASSERT_GE(events.size(), 1u);
  const contact::ContactEvent& impact = events.front();
  EXPECT_TRUE(impact.impact);
  EXPECT_EQ(impact.phaseEnd, "reversed");
  EXPECT_NEAR(impact.impactVelocity, kApproach, 0.01 * kApproach);
  EXPECT_EQ(impact.energyMassBasis, "eq5");
  EXPECT_NEAR(impact.eq5Mass, ref.eq5Mass, 0.01 * ref.eq5Mass);
  const double energy = 0.5 * ref.eq5Mass * kApproach * kApproach;
  EXPECT_NEAR(impact.impactEnergy, energy, 0.01 * energy);
  EXPECT_NEAR(impact.peakForce, ref.peakForce, 0.02 * ref.peakForce);
  EXPECT_NEAR(impact.phaseWork, ref.absorbedWork, 0.02 * ref.absorbedWork);
  // The warning follows the reference's own ratio of the two estimates.
  const double ratio = energy / ref.absorbedWork;
  if (ratio > 1.1 * contact::kEnergyAgreement) {
    EXPECT_FALSE(impact.energyWarning.empty());
  }
  if (ratio < 0.9 * contact::kEnergyAgreement) {
    EXPECT_TRUE(impact.energyWarning.empty()) << impact.energyWarning;
  }
  // The wire is held and throws the lump back: with k_c = K / 20 the mass engaged is 1.5 % above the
  // bar's own, so a held line puts no upper bound on it.
  EXPECT_TRUE(std::isinf(impact.massUpperBound));
  EXPECT_GE(impact.energyMass, impact.massLowerBound);

  RecordProperty("reference_eq5_mass_kg", fmt::format("{:.4g}", ref.eq5Mass));
  RecordProperty("energy_over_absorbed", fmt::format("{:.3g}", ratio));
  RecordProperty("eq5_mass_relative_error", fmt::format("{:.3e}", impact.eq5Mass / ref.eq5Mass - 1.0));
  RecordProperty("absorbed_relative_error", fmt::format("{:.3e}", impact.phaseWork / ref.absorbedWork - 1.0));
  RecordProperty("peak_force_relative_error", fmt::format("{:.3e}", impact.peakForce / ref.peakForce - 1.0));
}

// k_c = 100 K: a short impact of the two masses, close to their reduced mass (15.2 kg); k_c = K: the
// support spring takes part (16.2 kg); k_c = K / 20: the lump moves little on its spring before the
// long, soft contact stops the bar (31.3 kg: the lump, thrown back by the wire, pushes the bar back
// before the approach stops).
const auto kFormulations = test::bothFormulations();
std::string caseName(const ::testing::TestParamInfo<std::tuple<double, model::ContactFormulation>>& p) {
  return test::formulationName(std::get<1>(p.param));
}

INSTANTIATE_TEST_SUITE_P(SoftContact, SpringSupportedMass,
                         ::testing::Combine(::testing::Values(0.05),
                                            ::testing::Values(model::ContactFormulation::Point)),
                         caseName);
INSTANTIATE_TEST_SUITE_P(ContactAsStiffAsSupport, SpringSupportedMass,
                         ::testing::Combine(::testing::Values(1.0),
                                            ::testing::Values(model::ContactFormulation::Point)),
                         caseName);
INSTANTIATE_TEST_SUITE_P(StiffContact, SpringSupportedMass,
                         ::testing::Combine(::testing::Values(100.0), kFormulations), caseName);
// Known failures, run by ctest as expected to fail (validation.distributed_impact_energy_soft_expected_fail
// and validation.distributed_impact_energy_as_stiff_expected_fail, tests/CMakeLists.txt). Measured
// 2026-11-30, distributed formulation against the reference with its own crossing law: k_c = K / 20, Eq. 5
// mass 32.25 kg against 30.91 (+4.4 %), peak force 15.82 against 15.44 N (+2.5 %); k_c = K, 17.71
// against 17.48 kg (+1.3 %), peak 37.83 against 37.61 N (+0.6 %); the same at a tenth of the step (not the
// time integration). k_c = 100 K passes (15.30 kg, 208.6 N, -0.1 %). The absorbed work agrees (+0.37 % and
// +0.16 %): the law and the deepest approach are right; what differs is the Eq. 5 quotient, impulse over the
// change of the force-weighted relative velocity at the reversal. The error grows with the penetration: at
// k_c = K / 20 the centrelines approach by 9 cm and the contact spreads +-0.27 m along the wire, whose 1 m
// elements put part of it on the nodes either side of the lump (the C1 curve's four-node stencils), where the
// reference has a point load on the lump; and the soft contact lasts 1.3 periods of the lump on its spring,
// so the Eq. 5 mass at the reversal is sensitive to the lump's phase. Not resolved.
INSTANTIATE_TEST_SUITE_P(
    DistributedKnownFailures, SpringSupportedMass,
    ::testing::Combine(::testing::Values(0.05, 1.0),
                       ::testing::Values(model::ContactFormulation::Distributed)),
    [](const ::testing::TestParamInfo<std::tuple<double, model::ContactFormulation>>& p) {
      return std::get<0>(p.param) < 0.5 ? "soft" : "as_stiff_as_support";
    });

// ---- 2. Simply supported beam struck at mid-span ----------------------------------------------------

constexpr double kBeamLength = 10.0, kBeamDiameter = 0.2, kSteelE = 2.1e11, kSteelDensity = 7850.0;
constexpr double kStrikerLength = 0.5, kStrikeSpeed = 1.0, kBeamContactStiffness = 1.0e7;

class SimplySupportedBeam : public ::testing::TestWithParam<model::ContactFormulation> {};

TEST_P(SimplySupportedBeam, StruckAtMidSpanMatchesTheModalSolution) {
  const bool distributed = GetParam() == model::ContactFormulation::Distributed;
  model::ModelSpec spec;
  spec.sourceFile = "simply supported beam struck at mid-span (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 0.0;
  section::LineType steel = test::solidRodType("steel", kBeamDiameter, kSteelE, kSteelDensity);
  steel.addedMassNormal = 0.0;
  spec.lineTypes["steel"] = steel;
  const double z = 10.0, gap = 0.001;
  spec.lines = {test::simpleLine("beam", "steel", kBeamLength, 20, model::EndKind::Pinned,
                                 Vec3(-0.5 * kBeamLength, 0, z), model::EndKind::Pinned,
                                 Vec3(0.5 * kBeamLength, 0, z)),
                test::simpleLine("striker", "steel", kStrikerLength, 1, model::EndKind::Free,
                                 Vec3(0, -0.5 * kStrikerLength, z + kBeamDiameter + gap), model::EndKind::Free,
                                 Vec3(0, 0.5 * kStrikerLength, z + kBeamDiameter + gap))};
  spec.contact.enabled = true;
  spec.contact.restitution = 1.0;
  spec.contact.stiffness = kBeamContactStiffness;
  spec.contact.formulation = GetParam();
  spec.dynamics.enabled = true;
  spec.dynamics.duration = gap / kStrikeSpeed + (distributed ? 0.06 : 0.03);
  spec.dynamics.timeStep = 2.5e-4;
  spec.dynamics.outputInterval = spec.dynamics.duration;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::Line& striker = m.lines()[1];
  double strikerMass = 0.0;
  for (int n = striker.firstNode; n <= striker.lastNode(); ++n) {
    strikerMass += m.nodeMass()[n];
    sim.state().velocity.segment<3>(m.dofs().firstDof(n)) = Vec3(0, 0, -kStrikeSpeed);
  }
  const time::DynamicResult run = sim.runDynamics(nullptr);
  ASSERT_TRUE(run.completed) << run.message;

  // Symmetric modes sin(n pi x / L), n = 1, 3, ..., 99: generalised mass mu L / 2, stiffness
  // (n pi / L)^4 EI L / 2, value sin(n pi / 2) = +-1 at mid-span.
  std::vector<double> modalMass, modalStiffness, shape;
  for (int n = 1; n <= 99; n += 2) {
    modalMass.push_back(steel.massPerLength * kBeamLength / 2.0);
    modalStiffness.push_back(std::pow(n * kPi / kBeamLength, 4) * steel.bendingStiffness * kBeamLength / 2.0);
    shape.push_back((n / 2) % 2 == 0 ? 1.0 : -1.0);
  }
  const LinearImpact ref =
      contactImpact(strikerMass, kStrikeSpeed,
                    distributed ? crossingLaw(kBeamContactStiffness, kBeamDiameter, kBeamDiameter)
                                : linearLaw(kBeamContactStiffness),
                    modalMass, modalStiffness, shape, 2.0e-7);
  const double beamMass = steel.massPerLength * kBeamLength;
  const double firstModeReduced = strikerMass * 0.5 * beamMass / (strikerMass + 0.5 * beamMass);
  ASSERT_GT(ref.eq5Mass, 0.0);
  EXPECT_LT(ref.eq5Mass, firstModeReduced);  // the reference's own sanity: a short contact engages less

  const auto& events = sim.contact()->events();
  ASSERT_GE(events.size(), 1u);
  const contact::ContactEvent& impact = events.front();
  EXPECT_TRUE(impact.impact);
  EXPECT_EQ(impact.phaseEnd, "reversed");
  EXPECT_EQ(impact.energyMassBasis, "eq5");
  EXPECT_NEAR(impact.eq5Mass, ref.eq5Mass, 0.03 * ref.eq5Mass);
  const double refEnergy = 0.5 * ref.eq5Mass * kStrikeSpeed * kStrikeSpeed;
  EXPECT_NEAR(impact.impactEnergy, refEnergy, 0.03 * refEnergy);
  EXPECT_NEAR(impact.phaseWork, ref.absorbedWork, 0.03 * ref.absorbedWork);
  EXPECT_NEAR(impact.peakForce, ref.peakForce, 0.03 * ref.peakForce);
  test::expectImpactEnergiesWithinBounds(events);

  RecordProperty("reference_eq5_mass_kg", fmt::format("{:.4g}", ref.eq5Mass));
  RecordProperty("first_mode_reduced_mass_kg", fmt::format("{:.4g}", firstModeReduced));
  RecordProperty("eq5_mass_relative_error", fmt::format("{:.3e}", impact.eq5Mass / ref.eq5Mass - 1.0));
  RecordProperty("absorbed_relative_error", fmt::format("{:.3e}", impact.phaseWork / ref.absorbedWork - 1.0));
}

INSTANTIATE_TEST_SUITE_P(Formulations, SimplySupportedBeam, kFormulations, test::formulationTestName);

}  // namespace
}  // namespace tangle
