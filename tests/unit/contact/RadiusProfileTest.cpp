/// Tests of tangle::contact::RadiusProfile (the contact radius along a line, docs/theory.md 9.11) and of the
/// clearances that use it: at a change of section the surface a clearance measures is the one the contact
/// presses on. Expected values are hand computations from the profile's definition: the section's radius
/// away from a change; over |r1 - r2| of arc centred on the node the smootherstep from one to the other, the
/// mean at the node.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {
namespace {

constexpr double kThick = 0.2;      // [m]
constexpr double kThin = 0.075;     // [m]
constexpr double kStriker = 0.125;  // [m]

/// A straight line along +y at x = 0, z = -50 from y = -10: 10 m thick (D 0.4 m, 1 m elements), 10 m thin
/// (D 0.15 m), one 1 m element of the thick section, 5 m thin; and a striker along +x at y = `strikerY` whose
/// end node lies at x = -0.5 m (D 0.25 m).
model::ModelSpec sectionChange(double strikerY) {
  model::ModelSpec spec;
  spec.sourceFile = "radius profile (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["thick"] = test::cableType("thick", 2.0 * kThick, 100.0, 1e9);
  spec.lineTypes["thin"] = test::cableType("thin", 2.0 * kThin, 20.0, 1e8);
  spec.lineTypes["striker"] = test::cableType("striker", 2.0 * kStriker, 50.0, 1e9);
  model::LineSpec target = test::simpleLine("target", "thick", 10.0, 10, model::EndKind::Pinned,
                                            Vec3(0, -10, -50), model::EndKind::Pinned, Vec3(0, 16, -50));
  target.sections.push_back({"thin", 10.0, 10});
  target.sections.push_back({"thick", 1.0, 1});
  target.sections.push_back({"thin", 5.0, 5});
  spec.lines = {target, test::simpleLine("striker", "striker", 20.0, 20, model::EndKind::Pinned,
                                         Vec3(-20.5, strikerY, -50), model::EndKind::Pinned,
                                         Vec3(-0.5, strikerY, -50))};
  return spec;
}

TEST(RadiusProfile, TapersOverTheDifferenceOfTheRadiiCentredOnTheNode) {
  const model::Model m(sectionChange(0.3));
  const model::Line& target = m.lines()[0];
  const RadiusProfile profile(m);
  const int last = target.firstElement + 9, first = target.firstElement + 10;  // either side of y = 0
  // Away from the change: each section's own.
  EXPECT_EQ(profile.at(target.firstElement + 5, 0.5), kThick);
  EXPECT_EQ(profile.at(first, 0.5), kThin);
  // The taper: |r1 - r2| = 0.125 m of arc centred on the node, so 0.0625 m into each 1 m element.
  EXPECT_EQ(profile.at(last, 1.0 - 0.0625), kThick);
  EXPECT_EQ(profile.at(first, 0.0625), kThin);
  EXPECT_NEAR(profile.at(last, 1.0), 0.5 * (kThick + kThin), 1e-15);
  EXPECT_NEAR(profile.at(first, 0.0), 0.5 * (kThick + kThin), 1e-15);
  // A quarter into the taper (u = 1/4 from the thick end): S(1/4) = 0.103515625.
  EXPECT_NEAR(profile.at(last, 1.0 - 0.03125), kThick + (kThin - kThick) * 0.103515625, 1e-15);
  // C1 across the node: the same slope in arc length from both elements (1 m each).
  EXPECT_NEAR(profile.profile(last, 1.0)[1], profile.profile(first, 0.0)[1], 1e-12);
  EXPECT_NEAR(profile.profile(first, 0.0)[1], 1.875 * (kThin - kThick) / 0.125, 1e-12);
  // Bounds and ends.
  EXPECT_NEAR(profile.largest(first), 0.5 * (kThick + kThin), 1e-15);
  EXPECT_EQ(profile.largest(last), kThick);
  EXPECT_EQ(profile.largest(target.firstElement + 20), kThick);  // the one thick element between thin ones
  EXPECT_NEAR(profile.taperEnds(first)[0], 0.0625, 1e-15);
  EXPECT_EQ(profile.taperEnds(first)[1], 1.0);
  // Node radii: the profile's at each node.
  const std::vector<double>& nodes = profile.nodeRadius();
  EXPECT_EQ(nodes[static_cast<std::size_t>(target.firstNode)], kThick);
  EXPECT_NEAR(nodes[static_cast<std::size_t>(target.firstNode + 10)], 0.5 * (kThick + kThin), 1e-15);
  EXPECT_EQ(nodes[static_cast<std::size_t>(target.firstNode + 15)], kThin);
  EXPECT_EQ(nodes[static_cast<std::size_t>(m.lines()[1].firstNode + 20)], kStriker);
}

// The striker's end node 0.5 m from the target's axis at y = 0.3 m, on the thin side of the change at y = 0
// and clear of its taper (which ends at y = 0.0625 m): its clearance is 0.5 - 0.075 - 0.125 = 0.3 m. Until
// 2026-12-07 the envelope took the radius of the segment's nearer node, the larger section's at a change:
// 0.5 - 0.2 - 0.125 = 0.175 m (a striker against a thin line next to its thick section reported -0.147 m
// where the contact pressed 3.3 cm deep). Level with the node (y = 0): the mean radius there, 0.1375 m.
TEST(RadiusProfile, TheEnvelopeMeasuresANodeAgainstTheSurfaceAtItsClosestPoint) {
  for (const auto& [y, expected] :
       {std::pair{0.3, 0.5 - kThin - kStriker}, std::pair{0.0, 0.5 - 0.5 * (kThick + kThin) - kStriker}}) {
    const model::Model m(sectionChange(y));
    const model::State s = m.initialState();
    const ClearanceEnvelope envelope(m, {{0, 1}});
    const std::vector<double> clearance = envelope.nodeClearance(s, 1, 0);
    ASSERT_EQ(clearance.size(), 21u);
    EXPECT_NEAR(clearance[20], expected, 1e-12) << "striker at y = " << y;
  }
}

// The clash report's clearance of the same pair: the thin element at 0.5 m gives 0.3 m, the thick element
// (nearest at the junction node, sqrt(0.5^2 + 0.3^2) = 0.583 m) 0.583 - 0.1375 - 0.125 = 0.321 m with the
// radius the profile has at the node; with the thick section's radius there (before 2026-12-07) it was
// 0.258 m, at the junction.
TEST(RadiusProfile, TheClashReportsClearanceIsTheSurfacesAtTheClosestPoints) {
  std::string yaml =
      "environment:\n  water_depth: 100\nline_types:\n"
      "  - {name: thick, outer_diameter: 0.4, mass_per_length: 100, axial_stiffness: 1.0e9}\n"
      "  - {name: thin, outer_diameter: 0.15, mass_per_length: 20, axial_stiffness: 1.0e8}\n"
      "  - {name: striker, outer_diameter: 0.25, mass_per_length: 50, axial_stiffness: 1.0e9}\n"
      "lines:\n"
      "  - name: target\n    end_a: {type: pinned, position: [0, -10, -50]}\n"
      "    end_b: {type: pinned, position: [0, 10, -50]}\n"
      "    sections: [{type: thick, length: 10, elements: 10}, {type: thin, length: 10, elements: 10}]\n"
      "  - name: striker\n    end_a: {type: pinned, position: [-20.5, 0.3, -50]}\n"
      "    end_b: {type: pinned, position: [-0.5, 0.3, -50]}\n"
      "    sections: [{type: striker, length: 20, elements: 20}]\n"
      "contact: {restitution: 0.5}\n";
  const model::ModelSpec spec = io::readModelString(yaml, "radius profile (test)");
  const model::Model m(spec);
  const model::State s = m.initialState();
  const LineContact contact(m, spec.contact, spec.dynamics.timeStep);
  const std::array<double, 3> c = contact.clearance(s, 0, 1);
  EXPECT_NEAR(c[0], 0.5 - kThin - kStriker, 1e-12);
  EXPECT_NEAR(c[1], 10.3, 1e-9);  // along the target [m]
  EXPECT_NEAR(c[2], 20.0, 1e-9);  // the striker's end
}

}  // namespace
}  // namespace tangle::contact
