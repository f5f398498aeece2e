// Issue 43: "Impact energy that converges with the mesh: the energy and mass of one physical impact within
// 10 % between 10, 5 and 1 m elements." At a shallow crossing the contact's patch is long beside the length
// of line whose mass takes part, and until 2026-12-07 the mesh-free estimate (docs/theory.md 9.10) gave way
// to the mesh's measurement as soon as the patch half-length passed a quarter of that length: two tensioned
// pipes crossing at 4 and 2 deg then read 332 and 338 kg on 5 m elements where the mesh that resolves them
// measures 79-107 and 92-111 kg (the contact's work and Eq. 5), three times the energy.
//
// Set-up (a user's YAML): two pipes (OD 0.25 m, 80 kg/m, EA 2 GN, EI 5 MN m^2, added mass 1), 60 m spans
// pinned at both ends and 3 cm short of them, so about 1 MN of tension, 2 m apart at their crossing in
// 100 m of water; the upper one at `angle` to the lower one, both its ends driven down (0.25 t^2 to 1 s,
// then 1 m/s): its middle meets the lower pipe's at 0.90 m/s, e = 0.5. Its waves take longer than the
// impact to reach the pinned ends (30 m at 88 m/s and more).
//
// The reference is the same impact on a mesh that resolves it: 0.25 m elements over the middle 6 m, which
// are at most a sixth of the participating length (0.125 m gave the same masses within 0.3 %, 2026-12-07).
// Its two measures part (the point impedance of a tensioned beam is part mass, part dashpot): Eq. 5's
// mass 107.3 / 111.3 / 199.7 kg and the work's 78.9 / 91.8 / 171.0 kg at 4 / 2 / 1 deg. The check is the
// one of RisersCrossingResolved (RisersClosingTest.cpp): the impact's mass on 5 m elements within that band
// widened by 10 % (the estimate's single frequency and secant law, theory 9.10 "What is approximate").
// Measured (2026-12-07): 100.9 kg and 89.9 kg from the estimate at 4 and 2 deg, whose patches are 0.28 and
// 0.56 of the participating length.
//
// At 1 deg the patch (1.37 m) is longer than the participating length (1.23 m): the estimate's 80.1 kg is
// half the resolved band and the mesh's own 365 kg on 5 m elements is twice it, so neither is right; the
// mesh's is reported with a note that says which elements would resolve the impact, and the reference runs
// as a known failure (ctest validation.shallow_crossing_1deg_expected_fail).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

/// The model with the pipes' elements: `coarse` 12 of 5 m, else 1 m elements with 0.25 m over the middle
/// 6 m.
std::string crossing(double angleDeg, bool coarse) {
  const double t = angleDeg * 3.141592653589793 / 180.0, cx = 30.0 * std::cos(t), cy = 30.0 * std::sin(t);
  const std::string sections =
      coarse ? "[{type: pipe, length: 59.97, elements: 12}]"
             : "[{type: pipe, length: 26.985, elements: 27}, {type: pipe, length: 6, elements: 24}, "
               "{type: pipe, length: 26.985, elements: 27}]";
  const std::string drive =
      "[[0, 0, 0, 0], [0.25, 0, 0, -0.015625], [0.5, 0, 0, -0.0625], [0.75, 0, 0, -0.140625], [1, 0, 0, "
      "-0.25], [10, 0, 0, -9.25]]";
  return fmt::format(R"(title: a pipe driven onto a crossing pipe at {angle} deg
environment:
  water_depth: 100
line_types:
  - {{name: pipe, outer_diameter: 0.25, mass_per_length: 80, axial_stiffness: 2.0e9, bending_stiffness: 5.0e6}}
lines:
  - name: lower
    end_a: {{type: pinned, position: [-30, 0, -50]}}
    end_b: {{type: pinned, position: [30, 0, -50]}}
    sections: {sections}
  - name: upper
    end_a: {{type: pinned, position: [{mx:.6f}, {my:.6f}, -48], motion: {{table: {drive}}}}}
    end_b: {{type: pinned, position: [{cx:.6f}, {cy:.6f}, -48], motion: {{table: {drive}}}}}
    sections: {sections}
contact: {{restitution: 0.5}}
dynamics: {{duration: 2.8, time_step: 0.005, ramp_time: 0, output_interval: 0.1}}
)",
                     fmt::arg("angle", angleDeg), fmt::arg("sections", sections), fmt::arg("mx", -cx),
                     fmt::arg("my", -cy), fmt::arg("cx", cx), fmt::arg("cy", cy), fmt::arg("drive", drive));
}

/// The run's first contact event (the impact), or a failure.
contact::ContactEvent firstImpact(double angleDeg, bool coarse) {
  analysis::Simulation sim(io::readModelString(crossing(angleDeg, coarse), "shallow-crossing.yaml"));
  EXPECT_TRUE(sim.solveStatics().converged);
  const time::DynamicResult run = sim.runDynamics(nullptr);
  EXPECT_TRUE(run.completed) << run.message;
  std::vector<contact::ContactEvent> all = sim.contact()->events();
  all.insert(all.end(), sim.contact()->openEvents().begin(), sim.contact()->openEvents().end());
  if (all.empty()) {
    ADD_FAILURE() << "no contact";
    return {};
  }
  EXPECT_TRUE(all.front().impact);
  return all.front();
}

class ShallowCrossing : public ::testing::TestWithParam<double> {};

TEST_P(ShallowCrossing, TheImpactMassOnFiveMetreElementsLiesWithinTheResolvedMeshsMeasures) {
  const double angle = GetParam();
  const contact::ContactEvent resolved = firstImpact(angle, false);
  const contact::ContactEvent coarse = firstImpact(angle, true);
  ASSERT_TRUE(std::isfinite(resolved.eq5Mass) && std::isfinite(resolved.workMass));
  RecordProperty("resolved_eq5_mass_kg", fmt::format("{:.5g}", resolved.eq5Mass));
  RecordProperty("resolved_work_mass_kg", fmt::format("{:.5g}", resolved.workMass));
  RecordProperty("coarse_energy_mass_kg", fmt::format("{:.5g}", coarse.energyMass));
  RecordProperty("coarse_basis", coarse.energyMassBasis);
  RecordProperty("coarse_note", coarse.continuumNote);
  EXPECT_NEAR(coarse.impactVelocity, 0.9, 0.01);
  const double low = std::min(resolved.eq5Mass, resolved.workMass);
  const double high = std::max(resolved.eq5Mass, resolved.workMass);
  EXPECT_GE(coarse.energyMass, 0.9 * low) << coarse.energyMassBasis << ": " << coarse.continuumNote;
  EXPECT_LE(coarse.energyMass, 1.1 * high) << coarse.energyMassBasis << ": " << coarse.continuumNote;
  // The impact's energy goes with its mass, whatever the basis.
  EXPECT_NEAR(coarse.impactEnergy, 0.5 * coarse.energyMass * coarse.impactVelocity * coarse.impactVelocity,
              1e-9 * coarse.impactEnergy);
}

// Where the estimate does not hold the analyst is told what mesh would measure the impact: elements of a
// third of the participating length (1.23 m at 1 deg: 0.41 m; 0.5 m elements there measured Eq. 5 within
// 0.5 % of the converged mass, 2026-12-07).
TEST(ShallowCrossingNote, WhereTheEstimateDoesNotHoldItSaysWhichElementsWouldResolveTheImpact) {
  const contact::ContactEvent e = firstImpact(1.0, true);
  EXPECT_EQ(e.energyMassBasis, "eq5");
  EXPECT_NE(e.continuumNote.find("a contact along a length"), std::string::npos) << e.continuumNote;
  EXPECT_NE(e.continuumNote.find("elements of at most 0.41 m"), std::string::npos) << e.continuumNote;
}

std::string angleName(const ::testing::TestParamInfo<double>& p) {
  return fmt::format("deg{}", static_cast<int>(std::lround(p.param)));
}

INSTANTIATE_TEST_SUITE_P(Issue43, ShallowCrossing, ::testing::Values(4.0, 2.0), angleName);
INSTANTIATE_TEST_SUITE_P(ShallowCrossingKnownFailures, ShallowCrossing, ::testing::Values(1.0), angleName);

}  // namespace
}  // namespace tangle
