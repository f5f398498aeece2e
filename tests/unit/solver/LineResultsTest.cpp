// End tensions of LineResults at a free end (issue 32 review): a free end with nothing attached carries no
// force, whatever the end element's own section force; with a mass attached at it, the line holds the mass.

#include <gtest/gtest.h>

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
      state.position[i].x() += 0.3 * static_cast<double>(i * i);  // bent
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

}  // namespace
}  // namespace tangle::solver
