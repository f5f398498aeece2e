// End tensions of LineResults at a free end (issue 32 review): a free end with nothing attached carries no
// force, whatever the end element's own section force; with a mass attached at it, the line holds the mass.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::solver {
namespace {

/// A 30 m hanging beam (3 elements, the last of a heavy type: a riser's LMRP) pinned at the top, free at
/// the bottom, straight down; optionally a 2 t mass at the free end.
model::ModelSpec hanging(bool massAtEnd) {
  model::ModelSpec spec;
  spec.sourceFile = "free end (test)";
  spec.environment.waterDepth = 200.0;
  spec.lineTypes["pipe"] = test::solidRodType("pipe", 0.3, 2.0e11, 7850.0);
  spec.lineTypes["lmrp"] = test::solidRodType("lmrp", 1.0, 2.0e11, 7850.0);
  model::LineSpec l = test::simpleLine("riser", "pipe", 20.0, 2, model::EndKind::Pinned, Vec3(0, 0, -10),
                                       model::EndKind::Free, Vec3(0, 0, -40));
  l.sections.push_back({"lmrp", 10.0, 1});
  if (massAtEnd) l.attachments.push_back({30.0, 2000.0, 0.0, 0.0, 0.0});
  spec.lines.push_back(l);
  return spec;
}

/// The line stretched by 0.1 % (every element in tension EA / 1000).
model::State stretched(analysis::Simulation& sim) {
  model::State s = sim.state();
  const model::Line& line = sim.model().lines()[0];
  for (int i = 0; i < line.nodeCount; ++i)
    s.position[static_cast<std::size_t>(line.firstNode + i)] = Vec3(0, 0, -10.0 - 1.001 * line.arcLength[static_cast<std::size_t>(i)]);
  return s;
}

TEST(LineResults, AFreeEndWithNothingAttachedHasNoEndTension) {
  analysis::Simulation sim(hanging(false));
  std::vector<LineSnapshot> out;
  computeLineResults(sim.model(), sim.assembler(), stretched(sim), nullptr, out, LineResultDetail::SectionForces);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_GT(out[0].endTensionA, 1e6);  // the held end: EA / 1000 of the pipe
  EXPECT_EQ(out[0].endTensionB, 0.0);
  EXPECT_EQ(out[0].endTensionForceB, Vec3::Zero());
  EXPECT_EQ(out[0].tension.back(), 0.0);
}

TEST(LineResults, AFreeEndWithAMassKeepsTheElementsForce) {
  analysis::Simulation sim(hanging(true));
  std::vector<LineSnapshot> out;
  computeLineResults(sim.model(), sim.assembler(), stretched(sim), nullptr, out, LineResultDetail::SectionForces);
  // Not zeroed: the line holds what is attached at its end (the value itself is the extrapolation's).
  EXPECT_GT(out[0].endTensionB, 1e6);
}

/// LineResultDetail::Ends (a coupled host's per-step fairlead tensions) gives the line ends' results of a
/// whole computation bit for bit: on the beam line above (with the mass: both ends carry force) and on a
/// cable line of two types, stretched and moving, with the support force of an assembly.
TEST(LineResults, EndsAloneAreTheWholeResultsEnds) {
  for (const bool cable : {false, true}) {
    model::ModelSpec spec = hanging(true);
    if (cable) {
      spec.lineTypes["pipe"] = test::cableType("pipe", 0.1, 20.0, 1.0e8);
      spec.lineTypes["lmrp"] = test::cableType("lmrp", 0.2, 80.0, 4.0e8);
    }
    analysis::Simulation sim(spec);
    model::State state = stretched(sim);
    for (std::size_t i = 0; i < state.position.size(); ++i)
      state.position[i].x() += 0.05 * static_cast<double>(i * i);  // bent
    sim.state() = state;
    const VecX force = sim.supportForce(true);
    std::vector<LineSnapshot> all, ends;
    sim.lineResults(force, true, all);
    sim.lineResults(force, true, ends, LineResultDetail::Ends);
    ASSERT_EQ(ends.size(), 1u);
    const LineSnapshot& a = all[0];
    const LineSnapshot& e = ends[0];
    EXPECT_EQ(e.name, a.name);
    EXPECT_EQ(e.position, a.position);
    EXPECT_EQ(e.endForceA, a.endForceA);
    EXPECT_EQ(e.endForceB, a.endForceB);
    EXPECT_EQ(e.endTensionForceA, a.endTensionForceA);
    EXPECT_EQ(e.endTensionForceB, a.endTensionForceB);
    EXPECT_EQ(e.endTensionA, a.endTensionA);
    EXPECT_EQ(e.endTensionB, a.endTensionB);
    EXPECT_EQ(e.tension.front(), a.tension.front());
    EXPECT_EQ(e.tension.back(), a.tension.back());
    EXPECT_EQ(e.hasBending, a.hasBending);
    EXPECT_EQ(e.hasBending, !cable);
    EXPECT_GT(a.endTensionA, 1e4);
    EXPECT_GT(std::abs(a.endTensionB), 1e3);
    // Nothing inside the line.
    EXPECT_EQ(e.tension[1], 0.0);
    EXPECT_NE(a.tension[1], 0.0);
    EXPECT_TRUE(e.wallTension.empty());
  }
}

// A cable whose end element is slack while the next one is taut (a snap front next to the end: a line shaken
// at its ends, new-user model of 2026-12-07): a bar carries no compression, so the end is slack: the end
// element's own force, the slack law's c EA strain = 1e-6 x 1e8 N x (-0.01) = -1 N. The linear extrapolation
// of the two elements' forces (-1 N and EA / 1000 = 1e5 N, equal 10 m elements: the end point half an
// element beyond the end's mid-point) gives -1 - 0.5 (1e5 + 1) = -5e4 N, which was reported as the end
// tension until then (a line's end read -74 kN with its interior at -0.7 N). The other end, with both
// elements at 1e5 N, keeps the extrapolation's 1e5 N.
TEST(LineResults, ACableEndNextToATautElementIsSlackNotCompressed) {
  model::ModelSpec spec;
  spec.sourceFile = "snap front (test)";
  spec.environment.waterDepth = 200.0;
  spec.lineTypes["wire"] = test::cableType("wire", 0.1, 20.0, 1.0e8);
  spec.lines.push_back(test::simpleLine("wire", "wire", 30.0, 3, model::EndKind::Pinned, Vec3(0, 0, -50),
                                        model::EndKind::Pinned, Vec3(30, 0, -50)));
  analysis::Simulation sim(spec);
  model::State s = sim.state();
  const model::Line& line = sim.model().lines()[0];
  const std::array<double, 4> x = {0.0, 9.9, 9.9 + 10.01, 9.9 + 20.02};  // element 0 slack, 1 and 2 taut
  for (int i = 0; i < line.nodeCount; ++i)
    s.position[static_cast<std::size_t>(line.firstNode + i)] = Vec3(x[static_cast<std::size_t>(i)], 0, -50);
  for (const LineResultDetail detail : {LineResultDetail::SectionForces, LineResultDetail::Ends}) {
    std::vector<LineSnapshot> out;
    computeLineResults(sim.model(), sim.assembler(), s, nullptr, out, detail);
    ASSERT_EQ(out.size(), 1u);
    const double slackLaw = 1e-6 * 1e8 * (9.9 - 10.0) / 10.0;  // [N]
    EXPECT_NEAR(out[0].endTensionA, slackLaw, 1e-9);
    EXPECT_NEAR(out[0].endTensionForceA.x(), slackLaw, 1e-9);  // along the end element's chord (+x)
    EXPECT_EQ(out[0].tension.front(), out[0].endTensionA);
    EXPECT_NEAR(out[0].endTensionB, 1e5, 1e-3);
  }
}

}  // namespace
}  // namespace tangle::solver
