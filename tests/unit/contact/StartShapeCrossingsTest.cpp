// contact::liftCrossedStartShapes (StartShapeCrossings.hpp): the program's start shapes that pass through
// each other are laid one over the other, the later line over the earlier, before statics.
//
// Two cables 100 m long between pinned ends 99 m apart at the same depth, crossing at right angles in
// mid-water: both catenaries sag alike, so their mid-points coincide (axes 0 m apart, surfaces overlapping
// by the sum of the radii). A mid-water crossing (the seabed case is
// tests/validation/contact/SeabedCrossingTest.cpp).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/StartShapeCrossings.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

std::string crossingYaml(const std::string& startShapeOfB = "") {
  return R"(title: two cables crossing in mid-water
environment:
  water_depth: 200
line_types:
  - {name: rope, outer_diameter: 0.1, mass_per_length: 10, axial_stiffness: 1.0e8}
  - {name: hose, outer_diameter: 0.2, mass_per_length: 40, axial_stiffness: 1.0e8, bending_stiffness: 1.0e4, torsional_stiffness: 1.0e4}
lines:
  - name: a
    end_a: {type: pinned, position: [-49.5, 0, -50]}
    end_b: {type: pinned, position: [49.5, 0, -50]}
    sections: [{type: rope, length: 100, elements: 20}]
  - name: b
    end_a: {type: pinned, position: [0, -49.5, -50]}
    end_b: {type: pinned, position: [0, 49.5, -50]}
    sections: [{type: hose, length: 100, elements: 24}]
)" + startShapeOfB +
         "contact: {clearance_margin: 50}\n";
}

TEST(StartShapeCrossings, LaysTheLaterLineOverTheEarlierWhereTheirCatenariesCross) {
  const model::ModelSpec spec = io::readModelString(crossingYaml(), "crossing.yaml");
  model::Model model(spec);
  model::State state = model.initialState();
  contact::LineContact contact(model, spec.contact, spec.dynamics.timeStep);
  const double radii = 0.05 + 0.1;
  // The axes nearly meet (the heavier hose stretches and sags 3.5 cm more).
  const double overlap = -contact.clearance(state, 0, 1)[0];
  ASSERT_GT(overlap, 0.5 * radii);
  const model::State before = state;
  const std::vector<contact::StartShapeLift> lifts = contact::liftCrossedStartShapes(model, contact, state);
  ASSERT_EQ(lifts.size(), 1u);
  EXPECT_EQ(lifts[0].lowerLine, 0);
  EXPECT_EQ(lifts[0].upperLine, 1);
  // Square to both chords at the crossing (slopes of about 1 % there), so upwards within 1 deg.
  const Vec3 d = lifts[0].direction;
  EXPECT_GT(d.z(), std::cos(degToRad(1.0)));
  EXPECT_EQ(lifts[0].overlap, overlap);
  EXPECT_NE(lifts[0].describe(model).find("line 'b' laid over line 'a'"), std::string::npos);
  // Clear of each other, by about the 5 % of the radii aimed at (the curves between the moved nodes may
  // stand a little higher or lower than the chords).
  const double gap = contact.clearance(state, 0, 1)[0];
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, 0.2 * radii);
  // Line a unmoved; b's nodes moved up only, and only near the crossing: the node at it and its two
  // neighbours (an element's length either side) and the taper beyond them (two elements: twenty times the
  // move is less).
  const model::Line& a = model.lines()[0];
  const model::Line& b = model.lines()[1];
  for (int n = a.firstNode; n <= a.lastNode(); ++n) EXPECT_EQ(state.position[n], before.position[n]);
  for (int n = b.firstNode; n <= b.lastNode(); ++n) {
    const Vec3 move = state.position[n] - before.position[n];
    EXPECT_NEAR((move - move.dot(d) * d).norm(), 0.0, 1e-12);  // along d, forwards
    EXPECT_GE(move.dot(d), 0.0);
    if (std::abs(before.position[n].y()) > 3.0 * 100.0 / 24.0 + 1e-9) {
      EXPECT_EQ(move.norm(), 0.0) << "node " << n;
    }
  }
  // The moved line's triads follow its new shape (a beam: its bending starts from the shape, not from a
  // kink between the triads and the chords): each node's first axis along its neighbours' chord.
  for (int i = 1; i + 1 < b.nodeCount; ++i) {
    const Vec3 chord =
        (state.position[b.firstNode + i + 1] - state.position[b.firstNode + i - 1]).normalized();
    EXPECT_NEAR(state.triad[b.firstNode + i].col(0).dot(chord), 1.0, 1e-12) << "node " << i;
  }
}

TEST(StartShapeCrossings, LeavesLinesApartAndUserStartShapesAlone) {
  {
    const model::ModelSpec spec = io::readModelString(crossingYaml(), "crossing.yaml");
    model::ModelSpec apart = spec;
    for (auto* end : {&apart.lines[1].endA, &apart.lines[1].endB}) end->position.z() = -40.0;
    model::Model model(apart);
    model::State state = model.initialState();
    contact::LineContact contact(model, apart.contact, apart.dynamics.timeStep);
    const model::State before = state;
    EXPECT_TRUE(contact::liftCrossedStartShapes(model, contact, state).empty());
    EXPECT_EQ(state.position, before.position);
  }
  {
    // Line b drawn by the user straight through line a's sag: the user's geometry, not moved (Simulation
    // refuses it; this function leaves it alone).
    double sagZ = 0.0;
    {
      const model::Model plain(io::readModelString(crossingYaml(), "crossing.yaml"));
      const model::Line& a = plain.lines()[0];
      sagZ = plain.initialState().position[a.firstNode + a.nodeCount / 2].z();
    }
    const model::ModelSpec spec = io::readModelString(
        crossingYaml(fmt::format("    start_shape: [[0, 0, {}]]\n", sagZ)), "crossing.yaml");
    model::Model model(spec);
    model::State state = model.initialState();
    contact::LineContact contact(model, spec.contact, spec.dynamics.timeStep);
    ASSERT_LT(contact.clearance(state, 0, 1)[0], -0.5 * 0.15);
    const model::State before = state;
    EXPECT_TRUE(contact::liftCrossedStartShapes(model, contact, state).empty());
    EXPECT_EQ(state.position, before.position);
  }
}

}  // namespace
}  // namespace tangle
