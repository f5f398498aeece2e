// Issue 43: "A riser swept into a chain-wire mooring line at about 1 m/s, the contact sliding over wire
// nodes: runs through for restitution 0, 0.5 and 1, friction 0 and 0.5, and 1, 5 and 10 m wire elements,
// with impact energies within 10 % of each other across the meshes." (With the point formulation every
// variant of the seed paper's application stopped 45-85 s after such an impact, when the contact reached a
// wire node.)
//
// Set-up, in water (300 m deep), with the default (distributed) contact: a 96 mm mooring wire (38 kg/m,
// EA 800 MN, Cd 1.2) pinned at (-+200, 0, -100) m, 400.5 m long, so it hangs in a shallow catenary along x
// (sag about 12 m); a 21 in drilling riser (0.533 m, 420 kg/m, EA 4.55 GN, EI 111 MN m^2, Cd 1.0), 180 m,
// vertical at x = 0, y = -6 m, its ends pinned and driven together (motion tables, cubic) at 0.5 m/s^2 up to
// 1 m/s at 30 deg from +y towards +x: the riser hits the wire at 0.87 m/s normal to it (less the lag of its
// middle behind its driven ends under drag) and then pushes it while sliding along it at 0.5 m/s, 5.5 m in
// the 11 s to the end of the run, over 5 wire nodes with 1 m elements and one with 5 m.
//
// Checks (every case): the run completes; one contact event, an impact that becomes sustained (the riser is
// driven into the wire) and is still open at the end; its impact speed between 0.8 m/s and the drive's
// normal component 0.866 m/s (measured 0.835); the deepest overlap below a quarter of the wire's diameter
// (the barrier's start, docs/theory.md 9.11; measured 5.9-6.7 mm against 24 mm); the contact slides at
// least 4 m along the wire; on the mesh, Eq. 5 over the impact phase and the absorbed work within 5 % of
// each other (measured 1-2 %); the impact energy is the mesh-free continuum estimate (docs/theory.md 9.10)
// and the same on every mesh (below).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "support/ContactChecks.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

constexpr double kSweepAngle = 30.0;  // from +y towards +x [deg]
constexpr double kWireLength = 400.0;

/// The model (YAML, read as a user's file) with wire elements of `element` m.
std::string sweptRiser(double element, double restitution, double friction) {
  const double angle = kSweepAngle * 3.141592653589793 / 180.0;
  std::string rows;
  for (double t : {0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 20.0, 40.0, 80.0}) {
    const double s = t <= 2.0 ? 0.25 * t * t : 1.0 + (t - 2.0);  // 0.5 m/s^2 to 1 m/s, then steady [m]
    rows += fmt::format("          - [{}, {:.6f}, {:.6f}, 0]\n", t, s * std::sin(angle), s * std::cos(angle));
  }
  const std::string motion = "      motion:\n        interpolation: cubic\n        table:\n" + rows;
  return fmt::format(R"(title: riser swept into a mooring wire
environment:
  water_depth: 300
line_types:
  - {{name: wire96, outer_diameter: 0.096, mass_per_length: 38.0, axial_stiffness: 8.0e8, drag_normal: 1.2}}
  - {{name: riser21, outer_diameter: 0.533, mass_per_length: 420, axial_stiffness: 4.55e9, bending_stiffness: 1.11e8, torsional_stiffness: 8.5e7, drag_normal: 1.0}}
lines:
  - name: wire
    end_a: {{type: pinned, position: [-200, 0, -100]}}
    end_b: {{type: pinned, position: [200, 0, -100]}}
    sections: [{{type: wire96, length: 400.5, elements: {}}}]
  - name: riser
    end_a:
      type: pinned
      position: [0, -6, -190]
{}    end_b:
      type: pinned
      position: [0, -6, -10]
{}    sections: [{{type: riser21, length: 180, elements: 36}}]
contact: {{restitution: {}, friction_coefficient: {}}}
dynamics: {{duration: 20, time_step: 0.01, output_interval: 0.5, ramp_time: 0}}
)",
                     static_cast<int>(std::lround(kWireLength / element)), motion, motion, restitution,
                     friction);
}

/// The first contact event of a run of the model.
struct SweepResult {
  bool completed = false;
  std::string message;
  int events = 0;
  contact::ContactEvent first;
  double stiffness = 0.0;  ///< the pair's contact stiffness k (contact/summary.json) [N/m]
};

SweepResult sweep(double element, double restitution, double friction) {
  analysis::Simulation sim(
      io::readModelString(sweptRiser(element, restitution, friction), "swept-riser.yaml"));
  SweepResult r;
  if (!sim.solveStatics().converged) return r;
  const time::DynamicResult run = sim.runDynamics(nullptr);
  r.completed = run.completed;
  r.message = run.message;
  const contact::LineContact& contact = *sim.contact();
  std::vector<contact::ContactEvent> all = contact.events();
  all.insert(all.end(), contact.openEvents().begin(), contact.openEvents().end());
  r.events = static_cast<int>(all.size());
  r.stiffness = contact.pairStiffness(0, 1);
  if (!all.empty()) r.first = all.front();
  return r;
}

using SweepCase = std::tuple<double, double, double>;  // wire element [m], restitution, friction
class RiserSweptIntoWire : public ::testing::TestWithParam<SweepCase> {};

TEST_P(RiserSweptIntoWire, RunsThroughWithOneBoundedImpactThatSlidesAlongTheWire) {
  const auto [element, restitution, friction] = GetParam();
  const SweepResult r = sweep(element, restitution, friction);
  ASSERT_TRUE(r.completed) << r.message;
  ASSERT_EQ(r.events, 1);
  const contact::ContactEvent& e = r.first;
  EXPECT_TRUE(e.impact);
  EXPECT_TRUE(e.sustained);
  EXPECT_TRUE(e.open);
  const double normalDrive = std::cos(kSweepAngle * 3.141592653589793 / 180.0);
  EXPECT_GT(e.impactVelocity, 0.8);
  EXPECT_LT(e.impactVelocity, normalDrive);
  EXPECT_LT(e.maxPenetration, 0.25 * 0.096);
  EXPECT_GT(e.arcAMax - e.arcAMin, 4.0) << "the contact's range along the wire";
  EXPECT_EQ(e.phaseEnd, "reversed");
  EXPECT_NEAR(e.phaseWork, e.meshEnergy, 0.05 * e.meshEnergy);
  EXPECT_EQ(e.energyMassBasis, "continuum") << e.continuumNote;
  test::expectImpactEnergiesWithinBounds({e});
  RecordProperty("impact_energy_J", fmt::format("{:.4g}", e.impactEnergy));
  RecordProperty("eq5_mass_kg", fmt::format("{:.4g}", e.eq5Mass));
  RecordProperty("mesh_energy_J", fmt::format("{:.4g}", e.meshEnergy));
  RecordProperty("continuum_mass_kg", fmt::format("{:.4g}", e.continuumMass));
  RecordProperty("peak_force_N", fmt::format("{:.4g}", e.peakForce));
  RecordProperty("max_penetration_m", fmt::format("{:.3g}", e.maxPenetration));
}

std::string sweepName(const ::testing::TestParamInfo<SweepCase>& p) {
  const auto [element, restitution, friction] = p.param;
  return fmt::format("wire{}m_e{}_mu{}", static_cast<int>(element),
                     static_cast<int>(std::lround(100 * restitution)),
                     static_cast<int>(std::lround(100 * friction)));
}

INSTANTIATE_TEST_SUITE_P(Issue43, RiserSweptIntoWire,
                         ::testing::Combine(::testing::Values(10.0, 5.0, 1.0),
                                            ::testing::Values(0.0, 0.5, 1.0), ::testing::Values(0.0, 0.5)),
                         sweepName);

// Issue 43: "the energy and mass of one physical impact within 10 % between 10, 5 and 1 m elements".
// What the mesh engages is about one wire element with its added mass (45 kg/m), because a wire node's
// mass oscillates on the contact's stiffness and turns round after half its period: measured 2026-11-30
// (e = 0.5, mu = 0) 187.4 / 102.8 / 20.6 J (mesh_energy_J) with Eq. 5 masses of 536 / 295 / 59 kg. The
// taut wire has no such node: struck by the far heavier riser its point acts as a dashpot of impedance
// 2 sqrt(T mu) = 9.5 kN s/m, and through the contact's 12.7 MN/m the impact engages Z^2 / k = 7 kg, 0.16 m
// of wire, over 2.3 ms (docs/theory.md 9.10; to resolve it the wire would need elements of a few cm). The
// impact energy is that mesh-free estimate, from the lines' tension, mass and bending stiffness at first
// contact: the same on every mesh within the spread of the impact speed and of the tension there.
//
// The impact's peak force goes with its energy (issue 43: "a peak contact force consistent with the impact
// (energy and contact stiffness)"; the riser "swept into a leg ... peak force within a factor 2 of the hand
// estimate from the impact energy and the contact stiffness"): impact_peak_force_N, on the energy's basis,
// the same on every mesh within the energy's 10 %, and within a factor 2 of sqrt(2 E k), E the impact
// energy and k the pair's contact stiffness (contact/summary.json: the distributed law's point stiffness,
// 12.7 MN/m; the crossing law stiffens as p^1.5, so the linear spring's estimate is only a hand estimate).
// Measured 2026-12-06: 10.52 / 10.52 / 10.51 kN against sqrt(2 E k) = 12.1 kN (0.87). The mesh's own peak
// over the impact phase is what the element's lumped mass on the law gives: 85.1 / 59.6 / 22.4 kN, 7.0 /
// 4.9 / 1.85 times the hand estimate, and it was the only peak force reported before (as the event's).
TEST(RiserSweptIntoWire, ImpactEnergyIsTheSameOnEveryWireMesh) {
  std::map<double, double> energy, force;
  for (double element : {10.0, 5.0, 1.0}) {
    const SweepResult r = sweep(element, 0.5, 0.0);
    ASSERT_TRUE(r.completed) << r.message;
    ASSERT_EQ(r.first.energyMassBasis, "continuum") << r.first.continuumNote;
    energy[element] = r.first.impactEnergy;
    force[element] = r.first.impactPeakForce;
    const double handEstimate = std::sqrt(2.0 * r.first.impactEnergy * r.stiffness);
    EXPECT_GT(r.first.impactPeakForce, 0.5 * handEstimate) << element << " m elements";
    EXPECT_LT(r.first.impactPeakForce, 2.0 * handEstimate) << element << " m elements";
    RecordProperty(fmt::format("impact_energy_{}m_J", static_cast<int>(element)),
                   fmt::format("{:.4g}", energy[element]));
    RecordProperty(fmt::format("mesh_energy_{}m_J", static_cast<int>(element)),
                   fmt::format("{:.4g}", r.first.meshEnergy));
    RecordProperty(fmt::format("impact_peak_force_{}m_N", static_cast<int>(element)),
                   fmt::format("{:.4g}", r.first.impactPeakForce));
    RecordProperty(fmt::format("mesh_impact_peak_force_{}m_N", static_cast<int>(element)),
                   fmt::format("{:.4g}", r.first.phasePeakForce));
    RecordProperty(fmt::format("event_peak_force_{}m_N", static_cast<int>(element)),
                   fmt::format("{:.4g}", r.first.peakForce));
    RecordProperty(fmt::format("hand_estimate_{}m_N", static_cast<int>(element)),
                   fmt::format("{:.4g}", handEstimate));
  }
  EXPECT_NEAR(energy[5.0], energy[1.0], 0.1 * energy[1.0]);
  EXPECT_NEAR(energy[10.0], energy[1.0], 0.1 * energy[1.0]);
  EXPECT_NEAR(force[5.0], force[1.0], 0.1 * force[1.0]);
  EXPECT_NEAR(force[10.0], force[1.0], 0.1 * force[1.0]);
}

}  // namespace
}  // namespace tangle
