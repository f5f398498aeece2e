// Issue 43: "two flexible risers closing at 1 m/s ...: complete; peak force within a factor 2 of the hand
// estimate from the impact energy and the contact stiffness" (the point formulation reported 315 kN for an
// impact whose energy and stiffness give 8 kN). Two 20 m lengths of a 0.3 m flexible riser (150 kg/m,
// EA 500 MN, EI 50 kN m^2), free, straight, one launched at the other at 1 m/s, with the distributed
// formulation and an explicit contact stiffness k = 600 kN/m (k_line = k / D = 2 MN/m^2, D = 0.3 m).
// Both fall freely together (gravity acts on both alike, so the relative motion is the one in zero
// gravity; with no gravity the convergence test, scaled by the lines' weights, has no scale), in air.
//
// Parallel (the risers side by side along their length): every point of both lines moves alike, so the
// impact is one degree of freedom per unit length, the reduced mass mu = m / 2 = 75 kg/m against the law
// f(p) (BarrierPenalty, docs/theory.md 9.11: k p^2 / (2 p0) to p0 = D / 100, then k (p - p0 / 2)). With
// no dashpot (e = 1) the largest penetration p* has the law's work W(p*) = mu v^2 / 2 = 37.5 J/m
// (W = k p0^2 / 6 + k ((p - p0/2)^2 - (p0/2)^2) / 2 beyond p0): p* = 7.56 mm, and the peak force is
// L k_line (p* - p0 / 2) = 242.5 kN. Below e = 1 the restitution is hysteresis (ContactLaw.hpp
// HystereticRestitution): the law loads along (1 + a) f, a = (1 - e^2) / (1 + e^2), so p* has
// (1 + a) W(p*) = mu v^2 / 2 and the peak is (1 + a) L k_line (p* - p0 / 2) (e = 0.5: 304.8 kN; e = 0:
// 339.4 kN, bounded and decreasing in e, where a dashpot of damping ratio 100 gave 5.74 MN); it unloads along
// (1 - a) f, giving back e^2 of the impact's energy. Tolerance 1 %: the peak between two of the ~40 steps
// of the impact (a sampled cosine peak is low by at most (pi / 40)^2 / 2 = 0.3 %), the integrator's
// dissipation (rho_inf = 0.8, a fraction of a percent over an impact) and the law's smoothing near the
// deepest point (v_s = 0.011 m/s: 0.1 % of the peak, by RK4 of the law alone). The rebound: its kinetic
// energy (v_r / v)^2 within 0.01 of e^2 (1 % of the impact energy, as the peak; at e = 0 the smoothing lets
// the lines part at 0.045 m/s, 0.2 % of the energy); the event's impact speed 1 m/s and its Eq. 5 mass, the
// reduced mass of the two whole lines L m / 2 = 1500 kg, 1 % (one step of 40 at the phase's end).
//
// Crossing (at a right angle): the penetration along each line is p - u^2 / (2 R) (R = rA + rB), and the
// law's linear part integrates to the Hertz-like F = (4/3) k_line sqrt(2 R) p^(3/2) with the work
// W = (8/15) k_line sqrt(2 R) p^(5/2) (DistributedContact.hpp). The hand estimate of the peak force sets W
// to the impact's energy (the event's 1/2 m_Eq5 v^2), with the loading branch (1 + a) F at e < 1 (a peak
// (1 + a)^0.4 times the elastic one at the same energy); the issue asks for a factor 2 (the law's quadratic
// start, the mass taking part growing during the impact). The energy is the mesh-free continuum estimate
// (docs/theory.md 9.10); what the mesh engaged must lie between the reduced masses of one element of each
// line and of the two whole lines.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kDiameter = 0.3;  // [m]
constexpr double kMass = 150.0;    // [kg/m]
constexpr double kLength = 20.0;   // [m]
constexpr int kElements = 10;
constexpr double kStiffness = 6.0e5;  // contact.stiffness k [N/m]
constexpr double kSpeed = 1.0;        // closing speed [m/s]
constexpr double kStartGap = 0.1;     // surface gap at launch [m]
constexpr double kZ = 100.0;          // in air throughout the fall [m]

struct ClosingCase {
  bool parallel;
  double restitution;
};

struct ClosingRun {
  bool completed = false;
  std::string message;
  std::vector<contact::ContactEvent> events;
  double reboundSpeed = 0.0;  // relative speed apart along the launch direction at the end [m/s]
};

/// Line A along x at the origin; line B along x (parallel) or y (crossing), one diameter plus the start gap
/// away along z, launched towards A at kSpeed.
ClosingRun runClosing(const ClosingCase& c, int elements = kElements) {
  model::ModelSpec spec;
  spec.sourceFile = "risers closing (test)";
  spec.environment.waterDepth = 50.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["riser"] = test::beamType("riser", kDiameter, kMass, 5.0e8, 5.0e4, 0.0, 0.0);
  const double offset = kDiameter + kStartGap;
  const Vec3 a0(-0.5 * kLength, 0, kZ), a1(0.5 * kLength, 0, kZ);
  const Vec3 b0 = c.parallel ? Vec3(-0.5 * kLength, 0, kZ + offset) : Vec3(0, -0.5 * kLength, kZ + offset);
  const Vec3 b1 = c.parallel ? Vec3(0.5 * kLength, 0, kZ + offset) : Vec3(0, 0.5 * kLength, kZ + offset);
  spec.lines.push_back(
      test::simpleLine("A", "riser", kLength, elements, model::EndKind::Free, a0, model::EndKind::Free, a1));
  spec.lines.push_back(
      test::simpleLine("B", "riser", kLength, elements, model::EndKind::Free, b0, model::EndKind::Free, b1));
  spec.contact.enabled = true;
  spec.contact.formulation = model::ContactFormulation::Distributed;
  spec.contact.stiffness = kStiffness;
  spec.contact.restitution = c.restitution;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = 0.4;
  spec.dynamics.timeStep = 0.005;
  spec.dynamics.outputInterval = 0.05;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::DofMap& dofs = m.dofs();
  for (int i = 0; i < 2; ++i) {
    const model::Line& line = m.lines()[static_cast<std::size_t>(i)];
    const Vec3 start = i == 0 ? a0 : b0, end = i == 0 ? a1 : b1;
    for (int n = line.firstNode; n <= line.lastNode(); ++n) {
      // Straight and unstretched (a free line's start shape is a taut catenary between its ends).
      const double s = static_cast<double>(n - line.firstNode) / (line.nodeCount - 1);
      sim.state().position[n] = start + s * (end - start);
      if (i == 1) sim.state().velocity.segment<3>(dofs.firstDof(n)) = Vec3(0, 0, -kSpeed);
    }
  }
  ClosingRun out;
  const time::DynamicResult run = sim.runDynamics([](const model::State&, const VecX&) {}, false);
  out.completed = run.completed;
  out.message = run.message;
  out.events = sim.contact()->events();
  // Mean vertical velocity of each line's nodes (equal node masses along each line but its ends: weighted).
  const auto meanVelocity = [&](int i) {
    const model::Line& line = m.lines()[static_cast<std::size_t>(i)];
    double mass = 0.0, momentum = 0.0;
    for (int n = line.firstNode; n <= line.lastNode(); ++n) {
      mass += m.nodeMass()[n];
      momentum += m.nodeMass()[n] * sim.state().velocity[dofs.firstDof(n) + 2];
    }
    return momentum / mass;
  };
  out.reboundSpeed = meanVelocity(1) - meanVelocity(0);
  return out;
}

/// The impact: the event with the largest impulse (the first of equals). Side by side, the first touch of the
/// whole length opens an event of 1e-26 N that closes at once, and the impact is a second event: a defect of
/// the event tracker noted in issue 43, not of the contact.
const contact::ContactEvent& largestImpulse(const std::vector<contact::ContactEvent>& events) {
  const contact::ContactEvent* impact = &events.front();
  for (const contact::ContactEvent& e : events)
    if (e.impulse > impact->impulse) impact = &e;
  return *impact;
}

/// Work of the law per unit length up to penetration p [J/m] (the law's definition, BarrierPenalty; below
/// the barrier's start).
double lawWork(double k, double p0, double p) {
  if (p <= p0) return k * p * p * p / (6.0 * p0);
  return k * p0 * p0 / 6.0 + 0.5 * k * ((p - 0.5 * p0) * (p - 0.5 * p0) - 0.25 * p0 * p0);
}

class RisersClosing : public ::testing::TestWithParam<ClosingCase> {};

TEST_P(RisersClosing, CompleteWithThePeakForceOfTheImpactEnergy) {
  const ClosingCase c = GetParam();
  const ClosingRun run = runClosing(c);
  ASSERT_TRUE(run.completed) << run.message;
  ASSERT_FALSE(run.events.empty());
  const contact::ContactEvent& first = largestImpulse(run.events);
  RecordProperty("events", std::to_string(run.events.size()));
  const double kLine = kStiffness / kDiameter;  // [N/m^2]
  const double p0 = 0.01 * kDiameter;
  RecordProperty("peak_force_N", fmt::format("{:.5g}", first.peakForce));
  RecordProperty("impact_energy_J", fmt::format("{:.5g}", first.impactEnergy));
  RecordProperty("energy_mass_kg", fmt::format("{:.5g}", first.energyMass));
  RecordProperty("energy_mass_basis", first.energyMassBasis);
  RecordProperty("mesh_mass_kg", fmt::format("{:.5g}", first.meshMass));
  RecordProperty("work_mass_kg", fmt::format("{:.5g}", first.workMass));
  RecordProperty("continuum_mass_kg", fmt::format("{:.5g}", first.continuumMass));
  RecordProperty("continuum_note", first.continuumNote);
  RecordProperty("rebound_speed_m_s", fmt::format("{:.5g}", run.reboundSpeed));
  RecordProperty("max_penetration_m", fmt::format("{:.4g}", first.maxPenetration));
  EXPECT_NEAR(first.impactVelocity, kSpeed, 0.01 * kSpeed);
  // No overlap beyond the barrier's bound (half the smaller diameter).
  EXPECT_LT(first.maxPenetration, 0.5 * kDiameter);
  if (c.parallel) {
    const double pairMass = 0.5 * kMass * kLength;  // [kg]
    EXPECT_NEAR(first.energyMass, pairMass, 0.01 * pairMass);
    // p* from (1 + a) W(p*) = mu v^2 / 2 by bisection on the law's work.
    const double e2 = c.restitution * c.restitution;
    const double loading = 1.0 + (1.0 - e2) / (1.0 + e2);                    // 1 + a
    const double perLength = 0.5 * 0.5 * kMass * kSpeed * kSpeed / loading;  // [J/m]
    double lo = 0.0, hi = 0.25 * kDiameter;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (lawWork(kLine, p0, mid) < perLength ? lo : hi) = mid;
    }
    const double pStar = 0.5 * (lo + hi);
    const double expected = loading * kLength * kLine * (pStar - 0.5 * p0);
    RecordProperty("expected_peak_force_N", fmt::format("{:.5g}", expected));
    EXPECT_NEAR(first.peakForce, expected, 0.01 * expected);
    // Rebound energy e^2 of the impact's (file comment).
    const double reboundFraction = run.reboundSpeed * run.reboundSpeed / (kSpeed * kSpeed);
    RecordProperty("rebound_energy_fraction", fmt::format("{:.5g}", reboundFraction));
    EXPECT_NEAR(reboundFraction, e2, 0.01);
    EXPECT_GT(run.reboundSpeed, 0.0);
  } else {
    // What the mesh engaged: at least one element of each line's, at most the two whole lines' (reduced);
    // the impact's mass (the continuum estimate, docs/theory.md 9.10: the crossing is a point on lines
    // whose bending waves do not reach their ends within it) at most the whole lines'.
    const double elementPair = 0.5 * kMass * kLength / kElements, linePair = 0.5 * kMass * kLength;
    EXPECT_EQ(first.energyMassBasis, "continuum") << first.continuumNote;
    EXPECT_GE(first.meshMass, elementPair * (1.0 - 1e-9));
    EXPECT_LE(first.meshMass, linePair * (1.0 + 1e-9));
    EXPECT_LE(first.energyMass, linePair * (1.0 + 1e-9));
    const double radii = kDiameter;
    // The loading branch (1 + a) F (file comment): (1 + a) W(p*) = E.
    const double e2 = c.restitution * c.restitution;
    const double loading = 1.0 + (1.0 - e2) / (1.0 + e2);
    const double pStar =
        std::pow(first.impactEnergy / (loading * (8.0 / 15.0) * kLine * std::sqrt(2.0 * radii)), 0.4);
    const double expected = loading * (4.0 / 3.0) * kLine * std::sqrt(2.0 * radii) * std::pow(pStar, 1.5);
    RecordProperty("expected_peak_force_N", fmt::format("{:.5g}", expected));
    EXPECT_GT(first.peakForce, 0.5 * expected);
    EXPECT_LT(first.peakForce, 2.0 * expected);
    EXPECT_LE(run.reboundSpeed, kSpeed * (1.0 + 1e-3));  // no energy created
  }
}

// The crossing's mesh-free participating mass (docs/theory.md 9.10) against the same impact on a mesh that
// resolves it: 40 elements of 0.5 m (the participating lengths are 0.8 m of each riser; 160 elements gave
// the same masses within 0.3 %, measured 2026-12-03). On untensioned beams the point impedance has a 45
// degree phase, half mass and half dashpot, and the converged mesh's two measures part: the momentum's
// (Eq. 5) and the energy's (the contact's work) are 119.8 / 137.4 / 156.9 kg and 94.6 / 84.3 / 79.9 kg at
// e = 1 / 0.5 / 0 (four times finer impact steps: 119.7 / 137.0 / 158.0 and 94.6 / 84.2 / 79.8 kg; before
// the step limit judged a crossing by its own law, 2026-12-04, Eq. 5 came to 120.0 / 137.4 / 151.9 kg),
// the estimate 132.0 / 117.9 / 111.8 kg (the 10-element mesh's Eq. 5: 157 / 156 / 155 kg). The check: the
// estimate within the converged mesh's band, widened by 10 % (the estimate's single frequency and secant
// law, theory 9.10 "What is approximate"). At e = 1 the estimate is 1.102 times the converged Eq. 5 mass,
// just outside: a known failure (ctest validation.continuum_mass_crossing_e100_expected_fail), passed by
// 0.02 % while the impact steps were coarser.
class RisersCrossingResolved : public ::testing::TestWithParam<double> {};

TEST_P(RisersCrossingResolved, TheContinuumMassLiesWithinTheResolvedMeshsMeasures) {
  const ClosingRun run = runClosing(ClosingCase{false, GetParam()}, 40);
  ASSERT_TRUE(run.completed) << run.message;
  ASSERT_FALSE(run.events.empty());
  const contact::ContactEvent& e = largestImpulse(run.events);
  ASSERT_EQ(e.energyMassBasis, "continuum") << e.continuumNote;
  ASSERT_TRUE(std::isfinite(e.eq5Mass) && std::isfinite(e.workMass));
  RecordProperty("eq5_mass_kg", fmt::format("{:.5g}", e.eq5Mass));
  RecordProperty("work_mass_kg", fmt::format("{:.5g}", e.workMass));
  RecordProperty("continuum_mass_kg", fmt::format("{:.5g}", e.continuumMass));
  const double low = std::min(e.eq5Mass, e.workMass), high = std::max(e.eq5Mass, e.workMass);
  EXPECT_GE(e.continuumMass, 0.9 * low);
  EXPECT_LE(e.continuumMass, 1.1 * high);
}

std::string caseName(const ::testing::TestParamInfo<ClosingCase>& p) {
  return fmt::format("{}_e{:.0f}", p.param.parallel ? "parallel" : "crossing", 100.0 * p.param.restitution);
}

INSTANTIATE_TEST_SUITE_P(Distributed, RisersClosing,
                         ::testing::Values(ClosingCase{true, 1.0}, ClosingCase{true, 0.5},
                                           ClosingCase{true, 0.0}, ClosingCase{false, 1.0},
                                           ClosingCase{false, 0.5}, ClosingCase{false, 0.0}),
                         caseName);
std::string restitutionName(const ::testing::TestParamInfo<double>& p) {
  return fmt::format("e{:.0f}", 100.0 * p.param);
}

INSTANTIATE_TEST_SUITE_P(Distributed, RisersCrossingResolved, ::testing::Values(0.5, 0.0), restitutionName);
INSTANTIATE_TEST_SUITE_P(DistributedKnownFailures, RisersCrossingResolved, ::testing::Values(1.0),
                         restitutionName);

}  // namespace
}  // namespace tangle
