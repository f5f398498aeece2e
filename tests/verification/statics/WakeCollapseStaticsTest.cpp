// Statics of two lazy-wave risers side by side across a current, the downstream one in the upstream one's
// wake (Huse), hung 12 m apart (issue 43: "statics of two risers in current with wake interference,
// touching: converges with contact"; DNV-RP-F203's wake-induced collapse). 1000 m each in 500 m of water,
// 150 m of buoyancy (0.9 m) from 400 m on a 0.35 m flexible, 0.8 m/s at the surface across the pair, 0.2 m/s
// at the seabed; 50 elements per line.
//
// Without the wake the two lines are the same line under the same loads, 12 m apart: the solution is a
// translation, so every node of one is 12 m from its twin (checked to 1 mm: the convergence tolerance of
// 1 N on lateral stiffnesses of tens of N/m). With the wake the downstream line loses drag and the upstream
// one swings onto it: the static solve must end with the two in contact (a force on the upstream line from
// the downstream one, against the current, mostly across the flow) and no line through the other. The
// current continuation's Newton stalled at drag fraction 0.34 on the tangent without the drag's dependence on
// the deficit; the arc-length stage (docs/theory.md 7.1 stage 2c, 12.2) follows the path to the contact.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

/// The pair hung `gap` m apart (12, 4 or 20), in a current of `surfaceSpeed` m/s at the surface.
std::string lazyWavePair(bool wake, int gap = 12, const std::string& surfaceSpeed = "0.8") {
  std::string yaml = R"(environment:
  water_depth: 500
  current:
    - {z: 0, speed: @SPEED@, azimuth: 90}
    - {z: -500, speed: 0.2, azimuth: 90}
  seabed: {normal_stiffness: 1.0e5, friction_coefficient: 0.5}
line_types:
  - {name: flex, outer_diameter: 0.35, mass_per_length: 160, axial_stiffness: 7.0e8, bending_stiffness: 1.0e5,
     drag_normal: 1.2, added_mass_normal: 1.0}
  - {name: buoyant, outer_diameter: 0.9, mass_per_length: 350, axial_stiffness: 7.0e8, bending_stiffness: 1.0e5,
     drag_normal: 1.2, added_mass_normal: 1.0}
lines:
  - name: up
    contact: true
    end_a: {type: pinned, position: [0, @UP@, -20]}
    end_b: {type: anchored, position: [700, @UP@, -500]}
    sections: [{type: flex, length: 400, elements: 20}, {type: buoyant, length: 150, elements: 8},
               {type: flex, length: 450, elements: 22}]
  - name: down
    contact: true
    end_a: {type: pinned, position: [0, @DOWN@, -20]}
    end_b: {type: anchored, position: [700, @DOWN@, -500]}
    sections: [{type: flex, length: 400, elements: 20}, {type: buoyant, length: 150, elements: 8},
               {type: flex, length: 450, elements: 22}]
contact: {restitution: 0.5, clearance_margin: 50}
statics: {max_iterations: 2000}
)";
  if (wake) yaml += "wake_interference:\n  - {upstream: up, downstream: down, model: huse}\n";
  for (const auto& [token, value] : {std::pair<std::string, std::string>{"@UP@", std::to_string(-gap / 2)},
                                     {"@DOWN@", std::to_string(gap / 2)},
                                     {"@SPEED@", surfaceSpeed}})
    for (std::size_t at = yaml.find(token); at != std::string::npos; at = yaml.find(token))
      yaml.replace(at, token.size(), value);
  return yaml;
}

TEST(WakeCollapseStatics, WithoutTheWakeTheTwinLinesStayTwelveMetresApart) {
  analysis::Simulation sim(io::readModelString(lazyWavePair(false), "pair.yaml"));
  const solver::StaticResult result = sim.solveStatics();
  ASSERT_TRUE(result.converged) << result.message;
  const model::Line& up = sim.model().lines()[0];
  const model::Line& down = sim.model().lines()[1];
  ASSERT_EQ(up.nodeCount, down.nodeCount);
  double worst = 0.0;
  for (int i = 0; i < up.nodeCount; ++i) {
    const Vec3 d = sim.state().position[down.firstNode + i] - sim.state().position[up.firstNode + i];
    worst = std::max(worst, (d - Vec3(0, 12, 0)).norm());
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(sim.contact()->pairForce(0, 1).norm(), 0.0, 1e-9);
}

/// Solves the statics of `yaml` and checks what every in-wake case must end with: converged on its own mesh
/// past the stall by the arc-length stage, no line through the other, the upstream line pushed against the
/// current. Returns the contact force on the upstream line [N].
Vec3 expectRestingInContact(const std::string& yaml) {
  analysis::Simulation sim(io::readModelString(yaml, "pair.yaml"));
  const solver::StaticResult result = sim.solveStatics();
  EXPECT_TRUE(result.converged) << result.message;
  if (!result.converged) return Vec3::Zero();
  EXPECT_LE(result.residual, result.tolerance) << result.message;
  EXPECT_GT(result.arcLengthSteps, 0) << result.message;
  EXPECT_EQ(sim.contact()->rejectState(sim.state()), "");
  const Vec3 onUpstream = sim.contact()->pairForce(0, 1);
  EXPECT_LT(onUpstream.y(), -1.0) << "no contact force against the current on the upstream line";
  return onUpstream;
}

TEST(WakeCollapseStatics, InTheWakeTheLinesRestInContact) {
  // On its own mesh, past the stall by the arc-length stage (without it: 8 994 Newton iterations and 5.8 s
  // CPU through the quarter mesh's equilibrium; with it 1 615 and 1.2 s; with the wake's coupling to the
  // upstream element in its tangent, docs/theory.md 12.2, 719 and 0.6 s).
  const Vec3 onUpstream = expectRestingInContact(lazyWavePair(true));
  EXPECT_GT(-onUpstream.y(), 0.8 * onUpstream.norm()) << "contact force not across the flow";
}

// Hung 4 m apart the buoyancy sections (0.9 m) nearly touch already in still water: the lines lie along each
// other from drag fraction 0.05 on, 10-100 um deep over hundreds of metres, with several dips per element,
// and roll along each other as the current grows. Before 2026-12-03 the path stalled there (at drag fraction
// 0.46 with 1.3 N against the 0.96 N tolerance: the tangent without the wake's coupling to the upstream line;
// with the 100-element mesh at 0.82 with 1.9-2.9 N: the contact's force jumped where two of its intervals
// merged) and the statics failed after 158 s CPU. Measured now: 2.7 s CPU; in contact between arcs 169 and
// 403 m of the upstream line, 0.92 kN in all.
TEST(WakeCollapseStatics, HungFourMetresApartTheyRestAlongEachOther) {
  const std::string yaml = lazyWavePair(true, 4);
  ASSERT_NE(yaml.find("[0, -2, -20]"), std::string::npos);
  ASSERT_NE(yaml.find("[700, 2, -500]"), std::string::npos);
  expectRestingInContact(yaml);
}

// Anchored 20 m apart in 1.5 m/s: the lower catenaries run along the current, each end 20 m behind the other,
// and the downstream line's midpoints project onto the upstream line near its anchor and near its nodes.
// Before 2026-12-06 the wake's axis was the chords, each point projected square to one of them, and the wake
// stopped at the line's ends: a point in the wedge outside a kink of the upstream line took the node with
// the tangent of whichever element the walk came from, so the same state gave deficits 5 % apart between
// evaluations, and the arc length stalled near the downstream line's anchor (6-60 N against 0.96 N). This
// model failed after 53 s CPU at 14db8a7 (`tangle run`) and takes about 1 s now (on 100 elements per line:
// 54 s to fail, now 1.4 s). The lines do not touch, so the upstream line carries exactly the loads it
// carries without the wake (the wake acts on the downstream line only): both solutions must give the same
// upstream line, within 2 cm (the out-of-balance allowance of 0.96 N against the lateral stiffness of the
// buoyant hump, of order its tension over its span, 1e5 N / 500 m = 200 N/m: 5 mm, four times for two
// solutions that stop at different points within it). And the downstream line, sheltered, must be pushed
// less far downstream than without the wake (by more than 1 m).
TEST(WakeCollapseStatics, AnchoredTwentyMetresApartTheUpstreamLineIsAsWithoutTheWake) {
  analysis::Simulation inWake(io::readModelString(lazyWavePair(true, 20, "1.5"), "pair.yaml"));
  const solver::StaticResult result = inWake.solveStatics();
  ASSERT_TRUE(result.converged) << result.message;
  EXPECT_LE(result.residual, result.tolerance) << result.message;
  ASSERT_NEAR(inWake.contact()->pairForce(0, 1).norm(), 0.0, 1e-9)
      << "the lines touch: the check below needs them apart";
  analysis::Simulation alone(io::readModelString(lazyWavePair(false, 20, "1.5"), "pair.yaml"));
  ASSERT_TRUE(alone.solveStatics().converged);
  const model::Line& up = inWake.model().lines()[0];
  const model::Line& down = inWake.model().lines()[1];
  double worstUpstream = 0.0, shelter = 0.0;  // [m]
  for (int i = 0; i < up.nodeCount; ++i) {
    worstUpstream = std::max(
        worstUpstream,
        (inWake.state().position[up.firstNode + i] - alone.state().position[up.firstNode + i]).norm());
    shelter = std::max(shelter, alone.state().position[down.firstNode + i].y() -
                                    inWake.state().position[down.firstNode + i].y());
  }
  EXPECT_LT(worstUpstream, 0.02);
  EXPECT_GT(shelter, 1.0) << "the wake did not hold the downstream line back";
  RecordProperty("upstream_difference_m", std::to_string(worstUpstream));
  RecordProperty("shelter_m", std::to_string(shelter));
}

}  // namespace
}  // namespace tangle
