// Validation against the seed paper, section 6.1 (Silva, Pereira & Jacob 2007): two identical simply
// supported beams cross at right angles, initially close but not touching; their supports are moved
// slowly towards each other (speed < 0.0005 m/s) so the midspans press on each other. With
// E = 70 GPa, L = 1.2 m, solid circular d = 20 mm and a midspan deflection u = d/4 = 5 mm of each beam,
// the contact force is P = 48 E I u / L^3 = 76.4 N and the midspan moment M = P L / 4 = 22.9 N m
// (Euler-Bernoulli, small deflection). The paper reports the same result for 2 to 60 elements per beam
// and time steps from 0.1 s to 0.0001 s.
//
// Tolerance 1 % (the bound). Known deviations below it: the penalty penetration P / k (k =
// 0.1 EA / L_element >= 3.7e6 N/m, so P/k <= 2e-5 m = 0.4 % of u, split between the two beams: the
// force is lower by ~0.2 %), and the geometric nonlinearity of a 5 mm deflection on 1.2 m (u/L = 0.4 %;
// one end of each beam is a roller, so there is no membrane tension).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/core/Units.hpp"

namespace tangle {
namespace {

constexpr double kE = 70.0e9, kRho = 2680.0, kL = 1.2, kD = 0.02;
constexpr double kU = kD / 4.0;     // midspan deflection of each beam [m]
constexpr double kGap = 1.0e-4;     // initial clearance between the beams [m]
constexpr double kHeight = 10.0;    // in air, above the water [m]
constexpr double kRampTime = 12.0;  // support speed (U / T) = 0.42 mm/s < 0.5 mm/s

struct Case {
  int elements;
  double timeStep;
  model::ContactFormulation formulation = model::ContactFormulation::Distributed;
};

/// Quasi-static averages over the last second of the run.
struct PressedBeams {
  bool completed = false;
  std::string message;
  double force = 0.0;         ///< contact force [N]
  double moment[2] = {0, 0};  ///< midspan bending moments [N m]
  double penetration = 0.0;   ///< overlap of the two surfaces [m] (minus the clearance)
  int contactCount = 0;       ///< most contact patches at once
};

PressedBeams pressBeams(const Case& c) {
  model::ModelSpec spec;
  spec.sourceFile = "perpendicular beams (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = 0.0;  // the paper's closed form has no self weight
  spec.lineTypes["rod"] = test::solidRodType("rod", kD, kE, kRho);
  const double r = 0.5 * kD;
  const double z1 = kHeight + r + 0.5 * kGap, z2 = kHeight - r - 0.5 * kGap;
  // Supports travel U = u + gap/2 so that each midspan deflects exactly u once the gap has closed.
  const double travel = kU + 0.5 * kGap;
  model::LineSpec b1 =
      test::simpleLine("beam1", "rod", kL, c.elements, model::EndKind::Pinned, Vec3(-0.5 * kL, 0, z1),
                       model::EndKind::Pinned, Vec3(0.5 * kL, 0, z1));
  model::LineSpec b2 =
      test::simpleLine("beam2", "rod", kL, c.elements, model::EndKind::Pinned, Vec3(0, -0.5 * kL, z2),
                       model::EndKind::Pinned, Vec3(0, 0.5 * kL, z2));
  for (model::EndSpec* end : {&b1.endA, &b1.endB, &b2.endA, &b2.endB}) {
    const double sign = end == &b1.endA || end == &b1.endB ? -1.0 : 1.0;
    end->motion.enabled = true;
    end->motion.table = {{0.0, 0.0, 0.0, 0.0}, {kRampTime, 0.0, 0.0, sign * travel}};
  }
  // Simply supported: end B of each beam slides freely along the beam's axis (a roller), so no
  // membrane tension builds up (with both ends pinned, a 5 mm sag would stretch the beam and add ~13 N).
  b1.endB.release[0] = true;
  b2.endB.release[1] = true;
  spec.lines = {b1, b2};
  spec.contact.enabled = true;
  spec.contact.formulation = c.formulation;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = kRampTime + 1.0;
  spec.dynamics.timeStep = c.timeStep;
  spec.dynamics.outputInterval = std::max(0.1, c.timeStep);
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  PressedBeams out;
  if (!sim.solveStatics().converged) {
    out.message = "statics did not converge";
    return out;
  }
  // Quasi-static values: averages over the last second, after the supports have stopped (the first
  // touch excites small vibrations of the beams that the small time steps resolve and hardly damp).
  double forceSum = 0.0, momentSum[2] = {0.0, 0.0}, penetrationSum = 0.0;
  int samples = 0, contactCount = 0;
  const time::DynamicResult run = sim.runDynamics([&](const model::State& s, const VecX&) {
    if (s.time < kRampTime + 1e-9) return;
    // The contact patches at the committed state (either formulation: a point contact, or the Gauss
    // points of one crossing).
    int touching = 0;
    for (const contact::ContactPatch& patch : sim.contact()->patches()) {
      if (patch.force <= 0.0) continue;
      ++touching;
      forceSum += patch.force;
    }
    contactCount = std::max(contactCount, touching);
    const auto lines = sim.snapshot(true);
    for (int l = 0; l < 2; ++l) momentSum[l] += lines[l].bendingMoment[lines[l].bendingMoment.size() / 2];
    penetrationSum -= sim.contact()->clearance(s, 0, 1)[0];
    ++samples;
  });
  out.completed = run.completed;
  out.message = run.message;
  if (samples == 0) return out;
  out.force = forceSum / samples;
  for (int l = 0; l < 2; ++l) out.moment[l] = momentSum[l] / samples;
  out.penetration = penetrationSum / samples;
  out.contactCount = contactCount;
  return out;
}

class PerpendicularBeams : public ::testing::TestWithParam<Case> {};

double beamInertia() { return kPi * std::pow(kD, 4) / 64.0; }

TEST_P(PerpendicularBeams, ContactForceAndMidspanMomentMatchBeamTheory) {
  const PressedBeams r = pressBeams(GetParam());
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_EQ(r.contactCount, 1) << "exactly one contact patch between the midspans";
  const double expectedP = 48.0 * kE * beamInertia() * kU / std::pow(kL, 3);  // 76.4 N
  const double expectedM = expectedP * kL / 4.0;                              // 22.9 N m
  EXPECT_NEAR(expectedP, 76.4, 0.05);  // the paper's number, as a check of the set-up
  RecordProperty("force_N", std::to_string(r.force));
  RecordProperty("penetration_m", std::to_string(r.penetration));
  EXPECT_NEAR(r.force, expectedP, 0.01 * expectedP);
  for (int l = 0; l < 2; ++l) EXPECT_NEAR(r.moment[l], expectedM, 0.01 * expectedM) << "beam " << l + 1;
}

// The same beams with the contact's own compliance: the surfaces overlap by p, so each midspan deflects
// u - p/2 and P = 48 E I (u - p/2) / L^3 (beam theory with the contact a spring in series; p measured).
// Tolerance 1 % as above (the geometric nonlinearity, u/L = 0.4 %, is what is left).
class PerpendicularBeamsCompliance : public ::testing::TestWithParam<Case> {};

TEST_P(PerpendicularBeamsCompliance, ContactForceMatchesBeamTheoryWithTheContactCompliance) {
  const PressedBeams r = pressBeams(GetParam());
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_EQ(r.contactCount, 1) << "exactly one contact patch between the midspans";
  EXPECT_GT(r.penetration, 0.0);
  EXPECT_LT(r.penetration, 0.1 * kU) << "the contact is a stiff spring beside the beams";
  const double expectedP = 48.0 * kE * beamInertia() * (kU - 0.5 * r.penetration) / std::pow(kL, 3);
  EXPECT_NEAR(r.force, expectedP, 0.01 * expectedP);
  for (int l = 0; l < 2; ++l)
    EXPECT_NEAR(r.moment[l], expectedP * kL / 4.0, 0.01 * expectedP * kL / 4.0) << "beam " << l + 1;
}

std::string caseName(const ::testing::TestParamInfo<Case>& p) {
  return std::to_string(p.param.elements) + "elements_dt" +
         std::to_string(static_cast<int>(std::round(1.0 / p.param.timeStep)));
}

// The default formulation (distributed: Gauss points of each beam against the other's C1 centreline).
// Against the paper's 76.4 N it is 1.8 % low at its automatic stiffness (74.997 N with 2 elements and
// dt = 0.1 s): the two 20 mm rods overlap by 0.18 mm, where the point formulation's penalty overlaps by
// 0.02 mm. A crossing's force grows as p^1.5 (the contact length grows with the overlap), so at this
// small load the crossing is softer than the point stiffness it matches at p = (rA + rB) / 8 (2.5 mm).
// The compliance-corrected form passes (above); the paper's number runs as a known failure.
INSTANTIATE_TEST_SUITE_P(Paper61KnownFailures, PerpendicularBeams,
                         ::testing::Values(Case{2, 0.1}, Case{6, 0.01}, Case{20, 0.1}, Case{60, 0.1},
                                           Case{2, 0.001}),
                         caseName);

// The point formulation (docs/theory.md 9.0-9.8).
constexpr auto kPoint = model::ContactFormulation::Point;
INSTANTIATE_TEST_SUITE_P(Paper61Point, PerpendicularBeams,
                         ::testing::Values(Case{2, 0.1, kPoint}, Case{6, 0.01, kPoint}, Case{20, 0.1, kPoint},
                                           Case{60, 0.1, kPoint}, Case{2, 0.001, kPoint}),
                         caseName);

// Both formulations with the contact's compliance.
INSTANTIATE_TEST_SUITE_P(Paper61, PerpendicularBeamsCompliance,
                         ::testing::Values(Case{2, 0.1}, Case{6, 0.01}, Case{20, 0.1}, Case{60, 0.1},
                                           Case{2, 0.001}, Case{2, 0.1, kPoint}, Case{60, 0.1, kPoint}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return caseName(p) + (p.param.formulation == kPoint ? "_point" : "");
                         });

}  // namespace
}  // namespace tangle
